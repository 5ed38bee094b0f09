"""The annex's sections on the results in the report's language: B.4 the unreinforced wall,
B.5 the retrofit options (ranking, charts, design mode, a_dyn of every record, scatter,
model conventions) and B.7 the governing time history.  Words from the catalogue, tables
from :mod:`~frp_assess.report.annex_result_tables` and
:mod:`~frp_assess.report.annex_design_tables`."""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import annex_design_tables as adt
from frp_assess.report import annex_result_tables as tr
from frp_assess.report import charts, history_section, ida_words
from frp_assess.report.annex_design_tables import case_label
from frp_assess.report.annex_floor import checks_part
from frp_assess.report.annex_input_tables import wall_property_rows
from frp_assess.report.charts import localize_drawing
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import (
    cond_break,
    esc,
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
from frp_assess.report.formats import column_blocks, run_words, shows_run_prose
from frp_assess.report.lang import Lang
from frp_assess.report.verdict_text import robustness_lines
from frp_assess.results.model import AssessmentResult

Results = AssessmentResult


def unreinforced(results: Results, lang: Lang) -> list[Block]:
    """B.4: the rocking properties, the IDA record by record, the comparison with the code's
    linear check and the code's checks of every case."""
    urm = results.urm
    out: list[Block] = [page_break(), h1("4  " + lang.t("ax.h.urm")),
                        h2("4.1  " + lang.t("ax.h.rocking"))]  # fmt: skip
    out.append(key_value(wall_property_rows(results, lang), sub_values=True))
    out.append(h2("4.2  " + lang.t("ax.h.ida")))
    records = ida_words.records_table(urm, results, lang)
    widths = (30, 28, 40, 28, 24) if len(records.header) == 5 else (30, 18, 30, 20, 14, 30, 28)
    out.append(grid(records, [x * mm for x in widths], wrap=(0,)))
    out.append(markup(ida_words.records_caption(results, lang), "caption"))
    out.append(key_value(tr.case_summary_rows(results, urm, lang), sub_values=True))
    out.append(h2("4.3  " + lang.t("ax.h.comparison")))
    widths = (62, 24, 24, 28, 30)
    out.append(grid(tr.comparison_table(results, lang), [x * mm for x in widths], wrap=(0,)))
    out.append(gap(6))
    out.append(key_value(tr.code_check_rows(results, lang), sub_values=True))
    note = run_words(results.code_check.note, lang)
    if note:
        out.append(para(note, "caption"))
    out += checks_part(results, lang)
    return out


def _ranking(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = []
    rule = run_words(results.ranking_rule, lang)
    if rule is not None:
        out.append(markup(lang.t("ax.rank.rule", rule=esc(rule)), "small"))
    data = tr.ranking_table(results, lang)
    rec = results.recommended
    hl = [i for i, c in enumerate([results.urm, *tr.ranked_options(results)]) if c.name == rec]
    widths = [12, 22, 11, 14, 8, 11, 11, 11, 14, 12, 16, 15, 15]  # rank: "dropped"
    out.append(grid(data, [x * mm for x in widths], wrap=(1, 2, 3, 12), small=True, numeric_from=4,
                    highlight_rows=hl))  # fmt: skip
    key = (
        "ax.rank.caption.not"
        if not results.input_code_compliant
        else "ax.rank.caption.compliant"
        if results.retrofit_required
        else "ax.rank.caption.optional"
    )
    out.append(markup(lang.t("ax.rank.caption", highlighted=lang.t(key)), "caption"))
    for c in results.options:  # dropped by the pivot check: no rank, the reason here
        if c.pivot is not None and c.pivot.dropped:
            said = run_words(c.pivot.reason, lang)
            out.append(para(said or lang.t("ax.dropped.reason", case=case_label(c, lang)), "small"))
    return out


def _charts(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = []
    for kind, key in (("improvement", "ax.fig.improvement"), ("capacity_demand", "ax.fig.cd")):
        chart = localize_drawing(charts.options_chart(results, kind), lang)
        out.append(keep([figure(chart), markup(lang.t(key), "caption")]))
    return out


def _design(results: Results, lang: Lang) -> list[Block]:
    design = adt.design_table(results, lang)
    if design is None:
        return [markup(lang.t("ax.design.not_run"))]
    notes = shows_run_prose(lang)  # the run's note in a last column
    widths = [16, 18, 20, 20, 18, 18, 64] if notes else [28, 30, 30, 28, 28, 30]
    wrap = (6,) if notes else (1,)
    out: list[Block] = [grid(design, [x * mm for x in widths], wrap=wrap, numeric_from=2)]
    out.append(markup(lang.t("annex.design.note"), "caption"))
    return out


def _records(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = []
    for block in column_blocks(adt.a_dyn_table(results, lang)):
        n = len(block.header) - 1
        other = (174 - 34) / max(n, 1)
        out.append(grid(block, [34 * mm] + [other * mm] * n, wrap=(0,), small=True))
    out.append(markup(lang.t("annex.nc.note"), "caption"))
    out.append(cond_break(60 * mm))
    out.append(h2("5.5  " + lang.t("ax.h.scatter")))
    widths = (34, 18, 16, 13, 33, 20, 12, 28)
    out.append(grid(adt.scatter_table(results, lang), [x * mm for x in widths], wrap=(0, 4),
                    small=True, numeric_from=1))  # fmt: skip
    out.append(markup(lang.t(ida_words.rule_key(results, lang, "ax.scatter.caption")), "caption"))
    return out


def _sensitivity(results: Results, lang: Lang) -> list[Block]:
    sens = adt.sensitivity_table(results, lang)
    if sens is None or results.sensitivity is None:
        return []
    label = next((case_label(c, lang) for c in results.cases
                  if c.name == results.sensitivity.case), results.sensitivity.case)  # fmt: skip
    out: list[Block] = [cond_break(60 * mm), h2("5.6  " + lang.t("annex.h.sensitivity"))]
    widths = (54, 24, 20, 26, 26, 24)
    out.append(grid(sens, [x * mm for x in widths], wrap=(0,), numeric_from=1))
    note = ida_words.rule_key(results, lang, "ax.sens.caption")
    out.append(markup(lang.t(note, case=esc(label)), "caption"))
    spread = ida_words.spread_caption(results, lang)
    if spread is not None:
        out.append(markup(spread, "caption"))
    out += [markup(line) for line in robustness_lines(results, lang)]
    return out


def options(results: Results, lang: Lang) -> list[Block]:
    """B.5: the ranking, the charts of the FRP quantity, the design mode, a_dyn of every
    option and record, the scatter and the model conventions."""
    out: list[Block] = [page_break(), h1("5  " + lang.t("ax.h.options")),
                        h2("5.1  " + lang.t("ax.h.ranking"))]  # fmt: skip
    out += _ranking(results, lang)
    out.append(cond_break(90 * mm))
    out.append(h2("5.2  " + lang.t("ax.h.quantity")))
    out += _charts(results, lang)
    out.append(cond_break(50 * mm))
    out.append(h2("5.3  " + lang.t("ax.h.design")))
    out += _design(results, lang)
    out.append(cond_break(80 * mm))
    out.append(h2("5.4  " + lang.t("ax.h.a_dyn")))
    out += _records(results, lang)
    out += _sensitivity(results, lang)
    return out


def governing(results: Results, lang: Lang) -> list[Block]:
    """B.7: the governing time history."""
    out: list[Block] = [page_break(), h1("7  " + lang.t("annex.h.history"))]
    widths = (24, 20, 24, 40, 22, 44)
    out += history_section.blocks(
        results, lang, lambda t: grid(t, [x * mm for x in widths], wrap=(0, 3, 5)), 4
    )
    return out
