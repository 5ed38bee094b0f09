"""Fuzzing the output folder (issue 36 item 1): for any folder the user fills with files named
like the tool's outputs (results.csv, report.pdf, records/ and files in it, a results.json),
with or without a record of what the tool wrote (frp_assess/output_record.py), and any of
them changed since, the folder is accepted as a results folder only when every member in it
is one the tool wrote as it is now; otherwise one InputError line names a member, and the
check never writes, replaces or deletes anything."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from frp_assess.errors import InputError
from frp_assess.output_record import MANIFEST_NAME, SET_NAMES, member_digests, write_record
from frp_assess.output_set import check_out_dir
from tests.cli.outputs_helpers import tree

#: the member files a folder may hold (records/ file by file)
MEMBER_FILES = [n for n in SET_NAMES if n != "records"] + [
    "records/a.AT2",
    "records/SLC/b.AT2",
    "records/user-record.AT2",
]

folders = st.fixed_dictionaries(
    {
        # which member files exist, with which bytes
        "files": st.dictionaries(st.sampled_from(MEMBER_FILES), st.binary(max_size=64)),
        # whether the tool recorded them (as they were) ...
        "recorded": st.booleans(),
        # ... and which of them the user changed afterwards (or added unrecorded)
        "changed": st.lists(st.sampled_from(MEMBER_FILES), max_size=3, unique=True),
        "extra_user_file": st.booleans(),  # a file of the user's that is no member: ignored
    }
)


@given(folders)
def test_a_folder_is_accepted_only_when_every_member_is_the_tools(spec: dict) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out"
        out.mkdir()
        for rel, data in spec["files"].items():
            (out / rel).parent.mkdir(parents=True, exist_ok=True)
            (out / rel).write_bytes(data)
        if spec["recorded"]:
            write_record(out, {k: [v] for k, v in member_digests(out).items()}, {})
        foreign = set() if spec["recorded"] else set(spec["files"])
        for rel in spec["changed"]:
            (out / rel).parent.mkdir(parents=True, exist_ok=True)
            old = (out / rel).read_bytes() if (out / rel).exists() else None
            (out / rel).write_bytes((old or b"") + b"changed by the user")
            foreign.add(rel)
        if spec["extra_user_file"]:
            (out / "notes.txt").write_text("mine", encoding="utf-8")
        before = tree(out)
        if foreign:
            with pytest.raises(InputError) as err:
                check_out_dir(out)
            named = str(err.value)
            assert "not a file frp-assess wrote" in named and "\n" not in named
            assert any(str(out / rel) in named for rel in foreign), (named, foreign)
        else:
            assert check_out_dir(out) == out
        assert tree(out) == before  # the check wrote, replaced and deleted nothing
        assert (out / MANIFEST_NAME).exists() == spec["recorded"]
