"""The annex's tables of the results (the ranking, the summary's short list, the wall as it is
against the code's linear check) as pure functions of the typed results, in the report's
language: words from the catalogue (keys ``ax.*``), numbers by
:class:`~frp_assess.report.lang.Lang` (accelerations in g with 3 decimals, ratios with 2,
masses in kg with 1, costs with 0 and grouped thousands)."""

from __future__ import annotations

from frp_assess.report.annex_design_tables import case_label
from frp_assess.report.body_front import position_words
from frp_assess.report.formats import (
    DASH,
    TableData,
    bound,
    capacity_text,
    case_by_name,
    permille,
    ranked_options,
)
from frp_assess.report.lang import Lang
from frp_assess.report.verdict_text import cell, governing
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.rules.record_sets import MEAN_OF_RECORDS_FROM
from frp_assess.text_safety import Markup, pdf

Results = AssessmentResult


def a_dyn_label(results: Results, lang: Lang) -> Markup:
    """Header markup of the design a_dyn column (the mean, or the least favourable)."""
    return Markup(lang.t("ax.col.a_dyn.mean" if results.design_is_mean else "ax.col.a_dyn.min"))


def rank_text(case: CaseResult, lang: Lang) -> str:
    """The rank, "dropped" for an option the pivot check dropped, else a dash."""
    if case.rank is not None:
        return str(case.rank)
    dropped = case.pivot is not None and case.pivot.dropped and not case.is_unreinforced
    return lang.t("annex.dropped") if dropped else DASH


def ranking_row(case: CaseResult, target: float, lang: Lang) -> list[str]:
    lb = case.lower_bound
    n = lang.num
    return [
        rank_text(case, lang),
        case_label(case, lang),
        case.material or lang.t("ax.tie" if case.tie is not None else "ax.none"),
        DASH if case.position is None else position_words(case.position, lang, short=True),
        DASH if case.material is None else permille(case.ratio, lang),
        n(case.frp_mass_per_m, 1),
        n(case.frp_mass, 1),
        n(case.option_cost, 0, grouping=True),
        bound(n(case.design_a_dyn, 3), lb),
        bound(n(case.mean_q, 2), lb),
        bound(n(case.improvement, 2), lb),
        bound(capacity_text(case, target, lang), lb),
        cell(case, lang),
    ]


def ranking_table(results: Results, lang: Lang) -> TableData:
    """Unreinforced wall first, then every option by rank."""
    cur = pdf(results.costs.currency)
    header: list[str] = [
        lang.t("ax.col.rank"),
        lang.t("ax.col.option"),
        Markup(lang.t("ax.col.material_br")),
        Markup(lang.t("ax.col.position")),
        "ρ [‰]",
        Markup(lang.t("ax.col.frp_per_m")),
        Markup(lang.t("ax.col.frp_wall_br")),
        Markup(lang.t("ax.col.cost_br", cur=cur)),
        a_dyn_label(results, lang),
        lang.t("ax.col.mean_q"),
        Markup(lang.t("ax.col.improvement_br")),
        Markup(lang.t("ax.col.cd_br")),
        Markup(lang.t("ax.col.checks_br")),
    ]
    target = float(results.model.target)
    cases = [results.urm, *ranked_options(results)]
    return TableData(header, [ranking_row(c, target, lang) for c in cases])


def summary_table(results: Results, lang: Lang, n_alternatives: int = 3) -> TableData:
    """The unreinforced wall, the recommended option and the best alternatives."""
    cur = pdf(results.costs.currency)
    n = lang.num
    header = [
        "",
        lang.t("ax.col.option"),
        lang.t("ax.col.frp_wall"),
        Markup(lang.t("ax.col.cost", cur=cur)),
        a_dyn_label(results, lang),
        Markup(lang.t("ax.col.improvement_br")),
        Markup(lang.t("ax.col.cd_br")),
        Markup(lang.t("ax.col.checks_br")),
    ]
    ranked = [c for c in ranked_options(results) if c.rank is not None]  # not the dropped
    chosen: list[tuple[str, CaseResult]] = [(lang.t("ax.role.existing"), results.urm)]
    rec = case_by_name(results, results.recommended)
    if rec is not None:
        urm_ok = cell(results.urm, lang) == lang.t("verdict.cell.pass")
        if not results.input_code_compliant:
            role = "ax.role.best_ranked"
        else:
            role = "ax.role.optional" if urm_ok else "ax.role.recommended"
        chosen.append((lang.t(role), rec))
    others = [c for c in ranked if c is not rec][:n_alternatives]
    key = "ax.role.alternative" if rec else "ax.role.best"
    chosen += [(lang.t(key, i=i), c) for i, c in enumerate(others, 1)]
    target = float(results.model.target)
    rows = []
    for role, c in chosen:
        lb = c.lower_bound
        rows.append([role, case_label(c, lang), n(c.frp_mass, 1),
                     n(c.option_cost, 0, grouping=True), bound(n(c.design_a_dyn, 3), lb),
                     bound(n(c.improvement, 2), lb), bound(capacity_text(c, target, lang), lb),
                     cell(c, lang)])  # fmt: skip
    return TableData(header, rows)


def case_summary_rows(results: Results, case: CaseResult, lang: Lang) -> list[list[str]]:
    lb = case.lower_bound
    n = lang.num
    target = float(results.model.target)
    rows = [
        [lang.t("ax.case.mean"), bound(f"{n(case.mean_a_dyn, 3)} g", lb)],
        [lang.t("ax.case.least"), f"{n(case.min_a_dyn, 3)} g"],
        [lang.t("ax.case.q"), bound(n(case.mean_q, 2), lb)],
        [
            lang.t("ax.case.cd"),
            bound(capacity_text(case, target, lang), lb)
            + lang.t("ax.case.cd.value", fc=lang.gnum(case.fc), ags=n(results.demand.pga, 3)),
        ],
        [lang.t("ax.case.checks"), f"{cell(case, lang)}: {governing(case, lang)}"],
    ]
    if case.design_a_dyn is not None and not results.design_is_mean:
        design = f"{n(case.design_a_dyn, 3)} g"
        rows.insert(2, [lang.t("ax.case.design", n=MEAN_OF_RECORDS_FROM), design])
    return rows


def satisfied(ok: bool, lang: Lang) -> str:
    """The verdict of a check: satisfied or NOT satisfied."""
    return lang.t("word.pass" if ok else "word.fail")


def code_check_rows(results: Results, lang: Lang) -> list[list[str]]:
    k = results.code_check
    n = lang.num
    return [
        [lang.t("ax.code.alpha0"), n(k.alpha0, 4)],
        [lang.t("ax.code.e_star"), n(k.e_star, 3)],
        [lang.t("ax.code.m_star"), f"{n(k.M_star, 1)} kg/m"],
        [lang.t("ax.code.fc"), f"{lang.gnum(k.FC)} ({k.confidence_factor_level or DASH})"],
        [lang.t("ax.code.q"), lang.gnum(k.behaviour_factor)],
        ["a₀* = α₀·g / (e*·FC)", f"{n(k.a0_star, 3)} g"],
        [
            lang.t("ax.code.demand.floor" if results.building else "ax.code.demand"),
            f"{n(k.demand, 3)} g",
        ],  # fmt: skip
        [lang.t("ax.code.ratio"), n(k.ratio, 2)],
        [lang.t("ax.code.verdict"), satisfied(k.passed, lang)],
    ]


def comparison_table(results: Results, lang: Lang) -> TableData:
    """The IDA verdict of the unreinforced wall next to the code linear kinematic check."""
    urm = results.urm
    k = results.code_check
    n = lang.num
    lb = urm.lower_bound
    header = [lang.t(f"ax.cmp.{c}") for c in ("what", "capacity", "demand", "ratio", "verdict")]
    rows = [
        [
            lang.t("ax.cmp.ida.fc" if urm.fc != 1.0 else "ax.cmp.ida"),
            bound(n(urm.design_a_dyn / urm.fc, 3), lb),
            n(results.demand.pga, 3),
            bound(capacity_text(urm, float(results.model.target), lang), lb),
            satisfied(urm.meets_target, lang),
        ],
        [
            lang.t("ax.cmp.linear"),
            n(k.a0_star, 3),
            n(k.demand, 3),
            n(k.ratio, 2),
            satisfied(k.passed, lang),
        ],
    ]
    return TableData(header, rows)
