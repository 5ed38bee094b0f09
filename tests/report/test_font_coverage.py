"""What the PDF's font cannot show of the user's texts is said at report time (issue 36
item 7): CJK and emoji DejaVu Sans has no glyph for, and right-to-left letters reportlab
prints unjoined; one warning line, report.pdf still written.

Reference: DejaVu Sans's published coverage (no CJK ideographs; U+1F3E0 HOUSE BUILDING is
not among its emoji; Latin, Greek, ‰ are) and Unicode's bidirectional classes (ש U+05E9: R,
ب U+0628: AL).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.report.font_coverage import font_gaps
from tests.report.test_report import raw, typed


def with_name(name: str) -> dict:
    data = raw()
    data["project"]["name"] = name
    data["cases"][1]["name"] = name + " 1"
    return data


def test_latin_greek_and_symbols_print() -> None:
    assert font_gaps(typed(with_name("Facciata sud ‰ θ ρ — àèìòù"))) is None


def test_cjk_emoji_and_right_to_left_are_named() -> None:
    gaps = font_gaps(typed(with_name("Casa 中 🏠 ש ب")))
    assert gaps is not None
    assert "U+4E2D" in gaps and "U+1F3E0" in gaps  # no glyph: empty boxes
    assert "empty boxes" in gaps
    assert "U+05E9" in gaps and "U+0628" in gaps  # right to left: unjoined
    assert gaps.isascii()  # any console prints it


def test_report_command_warns_in_one_line_and_writes_the_pdf(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    d = tmp_path / "r"
    d.mkdir()
    (d / "results.json").write_text(json.dumps(with_name("Casa 中")), encoding="utf-8")
    assert main(["report", str(d)]) == 0
    err = [line for line in capsys.readouterr().err.splitlines() if "warning" in line]
    assert len(err) == 1 and "U+4E2D" in err[0], err
    assert (d / "report.pdf").stat().st_size > 0
