"""What the project-file tests of tests/config share: validate a text as a user would
(``frp-assess validate``) and check the one located line it refuses with."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.cli import main


def validate_text(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    """(exit code, stderr) of ``frp-assess validate`` on ``text`` written as p.yaml."""
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    code = main(["validate", str(path)])
    return code, capsys.readouterr().err


def assert_one_located_line(code: int, err: str, line: int, key: str, fragment: str) -> None:
    """Exit 2 and one line on stderr naming p.yaml, the line, the key and ``fragment``."""
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert f"p.yaml:{line}: {key}" in lines[0]
    assert fragment in lines[0]
