"""The one source of every verdict word of the report: the decision of results.json (each
case's ``passes``, ``governing_check``, ``governing_margin``; ``recommended``, ``closest``,
``robustness``) in the report's language, for the body and the annex alike.  The console,
results.csv and the TUI read the same fields through :mod:`frp_assess.results.verdict_words`
(one word in English); neither recomputes the decision.

A case *passes* when every deciding check passes (frp_assess/assess/decision.py); the IDA's
capacity/demand against the target is one of those checks, never the verdict by itself.
Probabilities of collapse are stated at FC·a_g·S, the demand the IDA check divides the
capacity by (and the console's), :func:`collapse_probability`.
"""

from __future__ import annotations

import math
import re

from frp_assess.report.flow import esc
from frp_assess.report.ida_words import collapse_window_line, rule_key
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult
#: the static kinematic checks of Circolare 2019 §C8.7.1 (supporting, never deciding)
STATIC_CHECKS = ("linear", "slv", "slc")


def passes(case: CaseResult) -> bool:
    """The decision on ``case``: every deciding check passes (files written before the
    decision fields: the IDA's target)."""
    return bool(case.meets_target) if case.passes is None else bool(case.passes)


def check_words(name: str, lang: Lang) -> str:
    """A deciding check of the results in the report's language."""
    key = f"check:{name}"
    return lang.t(key) if lang.has(key) else esc(name)


def cell(case: CaseResult, lang: Lang) -> str:
    """The verdict in a table cell."""
    return lang.t("verdict.cell.pass" if passes(case) else "verdict.cell.fail")


def margin_text(case: CaseResult, lang: Lang) -> str:
    """The governing margin with its comparison to 1: ``1.01 ≥ 1``, ``0.00 < 1``."""
    m = case.governing_margin
    if m is None:
        return lang.t("verdict.unbounded")
    shown = ("≥ " if case.governing_lower_bound else "") + lang.num(float(m), 2)
    # a margin that rounds to 1.00 is compared as it is, not as it is printed
    return f"{shown} {'≥' if m >= 1.0 else '<'} 1"


def governing(case: CaseResult, lang: Lang) -> str:
    """``governing check: <check>, margin <m> ≥/< 1`` (a fallen record said so)."""
    check = case.governing_check
    if check is None:
        return lang.t("verdict.ida_only", cd=lang.num(case.capacity_demand, 2))
    # a time-history margin is 0 only when a record made the wall fall (decision.py)
    fell = case.governing_margin == 0.0 and str(check).startswith("time history")
    text = lang.t("verdict.governing", check=check_words(str(check), lang),
                  margin=margin_text(case, lang))  # fmt: skip
    return text + (lang.t("verdict.fell") if fell else "")


def verdict_sentence(case: CaseResult, lang: Lang) -> str:
    """``passes every deciding check (governing …)`` or ``does NOT pass …``."""
    key = "verdict.passes" if passes(case) else "verdict.fails"
    return lang.t(key, governing=governing(case, lang))


def category_sentence(results: Results, lang: Lang) -> str | None:
    """How the options were judged: the category of the intervention (results.json
    ``intervention``, NTC 2018 §8.4) in one sentence; None for a file written before it."""
    iv = results.intervention
    if iv is None:
        return None
    name = lang.t(f"category.name.{iv.category}")
    return lang.t("decision.category", category=name, clause=esc(iv.clause))


def option_target(results: Results, lang: Lang) -> str:
    """What an option's IDA capacity/demand must reach, in words: the target (an upgrade, or
    a file written before the category), else the ζ_E the category asks (NTC 2018 §8.4)."""
    iv = results.intervention
    if iv is None or iv.category == "upgrade":
        return lang.gnum(results.model.target)
    return lang.t("category.ida_target", category=lang.t(f"category.name.{iv.category}"))


def failed_static(results: Results, case: CaseResult, lang: Lang) -> list[str]:
    """The static kinematic checks ``case`` fails, each as ``<check> ζ_E = <z>``."""
    kc = results.kinematic_checks
    if kc is None:
        return []
    k = next((x for x in kc.cases if x.case == case.name), None)
    if k is None:
        return []
    out = []
    for attr in STATIC_CHECKS:
        c = getattr(k, attr)
        if c.zeta_e is not None and not c.passed:
            out.append(f"{lang.t('check.' + attr)} ζ<sub>E</sub> = {lang.num(c.zeta_e, 2)}")
    return out


def rests_on(results: Results, case: CaseResult, lang: Lang) -> str | None:
    """Where a passing verdict stands beside failing static checks: on which checks it rests
    and why the static ones do not govern; None when there is nothing to explain."""
    if not passes(case):
        return None
    static = failed_static(results, case, lang)
    if not static:
        return None
    return lang.t("verdict.rests_on", static="; ".join(static))


def collapse_probability(results: Results, case: CaseResult) -> tuple[float, float] | None:
    """(FC·a_g·S [g], P(collapse) there [-]) from the case's lognormal fragility fit
    (median, β): Φ(ln(x/median)/β); None without a fit."""
    fr = case.scatter.fragility
    if fr is None or not (fr.median > 0 and fr.beta > 0):
        return None
    x = case.fc * results.demand.pga
    z = math.log(x / fr.median) / fr.beta
    return x, 0.5 * math.erfc(-z / math.sqrt(2.0))


def probability_text(p: float, lang: Lang) -> str:
    """A probability as a percentage, ``< 0.1 %`` below a thousandth."""
    if p < 1e-3:
        return f"< {lang.num(0.1, 1)} %"
    return f"{lang.num(100 * p, 1)} %"


def robustness_lines(results: Results, lang: Lang) -> list[str]:
    """The robustness statement (results.json ``robustness``): P(collapse) of the assessed
    case at FC·a_g·S, and, when the verdict is not robust, every record whose leaving out
    changes it and every model convention under which the case fails."""
    rob = results.robustness
    if rob is None:
        return []
    case = results.case(rob.case)
    out: list[str] = [line for line in [collapse_window_line(results, lang)] if line]
    if rob.p_collapse is not None:
        out.append(lang.t(rule_key(results, lang, "robust.p_collapse"), case=esc(rob.case),
                          x=lang.num(rob.design_intensity, 3),
                          p=probability_text(rob.p_collapse, lang)))  # fmt: skip
    if rob.survives:  # a wall that passes as it is: the case is margin, not a recommendation
        key = "robust.survives" if results.retrofit_required else "robust.survives_optional"
        out.append(lang.t(key, case=esc(rob.case)))
        return out
    if case is not None and not passes(case):  # nothing passes: does that verdict hold?
        flips = [lang.t("robust.loo", record=esc(lo.record), other=esc(lo.recommended))
                 for lo in rob.leave_one_out if lo.recommended]  # fmt: skip
        flips += [lang.t("robust.convention_passes", variant=variant_words(c.variant, lang),
                         case=esc(rob.case))
                  for c in rob.conventions if c.passes]  # fmt: skip
        key = "robust.not_robust_closest" if flips else "robust.none_passes"
        out.append(lang.t(key, case=esc(rob.case), reasons="; ".join(flips)))
        return out
    reasons = []
    for lo in rob.leave_one_out:
        if not lo.survives:
            other = esc(lo.recommended) if lo.recommended else lang.t("robust.nothing")
            reasons.append(lang.t("robust.loo", record=esc(lo.record), other=other))
    for conv in rob.conventions:
        if not conv.passes:
            margin = "—" if conv.governing_margin is None else lang.num(conv.governing_margin, 2)
            text = lang.t("robust.convention", variant=variant_words(conv.variant, lang),
                          check=check_words(conv.governing_check, lang), margin=margin)  # fmt: skip
            if conv.takes_over:
                text += lang.t("robust.takes_over", option=esc(conv.takes_over))
            reasons.append(text)
    out.append(lang.t("robust.not_robust", case=esc(rob.case), reasons="; ".join(reasons)))
    return out


def convention_cells(results: Results, variant: str, lang: Lang) -> list[str]:
    """The deciding checks' verdict and governing margin of the assessed case under one
    model convention of the sensitivity table (results.json ``robustness.conventions``);
    dashes when the robustness check did not run on the same case."""
    rob = results.robustness
    sens = results.sensitivity
    if rob is None or sens is None or rob.case != sens.case:
        return ["—", "—"]
    conv = next((c for c in rob.conventions if c.variant == variant), None)
    if conv is None:
        return ["—", "—"]
    margin = "—" if conv.governing_margin is None else lang.num(conv.governing_margin, 2)
    return [lang.t("verdict.cell.pass" if conv.passes else "verdict.cell.fail"), margin]


_CONVENTION = re.compile(r"^(restitution|collapse|rupture): ([a-z-]+)$")
_STRAIN = re.compile(r"^strain factor c = ([0-9.]+)$")
_MODULUS = re.compile(r"^E ([+-][0-9.]+)% \(([0-9.]+) GPa\)$")
_HUNT_STEP = re.compile(r"^IDA step ratio s = ([0-9.]+)$")
_SPREAD = re.compile(r"^numerical spread: .*\(offset ([0-9.]+)\)$")


def variant_words(variant: str, lang: Lang) -> str:
    """A model convention of the sensitivity table in the report's language: the run's label
    (``"as assessed"``, ``"collapse: end-of-record"``, ``"E -10% (41.4 GPa)"`` ...) read back
    into its parts; a label of another form is shown as written, numbers re-formatted."""
    if variant == "as assessed":
        return lang.t("sens.as_assessed")
    m = _CONVENTION.match(variant)
    if m and lang.has(f"sens.value.{m.group(2)}"):
        return lang.t(f"sens.{m.group(1)}", value=lang.t(f"sens.value.{m.group(2)}"))
    m = _STRAIN.match(variant)
    if m:
        return lang.t("sens.strain", c=lang.gnum(float(m.group(1))))
    m = _MODULUS.match(variant)
    if m:
        return lang.t(
            "sens.modulus", change=lang.numbers_in(m.group(1)), e=lang.gnum(float(m.group(2)))
        )
    m = _HUNT_STEP.match(variant)
    if m:
        return lang.t("sens.hunt_step", s=lang.gnum(float(m.group(1))))
    m = _SPREAD.match(variant)
    if m:
        return lang.t("sens.numerical_spread", offset=lang.gnum(float(m.group(1))))
    return lang.numbers_in(variant)
