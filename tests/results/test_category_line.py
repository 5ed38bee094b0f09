"""The one line the console and the TUI print of the category of the intervention
(results/verdict_words.category_line), from results.json's ``intervention``."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from frp_assess.results.json_io import from_json
from frp_assess.results.verdict import InterventionResult
from frp_assess.results.verdict_words import category_line

SMALL = Path(__file__).resolve().parents[1] / "golden" / "expected" / "small" / "results.json"


def test_each_category_in_one_line() -> None:
    """The golden run (an upgrade, target 1), then the same file as an improvement of class
    II (0.45 + 0.1 = 0.55) and as a local intervention (above 0.45)."""
    r = from_json(SMALL.read_text(encoding="utf-8"), file="results.json")
    assert category_line(r) == (
        "options judged as an upgrade (NTC 2018 §8.4.3): every deciding check ζ_E ≥ 1 "
        "(the IDA's ≥ the target 1)"
    )
    assert category_line(replace(r, intervention=None)) == category_line(r)
    imp = InterventionResult("improvement", "NTC 2018 §8.4.2", "II", False, 0.45, 0.55, False)
    line = category_line(replace(r, intervention=imp))
    assert "improvement (NTC 2018 §8.4.2, use class II)" in line and "ζ_E ≥ 0.55" in line
    local = InterventionResult("local", "NTC 2018 §8.4.1", None, False, 0.45, 0.45, True)
    line = category_line(replace(r, intervention=local))
    assert "local intervention (NTC 2018 §8.4.1)" in line and "above its ζ_E 0.45" in line
    assert "\n" not in line
