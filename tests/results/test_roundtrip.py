"""A real assessment's typed result survives results.json unchanged, and ranking is pure.

References: the result of a real run (frp_assess.api.run_assessment on the small wall of
tests/assess/test_run.py) and the ranking rule of docs/results-json.md written out by hand.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

from frp_assess.api import run_assessment
from frp_assess.assess.results import rank_cases
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


def test_ranking_returns_a_new_ranking_and_leaves_the_cases_alone(tmp_path: Path) -> None:
    result, _ = run_assessment(
        small_inputs(), tmp_path, jobs=2, pdf=False, created="2026-01-01", write=False
    )
    # pivot None: both options stand (the drop rule is tested in test_pivot_and_as_built.py)
    unranked = tuple(dataclasses.replace(c, rank=None, pivot=None) for c in result.cases)
    # two options, one made cheap and meeting the target: it must rank first
    urm, a, b = unranked
    a = dataclasses.replace(a, capacity_demand=0.5, meets_target=False, frp_cost=1.0)
    b = dataclasses.replace(b, capacity_demand=4.0, meets_target=True, frp_cost=99.0)
    ranked, best = rank_cases((urm, a, b), target=3.0)
    assert [c.rank for c in ranked] == [None, 2, 1]
    assert best == b.name
    assert [c.rank for c in (urm, a, b)] == [None, None, None]  # inputs untouched
    # none meets the target: ranked by capacity/demand, nothing recommended
    ranked, best = rank_cases(
        (urm, a, dataclasses.replace(b, capacity_demand=2.0, meets_target=False)), 3.0
    )
    assert [c.rank for c in ranked] == [None, 2, 1] and best is None
