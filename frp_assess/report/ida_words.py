"""The IDA's capacity rule as the report states it, in one place for the body and both
annexes: the rule that ran (results.json ``model.ida.capacity``), the effective collapse
intensity in an engineer's words (docs/model.md §11) or the first collapse as the paper's
convention (§5.1), the per-record table, the numerical spread's caption and the statement
that the verdict sits on a collapse window.  Words from the catalogue (keys ``ida.*``)."""

from __future__ import annotations

from frp_assess.report.flow import esc
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup

Results = AssessmentResult

#: the sensitivity row of the numerical spread (results.json ``sensitivity.rows[].variant``)
SPREAD_PREFIX = "numerical spread"


def is_effective(results: Results) -> bool:
    """The run took the effective collapse intensity as the capacity of a record."""
    return results.model.ida.capacity == "effective"


def rule_key(results: Results, lang: Lang, key: str) -> str:
    """``key`` + ``.effective`` when the run's capacity is the effective collapse intensity
    and the catalogue has that variant, else ``key`` (the first collapse's wording)."""
    alt = f"{key}.effective"
    return alt if is_effective(results) and lang.has(alt) else key


def method_paragraphs(results: Results, lang: Lang) -> list[str]:
    """The method section's IDA paragraphs: the rule that ran, with the run's numbers."""
    ida = results.model.ida
    if not is_effective(results):
        return [lang.t("method.ida"), lang.t("ida.first_collapse.rule", s=lang.gnum(ida.step_ratio),
                                             tol=lang.gnum(ida.tolerance))]  # fmt: skip
    coarse = ida.coarse_steps > 1  # the default sampling of docs/model.md §11.2, design (e)
    return [
        lang.t("ida.effective.what", cmax=lang.gnum(ida.max_multiplier)),
        lang.t(
            "ida.effective.sampling.coarse" if coarse else "ida.effective.sampling",
            r=lang.gnum(ida.ladder_ratio),
            offset=lang.gnum(ida.offset),
            tol=lang.gnum(ida.tolerance),
            band=lang.gnum(ida.early_stop_band),
            every=str(ida.coarse_steps),
            rc=lang.num(ida.ladder_ratio**ida.coarse_steps, 3),
            margin=lang.gnum(ida.fine_margin),
        ),  # fmt: skip
        lang.t("ida.effective.first"),
        spread_text(results, lang),
    ]


def settings_value(results: Results, lang: Lang) -> str:
    """The analysis-settings row of the IDA: its sampling, with the run's numbers."""
    ida = results.model.ida
    eff = is_effective(results)
    key = "model.ida.value.effective" if eff else "model.ida.value"
    return lang.t(
        key + ".coarse" if eff and ida.coarse_steps > 1 else key,
        s=lang.gnum(ida.ladder_ratio if eff else ida.step_ratio),
        tol=lang.gnum(ida.tolerance),
        cmax=lang.gnum(ida.max_multiplier),
        offset=lang.gnum(ida.offset),
        band=lang.gnum(ida.early_stop_band),
        sc=lang.num(ida.ladder_ratio**ida.coarse_steps, 3),
        margin=lang.gnum(ida.fine_margin),
    )


def _spread_numbers(results: Results, lang: Lang) -> tuple[str, str, str] | None:
    """(case, |change| of its design value with the ladder shifted [%], CoV of its a_dyn
    over the records [%]) from the sensitivity table; None without its spread row."""
    sens = results.sensitivity
    if sens is None or not sens.rows:
        return None
    row = next((r for r in sens.rows if r.variant.startswith(SPREAD_PREFIX)), None)
    case = results.case(sens.case)
    if row is None or case is None or case.scatter.cov is None:
        return None
    change = abs(100.0 * (row.design_a_dyn / sens.rows[0].design_a_dyn - 1.0))
    return esc(sens.case), lang.num(change, 1), lang.num(100.0 * case.scatter.cov, 0)


def spread_text(results: Results, lang: Lang) -> str:
    """The numerical spread is not the uncertainty of the capacity; the run's figures of
    both when the sensitivity table has the spread row."""
    found = _spread_numbers(results, lang)
    if found is None:
        return lang.t("ida.effective.spread")
    case, spread, cov = found
    return (
        lang.t("ida.effective.spread")
        + " "
        + lang.t("ida.effective.spread.run", case=case, spread=spread, cov=cov)
    )


def spread_caption(results: Results, lang: Lang) -> str | None:
    """The sensitivity table's "numerical spread" row explained; None when it is not there."""
    sens = results.sensitivity
    if sens is None or not any(r.variant.startswith(SPREAD_PREFIX) for r in sens.rows):
        return None
    return lang.t("ida.spread.caption")


def records_table(case: CaseResult, results: Results, lang: Lang) -> TableData:
    """One row per record: PGA, the capacity C (the rule that ran), a_dyn, q; with the
    effective collapse intensity also the first collapse (the paper's convention) and the
    number of collapse windows below C."""
    n = lang.num
    eff = is_effective(results)
    c_head = lang.t(rule_key(results, lang, "ida.col.c"))
    a_dyn = Markup("a<sub>dyn</sub> [g]")
    header: list[str] = [lang.t("col.record"), "PGA [g]", c_head, a_dyn, "q [-]"]
    if eff:
        header += [lang.t("ida.col.first"), lang.t("ida.col.windows")]
    rows = []
    for r in case.records:
        if r.collapse_multiplier is None:
            row = [r.record, n(r.pga, 3), lang.t("word.no_collapse"), "—", "—"]
        else:
            row = [r.record, n(r.pga, 3), n(r.collapse_multiplier, 3), n(r.a_dyn, 3), n(r.q, 2)]
        if eff:
            first = r.first_collapse_multiplier
            row += [lang.t("word.no_collapse") if first is None else n(first, 3),
                    str(r.windows_below)]  # fmt: skip
        rows.append(row)
    return TableData(header, rows)


def records_caption(results: Results, lang: Lang) -> str:
    """What the per-record table's columns are, for the rule that ran."""
    return lang.t(rule_key(results, lang, "ida.records.caption"))


def collapse_window_line(results: Results, lang: Lang) -> str | None:
    """The robustness statement's "the verdict sits on a collapse window" (results.json
    ``robustness.on_collapse_window``), with the checks at 0.98 and 1.02 times the demand;
    None when the verdict holds there."""
    rob = results.robustness
    if rob is None or not rob.on_collapse_window:
        return None
    near = "; ".join(
        lang.t("ida.near_demand", factor=lang.gnum(nd.factor),
               verdict=lang.t("verdict.cell.pass" if nd.passes else "verdict.cell.fail"))
        for nd in rob.time_history_near_demand
    )  # fmt: skip
    return lang.t("ida.on_window", case=esc(rob.case), near=near)
