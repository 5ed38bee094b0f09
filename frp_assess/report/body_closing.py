"""Conclusions and the appendix of assumptions and references (both languages)."""

from __future__ import annotations

from frp_assess.report import ida_words, loads_section
from frp_assess.report.body_front import option_words
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, h1, h2, markup
from frp_assess.report.lang import Lang
from frp_assess.report.verdict_text import (
    category_sentence,
    check_words,
    margin_text,
    passes,
    rests_on,
    robustness_lines,
    verdict_sentence,
)
from frp_assess.report.verdict_text import governing as governing_words
from frp_assess.results.model import AssessmentResult

Results = AssessmentResult


def _bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower else text


def conclusions(results: Results, lang: Lang) -> list[Block]:
    n = lang.num
    urm = results.urm
    target = lang.gnum(results.model.target)
    out: list[Block] = [h1(lang.t("h.conclusions"))]
    ok = passes(urm)
    cd = _bound(n(urm.capacity_demand, 2), urm.lower_bound)
    out.append(markup(lang.t("concl.as_is_ok" if ok else "concl.as_is_bad", cd=cd,
                             target=target, verdict=verdict_sentence(urm, lang))))  # fmt: skip
    why = rests_on(results, urm, lang)
    if why is not None:
        out.append(markup(why))
    failure = getattr(urm, "failure_mode", None)
    if failure:  # the kernel's failure mode, by its catalogue name when it has one
        key = f"failure:{failure}"
        mode = lang.t(key) if lang.has(key) else esc(str(failure).replace("_", " "))
        out.append(markup(lang.t("concl.failure_mode", mode=mode)))
    if not results.compliance.passed:
        out.append(markup(lang.t("concl.not_compliant"), "verdict_bad"))
    rec = results.case(results.recommended)
    if rec is not None:
        key = "concl.recommended" if results.input_code_compliant else "concl.best_ranked"
        if ok:
            key = "concl.not_needed"
        out.append(
            markup(
                lang.t(
                    key,
                    option=option_words(rec, lang),
                    cd=_bound(n(rec.capacity_demand, 2), rec.lower_bound),
                    improvement=_bound(n(rec.improvement, 2), rec.lower_bound),
                    mass=n(rec.frp_mass, 1),
                    cost=n(rec.option_cost, 0, grouping=True),
                    currency=esc(results.costs.currency),
                )
            )
        )
    elif results.options and results.case(results.closest) is None:
        out.append(markup(lang.t("retrofit.no_option_meets", target=target), "verdict_bad"))
    out += decision_lines(results, lang)
    out += [markup(line) for line in robustness_lines(results, lang)]
    if urm.lower_bound or any(c.lower_bound for c in results.options):
        out.append(markup(lang.t("concl.lower_bound"), "small"))
    out.append(markup(lang.t("concl.details")))
    out.append(markup(lang.t("concl.responsibility")))
    return out


def decision_lines(results: Results, lang: Lang) -> list[Block]:
    """The governing check and its margin for the wall as it is and the recommended option,
    and the closest option when none passes (the decision fields of the results; [] in
    files written before them)."""
    out: list[Block] = []
    category = category_sentence(results, lang)
    if category is not None and results.options:
        out.append(markup(category))
    rec = results.case(results.recommended)
    for case, key in ((rec, "decision.option"),):  # the wall as it is: in its verdict
        check = getattr(case, "governing_check", None) if case is not None else None
        if check is None or case is None:
            continue
        shown = margin_text(case, lang)
        out.append(markup(lang.t(key, check=check_words(str(check), lang), margin=shown)))
    closest = results.case(getattr(results, "closest", None))
    if closest is not None:
        out.append(markup(lang.t("decision.closest", option=option_words(closest, lang),
                                 governing=governing_words(closest, lang))))  # fmt: skip
    return out


def appendix(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = [h1(lang.t("h.appendix")), h2(lang.t("h.appendix.assumptions"))]
    piv = results.urm.pivot
    rule = piv.rule if piv is not None else "edge"
    out.append(markup("• " + lang.t("assume.pivot.crushing" if rule == "crushing"
                                    else "assume.pivot.edge"), "bullet"))  # fmt: skip
    for i in range(1, 8):
        key = ida_words.rule_key(results, lang, f"assume.{i}")
        out.append(markup("• " + lang.t(key), "bullet"))
    out += loads_section.assumptions(results, lang)  # docs/model.md §12: none without loads
    out.append(h2(lang.t("h.appendix.references")))
    for i in range(1, 11):
        out.append(markup(lang.t(f"ref.{i}"), "reference"))
    sw = results.software
    out.append(
        markup(
            lang.t("appendix.generated", name=esc(sw.name), version=esc(sw.version),
                   date=esc(lang.date(results.created))),
            "small",
        )
    )  # fmt: skip
    return out
