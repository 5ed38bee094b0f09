"""A real assessment's typed result survives results.json unchanged.

References: the result of a real run (frp_assess.api.run_assessment on the small wall of
tests/assess/test_run.py).
"""

from __future__ import annotations

from pathlib import Path

from frp_assess.api import run_assessment
from frp_assess.results.csv_files import results_csv
from frp_assess.results.json_io import from_json, to_json
from tests.assess.test_run import small_inputs


def test_a_real_result_round_trips_through_results_json(tmp_path: Path) -> None:
    result, _ = run_assessment(small_inputs(), tmp_path, jobs=2, pdf=False, created="2026-01-01")
    text = to_json(result)
    again = from_json(text, file="results.json")
    assert again == result
    assert to_json(again) == text == (tmp_path / "results.json").read_text(encoding="utf-8")
    assert results_csv(again) == (tmp_path / "results.csv").read_text(encoding="utf-8")
    assert isinstance(again.cases, tuple) and isinstance(again.cases[0].records, tuple)
