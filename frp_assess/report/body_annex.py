"""The calculation details in the report's language (the Italian annex): every option, the
design mode, the collapse acceleration of every option and accelerogram, the scatter, the
model conventions, the code's checks of every case, the bars as built and their anchorage
(three of them in :mod:`~frp_assess.report.annex_design_tables`).  Words from the
catalogue, numbers from the results."""

from __future__ import annotations

from collections.abc import Callable

from reportlab.lib.units import mm

from frp_assess.report import history_section, ida_words, pivot_section
from frp_assess.report.body_front import position_words
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, esc, grid, h1, h2, markup
from frp_assess.report.formats import TableData, column_blocks
from frp_assess.report.lang import Lang, short
from frp_assess.report.verdict_text import (
    cell,
    collapse_probability,
    probability_text,
    robustness_lines,
)
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup

Results = AssessmentResult


def _bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower else text


def case_label(c: CaseResult, lang: Lang) -> str:
    """A case in a table: the wall as it is, or the option's name as the user wrote it (the
    project file's ``interventions[].name``, whatever the report's language; its material,
    position and ρ are in the ranking and the annex's option table)."""
    if c.is_unreinforced:
        return lang.t("annex.urm")
    return c.name


def _described(c: CaseResult, lang: Lang) -> str:
    """An option's name (:func:`case_label`) with its material, position and ρ [‰]."""
    pos = position_words(c.position, lang, short=True)
    return f"{case_label(c, lang)} ({c.material or '—'}, {pos}, {lang.num(c.ratio, 2)} ‰)"


def _cases(results: Results) -> list[CaseResult]:
    return [results.urm, *results.ranked_options]


def options_table(results: Results, lang: Lang) -> TableData:
    n = lang.num
    header = [
        "#",
        lang.t("annex.col.option"),
        Markup("a<sub>dyn,d</sub> [g]"),
        lang.t("col.cd"),
        "I [-]",
        lang.t("col.mass"),
        lang.t("col.cost", currency=short(results.costs.currency)),
        lang.t("verdict.col"),
    ]
    rows = []
    for c in results.ranked_options:
        lb = c.lower_bound
        rank = str(c.rank) if c.rank is not None else lang.t("annex.dropped")
        rows.append([rank, _described(c, lang), _bound(n(c.design_a_dyn, 3), lb),
                     _bound(n(c.capacity_demand, 2), lb), _bound(n(c.improvement, 2), lb),
                     n(c.frp_mass, 1), n(c.option_cost, 0, grouping=True),
                     cell(c, lang)])  # fmt: skip
    return TableData(header, rows)


def a_dyn_table(
    results: Results, lang: Lang, label: Callable[[CaseResult], str] | None = None
) -> TableData:
    """a_dyn [g] of every case and record, the wall as it is first, then by rank
    (``label(case)`` names a case; default :func:`case_label`)."""
    name_of = label or (lambda c: case_label(c, lang))
    names = [r.name for r in results.records]
    rows = []
    for c in _cases(results):
        by_rec = {r.record: r for r in c.records}
        cells = []
        for name in names:
            r = by_rec.get(name)
            if r is None:
                cells.append("—")
            else:
                cells.append(lang.t("annex.nc") if r.a_dyn is None else lang.num(r.a_dyn, 3))
        rows.append([name_of(c), *cells])
    return TableData([lang.t("annex.col.option"), *names], rows)


def scatter_table(
    results: Results, lang: Lang, label: Callable[[CaseResult], str] | None = None
) -> TableData:
    """Record-to-record scatter of a_dyn and the lognormal fragility of every case (the wall
    as it is first, then by rank): mean, median, CoV, least favourable (record), fragility
    median, β and P(collapse) at FC·a_g·S; dashes where no lognormal was fitted.
    ``label(case)`` names a case (default :func:`case_label`)."""
    n = lang.num
    name = label or (lambda c: case_label(c, lang))
    header = [
        lang.t("annex.col.option"),
        Markup(lang.t("annex.col.mean")),
        Markup(lang.t("annex.col.median")),
        lang.t("annex.col.cov"),
        lang.t("annex.col.least"),
        lang.t("annex.col.frag_median"),
        "β [-]",
        Markup(lang.t("annex.col.pcollapse")),
    ]
    rows = []
    for c in _cases(results):
        sc = c.scatter
        fr = sc.fragility
        at = collapse_probability(results, c)
        rows.append([name(c), n(c.mean_a_dyn, 3), n(sc.median_a_dyn, 3), n(sc.cov, 2),
                     f"{n(c.min_a_dyn, 3)} ({sc.least_favourable_record})",
                     "—" if fr is None else n(fr.median, 3),
                     "—" if fr is None else n(fr.beta, 2),
                     "—" if at is None else probability_text(at[1], lang)])  # fmt: skip
    return TableData(header, rows)


def checks_table(results: Results, lang: Lang) -> TableData | None:
    kc = results.kinematic_checks
    if kc is None or not kc.cases:
        return None
    # the SLC time-history column when any case has it (files written before it: none)
    slc = any(k.time_history_slc is not None for k in kc.cases)
    header = [lang.t("annex.col.option"), lang.t("check.linear"), lang.t("check.slv"),
              lang.t("check.slc"), lang.t("check.th", ls="SLV"),
              *([lang.t("check.th", ls="SLC")] if slc else []), "IDA"]  # fmt: skip
    by_name = {c.name: c for c in results.cases}

    def cell(z: float | None, ok: bool | None) -> str:
        if ok is None:
            return "—"
        zeta = "—" if z is None else lang.num(z, 2)
        return f"{zeta} {lang.t('annex.ok' if ok else 'annex.ko')}"

    rows = []
    for k in kc.cases:
        case = by_name.get(k.case)
        label = case_label(case, lang) if case is not None else k.case
        th, th_slc, ida = k.time_history, k.time_history_slc, k.ida
        rows.append([
            label,
            cell(k.linear.zeta_e, k.linear.passed),
            cell(k.slv.zeta_e, k.slv.passed),
            cell(k.slc.zeta_e, k.slc.passed),
            cell(th.zeta_e, th.passed) if th is not None else "—",
            *([cell(th_slc.zeta_e, th_slc.passed) if th_slc is not None else "—"] if slc else []),
            cell(ida.zeta_e, ida.passed) if ida is not None else "—",
        ])  # fmt: skip
    return TableData(header, rows)


def intensities_text(results: Results, lang: Lang) -> str:
    """One sentence: the a_g·S each limit state is checked at (its own spectrum from the
    site, or the one spectrum given); empty for results without it."""
    kc = results.kinematic_checks
    if kc is None or not kc.intensities:
        return ""
    if kc.intensities[0].source == "site":
        states = "; ".join(
            f"{i.limit_state} a<sub>g</sub>·S = {lang.num(i.a_g_s, 3)} g" for i in kc.intensities
        )
        return lang.t("annex.checks.states", states=states)
    return lang.t("annex.checks.one_spectrum", ags=lang.num(kc.intensities[0].a_g_s, 3))


def bars_table(results: Results, lang: Lang) -> TableData | None:
    n = lang.num
    built = [(c, c.as_built) for c in results.ranked_options if c.as_built is not None]
    if not built:
        return None
    header = [lang.t("annex.col.option"), "Ø [mm]", lang.t("annex.col.per_line"),
              lang.t("annex.col.lines"), lang.t("annex.col.spacing"), lang.t("annex.col.total"),
              Markup("ρ<sub>inst</sub> [‰]"), lang.t("annex.col.length")]  # fmt: skip
    rows = [
        [case_label(c, lang), lang.gnum(b.diameter), str(b.bars_per_line), str(b.lines),
         n(b.spacing, 3), str(b.total_bars), n(b.ratio_installed, 3), n(b.bar_length, 2)]
        for c, b in built
        if b is not None
    ]  # fmt: skip
    return TableData(header, rows)


def annex(results: Results, lang: Lang) -> list[Block]:
    """The annex: heading and its parts B.1, B.2 ... (none of them numbered by the body;
    a part without data, e.g. the design mode not run, is left out and not numbered)."""
    from frp_assess.report import annex_design_tables as adt

    out: list[Block] = [h1(lang.t("h.annex")), markup(lang.t("annex.lead.short"))]
    part = 0

    def heading(key: str) -> Block:
        nonlocal part
        part += 1
        return h2(f"B.{part}  " + lang.t(key))

    if results.options:
        out += [heading("annex.h.options")]
        widths = [x * mm for x in (12, 52, 20, 20, 14, 16, 20, 20)]
        table = options_table(results, lang)
        out.append(grid(table, widths, wrap=(1,), numeric_from=2, small=True))
    design = adt.design_table(results, lang)
    if design is not None:
        out += [cond_break(60 * mm), heading("annex.h.design")]
        out.append(grid(design, [x * mm for x in (22, 30, 30, 26, 22, 28)], wrap=(1,),
                        numeric_from=2, small=True))  # fmt: skip
        out.append(markup(lang.t("annex.design.note"), "caption"))
    out += [cond_break(60 * mm), heading("annex.h.a_dyn")]
    for block in column_blocks(a_dyn_table(results, lang)):
        names = len(block.header) - 1
        other = (174 - 48) / max(names, 1)
        out.append(grid(block, [48 * mm] + [other * mm] * names, wrap=(0,), small=True))
    out.append(markup(lang.t("annex.nc.note"), "caption"))
    out += [cond_break(60 * mm), heading("annex.h.scatter")]
    widths = [x * mm for x in (40, 18, 18, 14, 30, 18, 12, 24)]
    out.append(grid(scatter_table(results, lang), widths, wrap=(0, 4), numeric_from=1,
                    small=True))  # fmt: skip
    out.append(markup(lang.t(ida_words.rule_key(results, lang, "annex.scatter.note")), "caption"))
    sens = adt.sensitivity_table(results, lang)
    if sens is not None and results.sensitivity is not None:
        label = next((case_label(c, lang) for c in results.cases
                      if c.name == results.sensitivity.case), results.sensitivity.case)  # fmt: skip
        out += [cond_break(60 * mm), heading("annex.h.sensitivity")]
        out.append(grid(sens, [x * mm for x in (58, 22, 20, 24, 26, 24)], wrap=(0,),
                        numeric_from=1, small=True))  # fmt: skip
        out += [markup(line) for line in robustness_lines(results, lang)]
        note = ida_words.rule_key(results, lang, "annex.sensitivity.note")
        out.append(markup(lang.t(note, case=esc(label)), "caption"))
        spread = ida_words.spread_caption(results, lang)
        if spread is not None:
            out.append(markup(spread, "caption"))
    checks = checks_table(results, lang)
    if checks is not None:
        out += [cond_break(60 * mm), heading("annex.h.checks")]
        # 174 mm, the text width, with or without the SLC time-history column
        cols = (52, 24, 24, 24, 26, 24) if len(checks.header) == 6 else (42, 20, 21, 21, 25, 25, 20)
        out.append(grid(checks, [x * mm for x in cols], wrap=(0,), small=True))
        out.append(markup(lang.t("annex.checks.note"), "caption"))
        states = intensities_text(results, lang)
        if states:
            out.append(markup(states, "caption"))
    if any(c.pivot is not None for c in results.cases):
        out += [cond_break(60 * mm), heading("annex.h.pivot")]
        out.append(markup(pivot_section.masonry_text(results, lang)))
        out.append(grid(pivot_section.pivot_table(results, lang, lambda c: case_label(c, lang)),
                        [x * mm for x in (48, 18, 16, 16, 24, 52)], wrap=(0, 5),
                        numeric_from=1, small=True))  # fmt: skip
        out.append(markup(lang.t("pivot.caption"), "caption"))
        out += [markup(line) for line in pivot_section.weaker_notes(
            results, lang, lambda c: case_label(c, lang))]  # fmt: skip
    bars = bars_table(results, lang)
    if bars is not None:
        out += [cond_break(60 * mm), heading("annex.h.bars")]
        out.append(grid(bars, [x * mm for x in (52, 14, 18, 14, 20, 16, 20, 20)], wrap=(0,),
                        small=True))  # fmt: skip
    if results.governing is not None and results.governing.runs:
        out += [cond_break(90 * mm), heading("annex.h.history")]
        out += history_section.blocks(
            results,
            lang,
            lambda t: grid(
                t, [x * mm for x in (26, 18, 24, 44, 20, 42)], wrap=(0, 3, 5), small=True
            ),  # fmt: skip
            3,
        )
    anchorage = adt.anchorage_table(results, lang)
    if anchorage is not None:
        out += [cond_break(60 * mm), heading("annex.h.anchorage")]
        out.append(grid(anchorage, [x * mm for x in (62, 28, 28, 28, 28)], wrap=(0,),
                        numeric_from=1, small=True))  # fmt: skip
        out.append(markup(lang.t("annex.anchorage.note"), "caption"))
    return out
