"""The checks: the wall as it is (stato di fatto) and as retrofitted (stato di progetto).
Both languages; words from the catalogue, numbers from the results."""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import charts, ida_words, tie_options_section
from frp_assess.report.body_closing import decision_lines
from frp_assess.report.body_front import option_words, position_words, tie_words
from frp_assess.report.charts import localize_drawing
from frp_assess.report.doc_model import Block, markup_text
from frp_assess.report.flow import cond_break, figure, grid, h1, h2, keep, key_value, markup
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang, short
from frp_assess.report.verdict_text import (
    cell,
    option_target,
    passes,
    rests_on,
    robustness_lines,
    verdict_sentence,
)
from frp_assess.results.checks import CaseChecks
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup

Results = AssessmentResult
#: the header of a column of collapse accelerations
A_DYN = Markup("a<sub>dyn</sub> [g]")


def _bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower else text


def decision(results: Results) -> object | None:
    """The verdict helper's decision block of the results, when the run wrote one."""
    return getattr(results, "decision", None)


def _checks_lines(checks: CaseChecks, lang: Lang) -> str:
    parts: list[tuple[str, float | None, bool]] = [
        (lang.t("check.linear"), checks.linear.zeta_e, checks.linear.passed)
    ]
    parts.append((lang.t("check.slv"), checks.slv.zeta_e, checks.slv.passed))
    parts.append((lang.t("check.slc"), checks.slc.zeta_e, checks.slc.passed))
    # the time-history checks at SLV and at SLC, each at its own a_g·S (both decide)
    for th in (checks.time_history, checks.time_history_slc):
        if th is not None:
            parts.append((lang.t("check.th", ls=th.limit_state), th.zeta_e, th.passed))
    if checks.ida is not None:
        parts.append(("IDA", checks.ida.zeta_e, checks.ida.passed))
    return "; ".join(
        f"{name}: ζ<sub>E</sub> = {lang.num(z, 2)} "
        + f"({lang.t('word.pass' if ok else 'word.fail')})"
        for name, z, ok in parts
        if z is not None
    )


def as_is(results: Results, lang: Lang) -> list[Block]:
    urm = results.urm
    n = lang.num
    target = results.model.target
    out: list[Block] = [h1(lang.t("h.as_is")), h2(lang.t("h.as_is.ida"))]
    records = ida_words.records_table(urm, results, lang)
    widths = (50, 28, 28, 28, 28) if len(records.header) == 5 else (34, 18, 28, 20, 16, 30, 28)
    out.append(grid(records, [x * mm for x in widths], wrap=(0,)))
    out.append(markup(ida_words.records_caption(results, lang), "caption"))
    stat = lang.t("model.design.mean" if results.design_is_mean else "model.design.least")
    lb = urm.lower_bound
    rows = [
        [lang.t("as_is.design_a_dyn"), _bound(n(urm.design_a_dyn, 3), lb) + f" g ({stat})"],
        [lang.t("as_is.fc"), lang.gnum(urm.fc)],
        [lang.t("seismic.demand"), f"{n(results.demand.pga, 3)} g"],
        [lang.t("as_is.cd"), _bound(n(urm.capacity_demand, 2), lb)],
        [lang.t("model.target"), lang.gnum(target)],
    ]
    out.append(key_value(rows, sub_values=True))
    ok = passes(urm)
    out.append(
        markup(
            lang.t("as_is.verdict_ok" if ok else "as_is.verdict_bad",
                   verdict=verdict_sentence(urm, lang),
                   cd=_bound(n(urm.capacity_demand, 2), lb), target=lang.gnum(target)),
            "verdict_ok" if ok else "verdict_bad",
        )
    )  # fmt: skip
    why = rests_on(results, urm, lang)
    if why is not None:
        out.append(markup(why))
    cc = results.code_check
    out.append(h2(lang.t("h.as_is.linear")))
    out.append(
        markup(
            lang.t(
                "as_is.linear",
                alpha0=n(cc.alpha0, 3),
                e_star=n(cc.e_star, 2),
                fc=lang.gnum(cc.FC),
                a0=n(cc.a0_star, 3),
                q=lang.gnum(cc.behaviour_factor),
                demand=n(cc.demand, 3),
                ratio=n(cc.ratio, 2),
                state=lang.t("word.pass" if cc.passed else "word.fail"),
            )
        )
    )
    ties = any(c.tie is not None for c in results.options)
    tie_words = lang.t("as_is.linear_note.ties", section=lang.t("h.retrofit.ties")) if ties else ""
    out.append(markup(lang.t("as_is.linear_note", ties=tie_words), "small"))
    kc = results.kinematic_checks
    if kc is not None and kc.cases:
        out.append(markup(lang.t("as_is.checks", lines=_checks_lines(kc.cases[0], lang))))
    return out


def _ranked(results: Results) -> list[CaseResult]:
    return [c for c in results.ranked_options if c.rank is not None]


def _ranking_table(results: Results, lang: Lang, limit: int = 12) -> TableData:
    n = lang.num
    header = [
        "#",
        lang.t("col.option"),
        lang.t("col.material"),
        lang.t("col.position"),
        "ρ [‰]",
        A_DYN,
        lang.t("col.cd"),
        "I [-]",
        lang.t("col.mass"),
        lang.t("col.cost", currency=short(results.costs.currency)),
        lang.t("verdict.col"),
    ]
    rows = []
    for c in _ranked(results)[:limit]:
        lb = c.lower_bound
        rows.append(
            [
                str(c.rank),
                c.name,
                c.material or "—",
                position_words(c.position, lang, short=True),
                "—" if c.material is None else n(c.ratio, 2),
                _bound(n(c.design_a_dyn, 3), lb),
                _bound(n(c.capacity_demand, 2), lb),
                _bound(n(c.improvement, 2), lb),
                n(c.frp_mass, 1),
                n(c.option_cost, 0, grouping=True),
                cell(c, lang),
            ]
        )
    return TableData(header, rows)


def retrofit(results: Results, lang: Lang) -> list[Block]:
    n = lang.num
    out: list[Block] = [h1(lang.t("h.retrofit"))]
    if not results.options:
        out.append(markup(lang.t("retrofit.none_examined")))
        return out
    any_tie = any(c.tie is not None for c in results.options)
    lead = "retrofit.lead.ties" if any_tie else "retrofit.lead"
    out.append(markup(lang.t(lead, n=len(results.options))))
    rec = results.case(results.recommended)
    compliant = bool(results.input_code_compliant)
    if rec is not None:
        optional = passes(results.urm)  # the wall as it is passes: no retrofit is needed
        key = "retrofit.recommended" if compliant else "retrofit.best_ranked"
        out.append(h2(lang.t("retrofit.optional" if optional and compliant else key)))
        lb = rec.lower_bound
        rows = [
            [lang.t("retrofit.option"), markup_text(option_words(rec, lang))],
            [lang.t("as_is.design_a_dyn"), _bound(n(rec.design_a_dyn, 3), lb) + " g"],
            [lang.t("as_is.cd"), _bound(n(rec.capacity_demand, 2), lb)],
            [lang.t("retrofit.improvement"), _bound(n(rec.improvement, 2), lb)],
            [lang.t("col.mass"), n(rec.frp_mass, 1)],
            [lang.t("col.cost", currency=short(results.costs.currency)),
             n(rec.option_cost, 0, grouping=True)],
        ]  # fmt: skip
        if rec.tie is not None:
            rows.append([lang.t("retrofit.tie"), markup_text(tie_words(rec.tie.tie, lang))])
        b = rec.as_built
        if b is not None:
            rows.append(
                [
                    lang.t("retrofit.layout"),
                    lang.t(
                        "retrofit.layout.one" if b.lines == 1 else "retrofit.layout.faces",
                        n=b.bars_per_line,
                        d=lang.gnum(b.diameter),
                        s=n(b.spacing, 3),
                        faces=b.lines,
                        total=b.total_bars,
                    ),
                ]
            )
            rows.append([lang.t("retrofit.bar_length"), f"{n(b.bar_length, 2)} m"])
        out.append(key_value(rows, sub_values=True, verbatim_rows=(0,)))
        if not compliant:
            out.append(markup(lang.t("retrofit.not_compliant"), "verdict_bad"))
        said = "retrofit.verdict_optional" if optional else "retrofit.verdict"
        said = said if compliant else "retrofit.verdict_best"
        out.append(markup(lang.t(said, verdict=verdict_sentence(rec, lang))))
        why = rests_on(results, rec, lang)
        if why is not None:
            out.append(markup(why))
        out += [markup(line) for line in robustness_lines(results, lang)]
    else:
        out.append(markup(lang.t("retrofit.no_option_meets", target=lang.gnum(
            results.model.target)), "verdict_bad"))  # fmt: skip
        out += decision_lines(results, lang)
        out += [markup(line) for line in robustness_lines(results, lang)]
    out.append(h2(lang.t("h.retrofit.ranking")))
    out.append(markup(lang.t("retrofit.rule", target=option_target(results, lang)), "small"))
    out.append(
        grid(_ranking_table(results, lang),
             [x * mm for x in (8, 24, 18, 19, 10, 15, 18, 10, 13, 15, 24)],
             wrap=(1, 2, 3, 10), numeric_from=4, highlight_rows=[0] if rec is not None else [])
    )  # fmt: skip
    n_dropped = sum(1 for c in results.options if c.rank is None)
    if n_dropped:
        out.append(markup(lang.t("retrofit.dropped", n=n_dropped, total=len(results.options))))
    if len(_ranked(results)) > 12:
        out.append(markup(lang.t("retrofit.more", n=len(_ranked(results)) - 12), "caption"))
    out += tie_options_section.section(results, lang)  # nothing without a tie option
    kc = results.kinematic_checks
    if kc is not None and rec is not None:
        by_name = {c.case: c for c in kc.cases}
        if rec.name in by_name:
            out.append(markup(lang.t("retrofit.checks", lines=_checks_lines(by_name[rec.name],
                                                                          lang))))  # fmt: skip
    out.append(cond_break(90 * mm))
    chart = localize_drawing(charts.options_chart(results, "capacity_demand"), lang)
    out.append(keep([figure(chart), markup(lang.t("fig.cd"), "caption")]))
    return out
