"""results.csv and spectra.csv, written from the typed results (docs/results-json.md)."""

from __future__ import annotations

import csv
import io

from frp_assess.results.model import AssessmentResult

#: results.csv columns: each names its statistic and its unit (g: acceleration in g)
CSV_FIELDS = [
    "case",
    "material",
    "position",
    "ratio_permille",
    "record",
    "record_pga_g",
    "record_collapse_multiplier",
    "record_a_dyn_g",
    "record_q",
    "record_failure_mode",
    "case_mean_a_dyn_g",
    "case_least_favourable_a_dyn_g",
    "case_design_a_dyn_g",
    "case_capacity_demand_design",
    "case_improvement_design",
    "case_frp_mass_kg",
    "case_frp_cost",
    "case_meets_target",
    "case_rank",
    "case_failure_mode",
]


def _g(x: float | None) -> str:
    return "" if x is None else f"{x:.6g}"


def results_csv(results: AssessmentResult) -> str:
    """One row per (case, record); accelerations in g, mass kg, cost in the currency.

    ``record_*`` columns belong to the row's record, ``case_*`` ones to the whole case (the
    same on every row of the case): mean and least favourable over the records, and the
    design value (the mean with 7 or more records, else the least favourable) that the
    capacity/demand ratio and the improvement use.
    """
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_FIELDS)
    for c in results.cases:
        for r in c.records:
            w.writerow(
                [
                    c.name,
                    c.material or "",
                    c.position or "",
                    c.ratio,
                    r.record,
                    _g(r.pga),
                    _g(r.collapse_multiplier),
                    _g(r.a_dyn),
                    _g(r.q),
                    r.failure_mode or "",
                    _g(c.mean_a_dyn),
                    _g(c.min_a_dyn),
                    _g(c.design_a_dyn),
                    _g(c.capacity_demand),
                    _g(c.improvement),
                    _g(c.frp_mass),
                    _g(c.frp_cost),
                    c.meets_target,
                    "" if c.rank is None else c.rank,
                    c.failure_mode or "",
                ]
            )
    return buf.getvalue()


def spectra_csv(results: AssessmentResult) -> str:
    """One row per period [s]: the target and mean spectra and each record's [g]."""
    s = results.seismic
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(
        ["period_s", "target_sa_g", "mean_sa_g"] + [f"{r.name}_sa_g" for r in results.records]
    )
    for i, T in enumerate(s.periods):
        w.writerow(
            [f"{T:.6g}", f"{s.target_sa[i]:.6g}", f"{s.mean_sa[i]:.6g}"]
            + [f"{r.sa[i]:.6g}" for r in results.records]
        )
    return buf.getvalue()
