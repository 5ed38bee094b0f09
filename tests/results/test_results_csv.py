"""results.csv for an office: the decision's verdict in its own columns (never a column that
contradicts it), the report's rounding, a byte-order mark, and the Italian conventions
(decimal comma, ";") when the report is Italian.

Reference: the report's fixture with a decision set by hand (tests/results/decided.py): the
expected words are written from that decision, not from the code under test.
"""

from __future__ import annotations

import csv
import io
import re
from typing import Any

import pytest

from frp_assess.results.csv_files import BOM, CSV_FIELDS, results_csv, spectra_csv
from tests.report.test_report import raw, typed
from tests.results.decided import decided


def rows(text: str, delimiter: str) -> list[dict[str, str]]:
    assert text.startswith(BOM)
    return list(csv.DictReader(io.StringIO(text[len(BOM) :]), delimiter=delimiter))


def test_the_verdict_columns_are_the_decisions() -> None:
    data = decided(raw())
    out = rows(results_csv(typed(data)), ",")
    assert "case_meets_target" not in out[0]  # the IDA check alone, true where options fail
    assert list(out[0]) == CSV_FIELDS
    by_name = {c["name"]: c for c in data["cases"]}
    for row in out:
        c = by_name[row["case"]]
        want = (
            "recommended"
            if c["name"] == data["recommended"]
            else ("passes" if c["passes"] else "fails")
        )
        assert row["case_verdict"] == want
        assert row["case_governing_check"] == "time history SLV"
        assert row["case_governing_margin"] == f"{c['governing_margin']:.2f}"
    assert sum(r["case_verdict"] != "fails" for r in out) == 2 * len(data["records"])


def test_no_retrofit_needed_recommends_nothing() -> None:
    data = decided(raw())
    data["cases"][0].update(passes=True, governing_margin=1.5)
    data["retrofit_required"] = False
    out = rows(results_csv(typed(data)), ",")
    assert "recommended" not in {r["case_verdict"] for r in out}


def test_rounded_as_the_report() -> None:
    """No 16-digit ratio: accelerations and multipliers 3 decimals, ratios 2, kg 1, cost 0."""
    out = rows(results_csv(typed(decided(raw()))), ",")
    decimals = {
        "ratio_permille": 2,
        "record_pga_g": 3,
        "record_collapse_multiplier": 3,
        "record_a_dyn_g": 3,
        "record_q": 2,
        "case_mean_a_dyn_g": 3,
        "case_design_a_dyn_g": 3,
        "case_improvement_design": 2,
        "case_frp_mass_kg": 1,
        "case_frp_cost": 0,
    }
    for row in out:
        for key, d in decimals.items():
            pattern = r"-?\d+" + ("" if d == 0 else r"\.\d" + "{" + str(d) + "}")
            if row[key]:
                assert re.fullmatch(pattern, row[key]), (key, row[key])


@pytest.mark.parametrize(("language", "delimiter", "decimal"), [("en", ",", "."), ("it", ";", ",")])
def test_language_conventions(language: str, delimiter: str, decimal: str) -> None:
    """An Italian report: ";" between fields and a decimal comma (the same values)."""
    data: dict[str, Any] = decided(raw())
    data["report"] = {"language": language, "template": None}
    out = rows(results_csv(typed(data)), delimiter)
    assert len(out[0]) == len(CSV_FIELDS)
    first = data["cases"][1]
    row = next(r for r in out if r["case"] == first["name"])
    assert row["case_design_a_dyn_g"] == f"{first['design_a_dyn']:.3f}".replace(".", decimal)
    assert row["case_frp_mass_kg"] == f"{first['frp_mass']:.1f}".replace(".", decimal)


def test_italian_verdict_words_and_checks() -> None:
    """An Italian report: the verdict words and the governing check in Italian, from the
    decision set by hand (recommended -> proposta, passes -> supera, fails -> non supera)."""
    data: dict[str, Any] = decided(raw())
    data["report"] = {"language": "it", "template": None}
    out = rows(results_csv(typed(data)), ";")
    by_name = {c["name"]: c for c in data["cases"]}
    for row in out:
        c = by_name[row["case"]]
        want = (
            "proposta"
            if c["name"] == data["recommended"]
            else ("supera" if c["passes"] else "non supera")
        )
        assert row["case_verdict"] == want
        assert row["case_governing_check"] == "verifica dinamica non lineare SLV"


@pytest.mark.parametrize(("language", "delimiter", "decimal"), [("en", ",", "."), ("it", ";", ",")])
def test_spectra_csv_in_the_same_conventions(language: str, delimiter: str, decimal: str) -> None:
    """spectra.csv as results.csv: a byte-order mark, and ";" with a decimal comma when the
    report is Italian; each value the results' at 6 significant digits."""
    data: dict[str, Any] = decided(raw())
    data["report"] = {"language": language, "template": None}
    out = rows(spectra_csv(typed(data)), delimiter)
    s = data["seismic"]
    assert len(out) == len(s["periods"])
    names = [r["name"] for r in data["records"]]
    assert list(out[0]) == ["period_s", "target_sa_g", "mean_sa_g"] + [f"{n}_sa_g" for n in names]
    for i, row in enumerate(out):
        assert row["period_s"] == f"{s['periods'][i]:.6g}".replace(".", decimal)
        assert row["mean_sa_g"] == f"{s['mean_sa'][i]:.6g}".replace(".", decimal)
        assert row[f"{names[0]}_sa_g"] == f"{data['records'][0]['sa'][i]:.6g}".replace(".", decimal)
