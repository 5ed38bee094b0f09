"""results.csv and spectra.csv, written from the typed results (docs/results-json.md).
Both follow the conventions below (spectra.csv has no verdict and rounds to 6 significant
digits).

results.csv is read in a spreadsheet by an office: it starts with a UTF-8 byte-order mark (so
that "‰" is not garbled), rounds as the report does (accelerations and multipliers 3
decimals, ratios 2, masses 1, costs 0) and, when the report is Italian (results.json
``report.language``), uses the Italian conventions: decimal comma, semicolon separator, the
verdict words and check names in Italian.  Its verdict columns are the decision's
(:mod:`frp_assess.results.verdict_words`).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Callable

from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.rounding import fmt_against
from frp_assess.results.verdict_words import in_language, verdict_word

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
    "case_capacity_demand_lower_bound",
    "case_improvement_design",
    "case_frp_mass_kg",
    "case_frp_cost",
    "case_verdict",
    "case_governing_check",
    "case_governing_margin",
    "case_rank",
    "case_failure_mode",
]

#: the columns added after :data:`CSV_FIELDS` when some option has tie-rods (a file without
#: them keeps its columns): the option's kind, its ties' steel and cost, its whole cost
TIE_CSV_FIELDS = ["case_kind", "case_tie_steel_kg", "case_tie_cost", "case_option_cost"]

#: the byte-order mark results.csv starts with (spreadsheets then read it as UTF-8)
BOM = "\ufeff"


class CsvStyle:
    """Separator, decimal mark and yes/no of a language: "," "." for English, ";" ","
    for Italian (the report's language)."""

    def __init__(self, language: str) -> None:
        italian = language == "it"
        self.language = language
        self.delimiter = ";" if italian else ","
        self.decimal = "," if italian else "."
        self.yes, self.no = ("sì", "no") if italian else ("yes", "no")

    def number(self, x: float | None, decimals: int) -> str:
        """``x`` with ``decimals`` decimals ("" for None)."""
        return "" if x is None else self.mark(f"{x:.{decimals}f}")

    def mark(self, text: str) -> str:
        """A number written with a point, in this style's decimal mark."""
        return text.replace(".", self.decimal)

    def flag(self, x: bool) -> str:
        return self.yes if x else self.no

    def word(self, text: str) -> str:
        """A verdict word or deciding check in this style's language."""
        return in_language(text, self.language)


def csv_style(results: AssessmentResult) -> CsvStyle:
    """The style of the report's language (results.json ``report.language``; English
    without one)."""
    return CsvStyle(results.report.language if results.report is not None else "en")


def case_columns(results: AssessmentResult, st: CsvStyle) -> Callable[[CaseResult], list[str]]:
    """The ``case_*`` cells of a case (the same on every row of the case)."""
    target = float(results.model.target)

    def cells(c: CaseResult) -> list[str]:
        margin = c.governing_margin
        return [
            st.number(c.mean_a_dyn, 3),
            st.number(c.min_a_dyn, 3),
            st.number(c.design_a_dyn, 3),
            st.mark(fmt_against(c.capacity_demand, target, c.capacity_demand >= target)),
            st.flag(c.lower_bound),
            st.number(c.improvement, 2),
            st.number(c.frp_mass, 1),
            st.number(c.frp_cost, 0),
            st.word(verdict_word(results, c)),
            st.word(c.governing_check or ""),
            "" if margin is None else st.mark(fmt_against(margin, 1.0, margin >= 1.0)),
            "" if c.rank is None else str(c.rank),
            c.failure_mode or "",
        ]

    return cells


def _tie_cells(c: CaseResult, st: CsvStyle) -> list[str]:
    """The :data:`TIE_CSV_FIELDS` cells of a case: kind (bars, tie, bars+tie; empty for the
    unreinforced wall), the ties' steel [kg] and cost, the option's cost (bars + ties)."""
    kind = "" if c.is_unreinforced else (c.kind or "bars")
    steel = None if c.tie is None else c.tie.steel_mass
    cost = None if c.tie is None else c.tie.cost
    return [kind, st.number(steel, 1), st.number(cost, 0), st.number(c.option_cost, 0)]


def results_csv(results: AssessmentResult) -> str:
    """One row per (case, record), after a byte-order mark; accelerations in g, mass kg,
    cost in the currency (docs/results-json.md, "results.csv").

    ``record_*`` columns belong to the row's record, ``case_*`` ones to the whole case (the
    same on every row of the case): mean and least favourable over the records, and the
    design value (the mean with 7 or more records, else the least favourable) that the
    capacity/demand ratio and the improvement use; the decision's verdict, governing check
    and margin.
    """
    st = csv_style(results)
    buf = io.StringIO()
    w = csv.writer(buf, delimiter=st.delimiter, lineterminator="\n")
    ties = any(c.tie is not None for c in results.cases)
    w.writerow(CSV_FIELDS + (TIE_CSV_FIELDS if ties else []))
    case_cells = case_columns(results, st)
    for c in results.cases:
        shared = case_cells(c) + (_tie_cells(c, st) if ties else [])
        for r in c.records:
            w.writerow(
                [
                    c.name,
                    c.material or "",
                    c.position or "",
                    st.number(c.ratio, 2),
                    r.record,
                    st.number(r.pga, 3),
                    st.number(r.collapse_multiplier, 3),
                    st.number(r.a_dyn, 3),
                    st.number(r.q, 2),
                    r.failure_mode or "",
                    *shared,
                ]
            )
    return BOM + buf.getvalue()


def spectra_csv(results: AssessmentResult) -> str:
    """One row per period [s]: the target and mean spectra and each record's [g], 6
    significant digits, in results.csv's conventions (a byte-order mark first; the decimal
    comma and ";" when the report is Italian)."""
    s = results.seismic
    st = csv_style(results)
    buf = io.StringIO()
    w = csv.writer(buf, delimiter=st.delimiter, lineterminator="\n")
    w.writerow(
        ["period_s", "target_sa_g", "mean_sa_g"] + [f"{r.name}_sa_g" for r in results.records]
    )
    for i, T in enumerate(s.periods):
        row = [T, s.target_sa[i], s.mean_sa[i]] + [r.sa[i] for r in results.records]
        w.writerow([st.mark(f"{x:.6g}") for x in row])
    return BOM + buf.getvalue()
