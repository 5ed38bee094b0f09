"""The typed row of a study's summary.csv (frp_assess.study.rows) and the study run of the
application service (frp_assess.app.study), which answers with those rows."""

from __future__ import annotations

import dataclasses
import threading
from pathlib import Path

import pytest

from frp_assess.app.study import run_study
from frp_assess.study import SummaryRow, parse_study
from frp_assess.study.run import SUMMARY_COLUMNS
from tests.study.conftest import TINY, tiny_records

#: a reinforced and an unreinforced row as summary.csv writes them (hand-written cells)
CELLS = {
    "case": "3",
    "label": "A2 one-sided H=3 CFRP external 1",
    "spectrum": "A2",
    "mechanism": "one-sided",
    "height_m": "3.0",
    "thickness_m": "0.39493",
    "alpha_deg": "7.5",
    "material": "CFRP",
    "position": "external",
    "ratio_permille": "1.0",
    "records": "7",
    "a_rm_g": "0.13164",
    "mean_a_dyn_g": "0.5",
    "min_a_dyn_g": "0.25",
    "mean_q": "3.8",
    "lower_bound": "yes",
    "unreinforced_case": "0",
    "unreinforced_mean_a_dyn_g": "0.2",
    "improvement": "2.5",
}


def test_the_fields_are_the_columns_of_summary_csv_in_order() -> None:
    names = [f.name for f in dataclasses.fields(SummaryRow) if f.name != "cells"]
    assert tuple(names) == SUMMARY_COLUMNS


def test_a_row_is_typed_and_still_reads_as_its_csv_text() -> None:
    row = SummaryRow.from_cells(CELLS)
    assert (row.case, row.records, row.unreinforced_case) == (3, 7, 0)
    assert (row.height_m, row.alpha_deg, row.ratio_permille) == (3.0, 7.5, 1.0)
    assert row.lower_bound is True and row.reinforced
    assert row.improvement == pytest.approx(0.5 / 0.2)  # the CSV's improvement, hand-checked
    assert row["mean_q"] == "3.8" and dict(row) == CELLS
    bare = SummaryRow.from_cells(
        {**CELLS, "material": "", "position": "", "ratio_permille": "", "lower_bound": "no"}
    )
    assert (bare.material, bare.position, bare.ratio_permille) == (None, None, None)
    assert not bare.reinforced and bare.lower_bound is False


def test_the_app_runs_a_study_and_answers_typed_rows(tmp_path: Path) -> None:
    study = parse_study(dict(TINY))
    outcome = run_study(
        study,
        tmp_path,
        jobs=1,
        records=tiny_records(),
        figures=False,
        cancel=threading.Event(),
    )
    rows = outcome.rows()
    # TINY: 2 heights × (1 unreinforced + 2 ratios of one material and position) = 6 cases
    assert len(rows) == 6 and outcome.figures == ()
    assert {r.height_m for r in rows} == {3.0, 4.0}
    for r in rows:
        base = next(u for u in rows if u.case == r.unreinforced_case)
        assert base.material is None
        assert r.improvement == pytest.approx(r.mean_a_dyn_g / base.mean_a_dyn_g)
