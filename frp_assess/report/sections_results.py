"""The detailed sections on the results: the unreinforced wall, the retrofit options and the
governing time history (the calculation details of the English report)."""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import annex_design_tables as adt
from frp_assess.report import body_annex, charts, floor_section, history_section, ida_words
from frp_assess.report import tables as tb
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import (
    cond_break,
    figure,
    gap,
    grid,
    h1,
    h2,
    keep,
    key_value,
    markup,
    page_break,
    para,
)
from frp_assess.report.formats import column_blocks
from frp_assess.report.tables import EN
from frp_assess.report.verdict_text import robustness_lines
from frp_assess.results.model import AssessmentResult

Results = AssessmentResult


# --- 4 Unreinforced wall ------------------------------------------------------------------


def unreinforced(results: Results) -> list[Block]:
    urm = results.urm
    out: list[Block] = [
        page_break(),
        h1("4  The unreinforced wall"),
        h2("4.1  Rocking properties"),
    ]
    out.append(key_value(tb.wall_property_rows(results), sub_values=True))
    out.append(h2("4.2  Incremental dynamic analysis, record by record"))
    records = ida_words.records_table(urm, results, EN)
    widths = (30, 28, 40, 28, 24) if len(records.header) == 5 else (30, 18, 30, 20, 14, 30, 28)
    out.append(grid(records, [x * mm for x in widths], wrap=(0,)))
    out.append(markup(ida_words.records_caption(results, EN), "caption"))
    out.append(key_value(tb.case_summary_rows(results, urm), sub_values=True))
    out.append(h2("4.3  Dynamic assessment next to the code kinematic check"))
    out.append(
        grid(tb.comparison_table(results), [62 * mm, 24 * mm, 24 * mm, 28 * mm, 30 * mm], wrap=(0,))
    )
    out.append(gap(6))
    out.append(key_value(tb.code_check_rows(results), sub_values=True))
    note = results.code_check.note
    if note:
        out.append(para(note, "caption"))
    out += floor_section.checks_part(results)
    return out


# --- 5 Retrofit options -------------------------------------------------------------------


def options(results: Results) -> list[Block]:
    out: list[Block] = [page_break(), h1("5  Retrofit options"), h2("5.1  Ranking")]
    out.append(para("Ranking rule: " + results.ranking_rule, "small"))
    data = tb.ranking_table(results)
    rec_name = results.recommended
    hl = [i for i, r in enumerate(data.rows) if r[1] == rec_name]
    widths = [12, 22, 11, 14, 8, 11, 11, 11, 14, 12, 16, 15, 15]  # rank: "dropped"
    out.append(
        grid(
            data,
            [x * mm for x in widths],
            wrap=(1, 2, 3),
            small=True,
            numeric_from=4,
            highlight_rows=hl,
        )
    )
    out.append(
        markup(
            "ρ: ratio of the active bars to the wall cross-section (external bars: the same on "
            "each face, so twice the quantity is installed). FRP masses per metre of wall and "
            "for the whole wall; costs indicative. q = a<sub>dyn</sub>/a<sub>RM</sub>; "
            "improvement = a<sub>dyn</sub> / a<sub>dyn</sub> of the unreinforced wall; "
            "capacity/demand = a<sub>dyn</sub> / (FC·a<sub>g</sub>·S). '≥': lower bound, "
            "some record did not overturn up to C_max. Highlighted: the "
            + (
                "recommended option."
                if results.input_code_compliant
                else "best ranked option (input not code-compliant: nothing is recommended)."
            ),
            "caption",
        )
    )
    for c in results.options:  # dropped by the pivot check: no rank, the reason here
        if c.pivot is not None and c.pivot.dropped:
            out.append(para(c.pivot.reason, "small"))
    out.append(cond_break(90 * mm))
    out.append(h2("5.2  Effect of the FRP quantity"))
    out.append(
        keep(
            [
                figure(charts.options_chart(results, "improvement")),
                para(
                    "Figure 2. Level of seismic improvement against the FRP installed on the wall, "
                    "one line per material and position.",
                    "caption",
                ),
            ]
        )
    )
    out.append(
        keep(
            [
                figure(charts.options_chart(results, "capacity_demand")),
                para(
                    "Figure 3. Capacity/demand of the IDA against the FRP installed on the "
                    "wall. The target line belongs to the IDA check alone: an option passes "
                    "only when every deciding check passes (column 'deciding checks' of the "
                    "ranking above), so an option above the line can still fail.",
                    "caption",
                ),
            ]
        )
    )
    out.append(cond_break(50 * mm))
    out.append(h2("5.3  Design mode: the smallest ratio that passes every deciding check"))
    design = adt.design_table(results, EN, notes=True)
    if design is not None:
        out.append(
            grid(
                design,
                [16 * mm, 18 * mm, 20 * mm, 20 * mm, 18 * mm, 18 * mm, 64 * mm],
                wrap=(6,),
                numeric_from=2,
            )
        )
    else:
        out.append(para("Design mode was not run for this project."))
    out.append(cond_break(80 * mm))
    out.append(h2("5.4  a_dyn [g] of every option and record"))
    for mat in column_blocks(body_annex.a_dyn_table(results, EN, lambda c: c.name)):
        n = len(mat.header) - 1
        other = (174 - 34) / max(n, 1)
        out.append(grid(mat, [34 * mm] + [other * mm] * n, wrap=(0,), small=True))
    out.append(para("n.c.: no collapse up to C_max for that record.", "caption"))
    out.append(cond_break(60 * mm))
    out.append(h2("5.5  How far the numbers can be trusted: scatter and fragility"))
    out.append(
        grid(
            body_annex.scatter_table(results, EN, lambda c: c.name),
            [x * mm for x in (34, 18, 16, 13, 33, 20, 12, 28)],
            wrap=(0, 4),
            small=True,
            numeric_from=1,
        )
    )
    out.append(
        para(
            "Statistics of a_dyn over the records (a record without collapse up to C_max "
            "enters at its lower bound). Fragility: a lognormal curve fitted by "
            + (
                "maximum likelihood to the fraction of records under which the wall fell at "
                "each intensity of the IDA's ladder"
                if ida_words.is_effective(results)
                else "maximum likelihood to the collapse accelerations (records without "
                "collapse right-censored)"
            )
            + "; P(collapse) is its value at the demand FC·a_g·S, the demand of "
            "the IDA check and of the robustness statement. With few records "
            "the fit is coarse: read it as the scatter of the result, not as a site "
            "probability.",
            "caption",
        )
    )
    sens = adt.sensitivity_table(results, EN)
    if sens is not None and results.sensitivity is not None:
        out.append(cond_break(60 * mm))
        out.append(h2("5.6  What the result depends on: the model conventions"))
        out.append(
            grid(sens, [x * mm for x in (54, 24, 20, 26, 26, 24)], wrap=(0,), numeric_from=1)
        )
        out.append(
            para(
                f"{results.sensitivity.case} under the conventions the paper leaves open, "
                "one at a time (docs/model.md §3), "
                + (
                    "the IDA's ladder shifted by half a step (numerical spread)"
                    if ida_words.is_effective(results)
                    else "the IDA's hunt at the square root of its step ratio (a finer hunt can "
                    "meet a lower collapse window)"
                )
                + ", and a ±10 % change of the bars' elastic modulus; the same records, "
                "the design value of a_dyn. The capacity/demand column is the IDA check's "
                "alone; the deciding checks' verdict and governing margin under each "
                "convention are in the last two columns.",
                "caption",
            )
        )
        spread = ida_words.spread_caption(results, EN)
        if spread is not None:
            out.append(markup(spread, "caption"))
        out += [markup(line) for line in robustness_lines(results, EN)]
    return out


# --- 6 Governing time history -------------------------------------------------------------


def governing(results: Results) -> list[Block]:
    out: list[Block] = [page_break(), h1("7  The governing time history")]
    gov = results.governing
    if not gov or not gov.runs:
        out.append(para("No time history is stored in the results."))
        return out
    out += history_section.blocks(
        results,
        EN,
        lambda t: grid(t, [24 * mm, 20 * mm, 24 * mm, 40 * mm, 22 * mm, 44 * mm], wrap=(0, 3, 5)),
        4,
    )
    return out
