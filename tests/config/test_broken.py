"""The corpus of broken project files: each gives its one-line error, at the right line.

Every file in ``broken/`` starts with ``# expect: <fragment of the message>``; the offending
line ends with ``# <-- error`` (no marker: the error is reported at line 1).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.config import load_project
from frp_assess.errors import InputError

BROKEN = Path(__file__).parent / "broken"
CASES = sorted(BROKEN.glob("*.yaml"))
MARKER = "# <-- error"


def expectation(path: Path) -> tuple[str, int]:
    """(message fragment, 1-based line) declared in a corpus file."""
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("# expect: "), f"{path.name}: no '# expect:' header"
    fragment = lines[0].removeprefix("# expect: ")
    marked = [i + 1 for i, text in enumerate(lines) if text.rstrip().endswith(MARKER)]
    assert len(marked) <= 1, f"{path.name}: more than one error marker"
    return fragment, (marked[0] if marked else 1)


def test_corpus_is_complete() -> None:
    assert len(CASES) >= 40


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_broken_file_gives_its_one_line_error(path: Path) -> None:
    fragment, line = expectation(path)
    with pytest.raises(InputError) as info:
        load_project(path)
    message = str(info.value)
    assert "\n" not in message
    assert message.startswith(f"{path}:{line}: "), message
    assert fragment in message, message
    assert info.value.line == line


@pytest.mark.parametrize(
    "name", ["unknown-key", "yaml-syntax", "duplicate-key", "missing-record-file", "empty-file"]
)
def test_cli_validate_broken_file(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    path = BROKEN / f"{name}.yaml"
    fragment, line = expectation(path)
    code = main(["validate", str(path)])
    out, err = capsys.readouterr()
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1, err
    assert "Traceback" not in err
    assert err.startswith(f"frp-assess: error: {path}:{line}: ")
    assert fragment in err


def test_missing_project_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "nope.yaml"
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert err == f"frp-assess: error: {path}: no such project file\n"
