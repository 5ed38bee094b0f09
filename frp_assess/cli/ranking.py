"""The ranking of ``frp-assess run``: one row per case that fits 80 columns, the decision's
verdict words (:mod:`frp_assess.results.verdict_words`) and a legend under it.

The columns are those an engineer needs to choose (rank, option, verdict, governing check and
its margin, the IDA's capacity/demand, FRP mass, cost); a_dyn, q and the improvement of every
case are in results.csv and the report's ranking table.
"""

from __future__ import annotations

from rich.console import Console

from frp_assess.cli.output import Column, print_table, user
from frp_assess.numbers import FALLS, fmt_capacity, margin_text
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.verdict_words import (
    GOVERNING_LEGEND,
    category_line,
    governing_short,
    verdict_word,
)


def ranking_columns(results: AssessmentResult) -> list[Column]:
    """Columns of the ranking table (the legend gives the currency and says the rest)."""
    return [
        Column("#"),
        Column("option", text=True),
        Column("verdict", text=True, fold=False),
        Column("governs", text=True, fold=False),
        Column("margin"),
        Column("C/D"),
        Column("FRP kg"),
        Column("cost"),
    ]


def is_dropped(case: CaseResult) -> bool:
    """The option fails the pivot check and has no rank (results.json ``pivot.dropped``:
    only in files written when options were dropped for their base)."""
    return case.pivot is not None and case.pivot.dropped and not case.is_unreinforced


def ranking_rows(results: AssessmentResult) -> list[list[str]]:
    """One row per case (plain text): the unreinforced wall, the options by rank, then those
    the pivot check dropped (rank "dropped", the reason below the table: :func:`dropped_lines`).
    The verdict, governing check and margin are the decision's; C/D is the IDA's
    (``capacity_demand``, "≥" before a lower bound)."""
    target = float(results.model.target)
    return [
        [
            ("dropped" if is_dropped(c) else "—") if c.rank is None else str(c.rank),
            c.name,
            verdict_word(results, c),
            governing_short(c.governing_check),
            margin_text(c),
            fmt_capacity(c, target),
            f"{c.frp_mass:.1f}",
            f"{c.option_cost:.0f}",
        ]
        for c in (results.urm, *results.ranked_options)
    ]


def ranking_title(results: AssessmentResult) -> str:
    """The table's title: the demand its margins and C/D are stated at (FC·a_g·S, the
    decision's; :func:`legend_lines` gives FC and a_g·S)."""
    return f"Retrofit options at FC·a_g·S = {demand_fc(results):.3f} g"


def demand_fc(results: AssessmentResult) -> float:
    """FC·a_g·S [g]: the demand of the decision's IDA check (FC of the unreinforced wall,
    the knowledge level's, the same for every case)."""
    return results.urm.fc * results.demand.pga


def legend_lines(results: AssessmentResult) -> list[str]:
    """What the columns mean, and what "recommended" means here."""
    lines = [
        f"cost in {results.costs.currency}, FRP in kg; demand FC·a_g·S = {results.urm.fc:g} "
        f"× {results.demand.pga:.3f} g; verdict: "
        "every deciding check passes, or not; governs: the deciding check with the smallest "
        f"margin ({GOVERNING_LEGEND}); margin: its capacity/demand, ≥ 1 passes, '{FALLS}': "
        "a record topples the wall; C/D: the IDA's design a_dyn/(FC·a_g·S) against the "
        f"target {results.model.target:g}, '≥' a lower bound",
        category_line(results),
    ]
    lines.extend(tie_lines(results))
    if results.recommended and not results.retrofit_required:
        lines.append(
            "no retrofit needed (the unreinforced wall passes): no option is recommended; "
            f"{results.recommended} is the cheapest that passes, for extra margin"
        )
    return lines


def tie_lines(results: AssessmentResult) -> list[str]:
    """What the ranking says of the options with tie-rods (none: no line): the steel, the
    cost counted, and whether the tie's prices were given."""
    ties = [c for c in results.options if c.tie is not None]
    if not ties:
        return []
    steel = "; ".join(f"{c.name}: {c.tie.steel_mass_per_m:.1f} kg/m" for c in ties if c.tie)
    given = all(c.tie.prices_given for c in ties if c.tie)
    return [
        "tie options: cost = the bars + the ties (each its bar, two plates, installation); "
        f"tie steel, not in FRP kg: {steel}"
        + ("" if given else "; tie costs not given (costs.tie_*): counted as 0")
    ]


def dropped_lines(results: AssessmentResult) -> list[str]:
    """One line per option the pivot check dropped: its name, the check, "dropped: <why>"."""
    return [c.pivot.reason for c in results.options if is_dropped(c) and c.pivot is not None]


def print_ranking(con: Console, results: AssessmentResult) -> None:
    """The ranking table, its legend, dropped options and the cases' remarks."""
    print_table(con, ranking_title(results), ranking_columns(results), ranking_rows(results))
    for line in legend_lines(results):
        con.print(user(line))
    for line in dropped_lines(results):
        con.print(user(line))
    for c in results.cases:
        if c.remark:
            con.print(f"note, {user(c.name)}: {user(c.remark)}")
