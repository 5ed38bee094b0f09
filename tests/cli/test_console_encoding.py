"""A console that is not UTF-8 (issue 36 item 4): `PYTHONIOENCODING=cp1252 frp-assess run p.yaml
> log.txt` (a Windows redirect), ascii, latin-1, `LC_ALL=C`: every command prints what the
stream can encode (frp_assess/cli/output.py: setup_streams, the console's render_str), exits
as it would on a UTF-8 console and leaves no half-made folder."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from frp_assess.cli import main
from frp_assess.cli.output import STREAM_ERRORS, ascii_spelling
from tests.cli.outputs_helpers import ROOT, cli_command, tiny_project

ENCODINGS = ("cp1252", "ascii", "latin-1")


def _run(args: list[str], env: dict[str, str], cwd: Path) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        cli_command(*args), env=env, cwd=cwd, capture_output=True, timeout=300, check=False
    )


def _env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONIOENCODING", "LC_ALL")}
    return dict(env, PYTHONPATH=str(ROOT), COLUMNS="100", **extra)


@pytest.mark.slow
def test_a_run_and_its_unchanged_rerun_on_consoles_that_are_not_utf8(tmp_path: Path) -> None:
    project = tiny_project(tmp_path)
    for enc in ENCODINGS:  # a run that computes (progress, tables, summary): exit 0
        out = tmp_path / f"out-{enc}"
        done = _run(
            ["run", str(project), "--out", str(out), "--jobs", "1"],
            _env(PYTHONIOENCODING=enc),
            tmp_path,
        )
        assert done.returncode == 0, done.stderr.decode(enc, "replace")
        text = done.stdout.decode(enc)  # every byte is the stream's encoding
        # the demand's symbol in the summary line: as it is where the encoding has "·"
        # (cp1252, latin-1), in its ASCII spelling elsewhere (cli/output.py)
        assert "capacity/demand = " in text, text
        assert "at FC·a_g·S = " in text or "at FC*a_g*S = " in text, text
        assert b"Traceback" not in done.stderr
        assert (out / "results.json").is_file()
    assert main(["run", str(project), "--out", str(tmp_path / "out"), "--jobs", "1"]) == 0
    for env in [_env(PYTHONIOENCODING=e) for e in ENCODINGS] + [_env(LC_ALL="C")]:
        again = _run(["run", str(project), "--out", str(tmp_path / "out")], env, tmp_path)
        assert again.returncode == 0, again.stderr
        assert b"unchanged since" in again.stdout and b"Traceback" not in again.stderr


def test_an_error_line_on_an_ascii_console(tmp_path: Path) -> None:
    """The one-line error of a file whose name the console cannot encode: exit 2, not 1."""
    bad = tmp_path / "θ≥‰.yaml"
    bad.write_text("wall: [\n", encoding="utf-8")
    done = _run(["validate", str(bad)], _env(PYTHONIOENCODING="ascii"), tmp_path)
    assert done.returncode == 2, done.stderr
    err = done.stderr.decode("ascii")
    assert err.count("\n") == 1 and "theta>= per mille.yaml" in err, err


@given(st.text(max_size=40))
def test_every_text_is_written_on_every_console(text: str) -> None:
    """Whatever a line holds (any code point, lone surrogates included), the standard streams'
    error handler writes it in ASCII, cp1252 or latin-1 without an exception; characters the
    encoding has are written as they are."""
    for enc in ENCODINGS:
        written = text.encode(enc, STREAM_ERRORS).decode(enc)
        for ch in text:
            try:
                ch.encode(enc)
            except UnicodeEncodeError:
                continue
            assert ch in written


@pytest.mark.parametrize(
    ("char", "spelled"),
    [("≥", ">="), ("≤", "<="), ("‰", " per mille"), ("θ", "theta"), ("α", "alpha"),
     ("Δ", "Delta"), ("γ", "gamma"), ("²", "2"), ("ₘ", "m"), ("\udc80", "?")],
)  # fmt: skip
def test_the_ascii_spellings(char: str, spelled: str) -> None:
    assert ascii_spelling(char) == spelled


def test_a_lock_that_made_its_folder_leaves_none_when_nothing_was_written(
    tmp_path: Path,
) -> None:
    """A run that fails after taking the lock of a new folder (a crash while printing, as on
    a cp1252 console before) leaves no folder holding only `.lock`; a folder that existed,
    or one that received anything else, keeps it."""
    from frp_assess.output_set import LOCK_NAME, FolderLock

    new = tmp_path / "new"
    with pytest.raises(UnicodeEncodeError), FolderLock(new):
        assert (new / LOCK_NAME).is_file()
        "≥".encode("cp1252")
    assert not new.exists()
    with FolderLock(new):
        (new / ".cache").mkdir()
    assert (new / LOCK_NAME).is_file() and (new / ".cache").is_dir()
    old = tmp_path / "old"
    old.mkdir()
    with FolderLock(old):
        pass
    assert (old / LOCK_NAME).is_file()
