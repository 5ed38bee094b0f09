"""Number formats and small helpers of the report's tables (plain text, not markup):

- accelerations in g: 3 decimals (:func:`fmt_acc`);
- ratios (capacity/demand, improvement): 2 decimals (:func:`fmt_ratio`);
- IDA multipliers: 3 decimals; masses: 1 decimal (kg); costs: 0 decimals with thousands commas.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from frp_assess.numbers import fmt_against
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup, pdf

Results = AssessmentResult

DASH = "—"
NO_COLLAPSE = "no collapse ≤ C_max"


@dataclass(frozen=True)
class TableData:
    """Header (plain text or :class:`Markup`) and body rows (plain text)."""

    header: list[str]
    rows: list[list[str]]


#: most record columns one table of a page's width holds; more are split into several tables
RECORD_COLUMNS = 10


def column_blocks(
    table: TableData, keep: int = 1, per_block: int = RECORD_COLUMNS
) -> list[TableData]:
    """``table`` cut into tables of at most ``per_block`` columns after its first ``keep``
    (repeated in each): a table with a column per record stays readable for any number of
    records (100 records made one table of 101 columns that no page could hold)."""
    rest = len(table.header) - keep
    if rest <= per_block:
        return [table]
    blocks = []
    for start in range(keep, len(table.header), per_block):
        cols = list(range(keep)) + list(range(start, min(start + per_block, len(table.header))))
        blocks.append(
            TableData(
                [table.header[c] for c in cols], [[row[c] for c in cols] for row in table.rows]
            )
        )
    return blocks


def head(template: str, **user: object) -> Markup:
    """A header cell of constant markup ``template`` with user values (escaped) filled in."""
    return Markup(template.format(**{k: pdf(v) for k, v in user.items()}))


# --- number formats -----------------------------------------------------------------------


def fmt_acc(x: float | None) -> str:
    return DASH if x is None else f"{x:.3f}"


def fmt_ratio(x: float | None) -> str:
    return DASH if x is None else f"{x:.2f}"


fmt_q = fmt_ratio


def fmt_capacity(case: CaseResult, target: float) -> str:
    """capacity/demand of a case with enough decimals to agree with its verdict against
    ``target`` (0.997 → '0.997', not '1.00', when it does not meet 1)."""
    return fmt_against(case.capacity_demand, target, case.meets_target)


def fmt_mult(x: float | None) -> str:
    return NO_COLLAPSE if x is None else f"{x:.3f}"


def fmt_mass(x: float | None) -> str:
    return DASH if x is None else f"{x:.1f}"


def fmt_cost(x: float | None) -> str:
    return DASH if x is None else f"{x:,.0f}"


def fmt_permille(x: float | None) -> str:
    """ρ in ‰: at most 2 decimals, trailing zeros dropped (2 → '2', 1.579 → '1.58')."""
    if x is None:
        return DASH
    return f"{x:.2f}".rstrip("0").rstrip(".")


def fmt_num(x: Any, digits: int = 3) -> str:
    """Generic value: numbers to ``digits`` significant figures, others as text."""
    if x is None:
        return DASH
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    return str(x)


def yes_no(x: bool | None) -> str:
    return DASH if x is None else ("yes" if x else "no")


def pass_fail(x: bool | None) -> str:
    return DASH if x is None else ("pass" if x else "FAIL")


# --- helpers on the results ---------------------------------------------------------------


def ranked_options(results: Results) -> list[CaseResult]:
    """Retrofit options by rank (1 first); unranked options last, in file order."""
    opts = list(results.options)
    return sorted(opts, key=lambda c: (c.rank is None, c.rank or 0))


def a_dyn_label(results: Results) -> str:
    """Header markup of the design a_dyn column."""
    return Markup(
        "mean a<sub>dyn</sub> [g]" if results.design_is_mean else "min a<sub>dyn</sub> [g]"
    )


def bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower and text != DASH else text


def case_by_name(results: Results, name: str | None) -> CaseResult | None:
    for c in results.cases:
        if c.name == name:
            return c
    return None


def position_text(pos: str | None) -> str:
    return DASH if pos is None else pos
