"""The template's placeholders are obvious, and validate/run warn while they are unchanged."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.assess.from_project import load_inputs
from frp_assess.cli import main


def new_project(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    path = tmp_path / "wall.yaml"
    assert main(["new", str(path)]) == 0
    capsys.readouterr()
    return path


def test_validate_warns_in_one_line_while_placeholders_are_unchanged(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = new_project(tmp_path, capsys)
    assert main(["validate", str(path)]) == 0
    captured = capsys.readouterr()
    assert captured.out.startswith(f"{path}: OK")
    (warning,) = captured.err.splitlines()
    line = path.read_text(encoding="utf-8").splitlines().index('  location: "<site address>"') + 1
    assert warning.startswith(f"frp-assess: warning: {path}:{line}: project: ")
    for placeholder in (
        "'<site address>'",
        "'<engineer, licence no.>'",
        "'<notes for the report>'",
    ):
        assert placeholder in warning


def test_no_warning_once_they_are_replaced(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = new_project(tmp_path, capsys)
    text = path.read_text(encoding="utf-8")
    text = text.replace('"<site address>"', "Via Roma 1, L'Aquila")
    text = text.replace('"<engineer, licence no.>"', "B. Rossi, n. 1234")
    path.write_text(text, encoding="utf-8")
    warned: list[str] = []
    load_inputs(path, warn=warned.append)
    assert len(warned) == 1 and "notes '<notes for the report>'" in warned[0]
    assert "location" not in warned[0]
    path.write_text(text.replace('"<notes for the report>"', "facade"), encoding="utf-8")
    assert main(["validate", str(path)]) == 0
    assert capsys.readouterr().err == ""
    warned.clear()
    load_inputs(path, warn=warned.append)
    assert warned == []


def test_run_warns_on_stderr_before_any_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = new_project(tmp_path, capsys)
    load_inputs(path)
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("frp-assess: warning: ")
