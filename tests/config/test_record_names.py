"""Record names are unique and safe as file names (they name records/<name>.AT2)."""

from __future__ import annotations

import pytest

from frp_assess.config import load_project_text
from frp_assess.config.schema import MAX_RECORD_NAME, unsafe_name_reason
from frp_assess.errors import InputError

HEAD = """\
wall: {thickness: 0.3, height: 3, masonry: rubble-stone, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A1}
  records:
    files:
"""


def load(*items: str) -> None:
    text = HEAD + "".join(f"      - {item}\n" for item in items)
    load_project_text(text, "p.yaml", check_files=False)


@pytest.mark.parametrize(
    ("name", "reason"),
    [
        ("../evil", "/"),
        ("/abs/path", "/"),
        ("a/b", "/"),
        ("..\\\\evil", "\\\\"),
        ("C:drive", ":"),
        ("..", "dot"),
        (".hidden", "dot"),
        ("trailing.", "dot"),
        ("' '", "empty"),
        ("''", "empty"),
        ("x" * (MAX_RECORD_NAME + 1), "characters"),
        ('"a\\tb"', "control"),
    ],
)
def test_unsafe_names_are_refused_on_their_line(name: str, reason: str) -> None:
    with pytest.raises(InputError) as info:
        load("{path: r.AT2}", f"{{path: s.AT2, name: {name}}}")
    assert info.value.line == 7 and info.value.key == "seismic.records.files[1].name"
    assert "not a safe file name" in info.value.message and reason in info.value.message


@pytest.mark.parametrize(
    "items",
    [
        ("{path: a/rec.AT2}", "{path: b/rec.AT2}"),  # same file name in two folders
        ("{path: a.AT2, name: Rec}", "{path: b.AT2, name: rec}"),  # case-insensitive file systems
        ("{path: rec.AT2}", "{path: other.txt, name: rec}"),
    ],
)
def test_two_records_with_one_name_are_refused(items: tuple[str, str]) -> None:
    with pytest.raises(InputError) as info:
        load(*items)
    assert info.value.line == 7 and "already the name of files[0]" in info.value.message


def test_a_file_name_that_cannot_name_a_record_asks_for_a_name() -> None:
    with pytest.raises(InputError) as info:
        load("{path: .AT2.txt}")
    assert info.value.key == "seismic.records.files[0].path" and "give a 'name:'" in str(info.value)


@pytest.mark.parametrize("name", ["Rec 1", "El Centro 1940 (NS)", "ÄÖ-ü_ß", "a.b", "x" * 100])
def test_ordinary_names_are_accepted(name: str) -> None:
    assert unsafe_name_reason(name) is None
    load(f"{{path: r.AT2, name: '{name}'}}")
