"""The governing time history, in the report's language (the English and the Italian annex
alike): the case and record, the runs at the collapse multiplier and just below it, and the
chart of θ/α and of the bar strain. Words from the catalogue, numbers from the results."""

from __future__ import annotations

import re

from frp_assess.report import charts
from frp_assess.report.doc_model import Block, with_subscripts
from frp_assess.report.flow import esc, figure, keep, markup
from frp_assess.report.formats import TableData, rupture_strain_words
from frp_assess.report.ida_words import rule_key
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, HistoryRun
from frp_assess.text_safety import Markup

Results = AssessmentResult
#: chart labels with a number or a run's label in them: (pattern, catalogue key)
_CHART = (
    (re.compile(r"leaves the plot at t = (.+) s"), "hist.chart.leaves"),
    (re.compile(r"(collapse|just below), C = (.+)"), "hist.chart.run"),
)


def words(key: str, lang: Lang) -> str:
    """A run's label or fate in the report's language (the catalogue's ``hist.<key>``)."""
    k = "hist." + key.replace(" ", "_")
    return lang.t(k) if lang.has(k) else esc(key)


def runs_table(results: Results, lang: Lang) -> TableData:
    """Per run: label, C, C·PGA [g], fate (decided at [s]), peak θ/α, peak ε [‰] (and when
    the bar broke)."""
    header = [lang.t("hist.col.run"), "C [-]", "a = C·PGA [g]", lang.t("hist.col.fate"),
              Markup("θ/α max [-]"), Markup("ε max [‰]")]  # fmt: skip
    gov = results.governing
    if gov is None:
        return TableData(header, [])
    pga = next((r.pga for r in results.records if r.name == gov.record), None)
    n = lang.num

    def fate(run: HistoryRun) -> str:
        said = words(run.fate, lang)
        return said if run.decided_time is None else f"{said} ({n(run.decided_time, 2)} s)"

    rows = []
    for run in gov.runs:
        strain = n(1e3 * run.peak_strain, 2)
        if run.ruptures:
            strain += " " + lang.t("hist.broke", t=n(run.ruptures[0].time, 2))
        rows.append([words(run.label, lang), n(run.multiplier, 3),
                     "—" if pga is None else n(run.multiplier * pga, 3), fate(run),
                     n(run.peak_rotation_ratio, 2), strain])  # fmt: skip
    return TableData(header, rows)


def chart_label(text: str, lang: Lang) -> str:
    """A label of the history chart in the report's language."""
    mark = "▲ " if text.startswith("▲ ") else ""
    if mark:
        return mark + chart_label(text[len(mark) :], lang)
    for pattern, key in _CHART:
        m = pattern.fullmatch(text)
        if m is not None:
            values = [lang.numbers_in(g) for g in m.groups()]
            if key == "hist.chart.run":
                return lang.t(key, run=words(values[0], lang), c=values[1])
            return lang.t(key, t=values[0])
    return lang.chart_label(text)


def blocks(results: Results, lang: Lang, table: object, figure_no: int) -> list[Block]:
    """The lead paragraph, the runs table (drawn by ``table(TableData)``: the caller's widths)
    and the chart with its caption; a sentence when no history is stored."""
    gov = results.governing
    if not gov or not gov.runs:
        return [markup(lang.t("hist.none"))]
    rs = gov.rupture_strain
    lead = lang.t(rule_key(results, lang, "hist.lead"), case=esc(gov.case), record=esc(gov.record))
    if rs is not None:
        rule = with_subscripts(esc(rupture_strain_words(results)))
        lead += " " + lang.t("hist.rupture", rule=rule,
                             eps=lang.num(1e3 * rs, 2))  # fmt: skip
    out: list[Block] = [markup(lead), table(runs_table(results, lang))]  # type: ignore[operator]
    chart = charts.history_chart(results)
    if chart is not None:
        if lang.code != "en":
            charts.relabel(chart, lambda text: chart_label(text, lang))
        caption = markup(lang.t(rule_key(results, lang, "hist.caption"), n=figure_no), "caption")
        out.append(keep([figure(chart), caption]))
    return out
