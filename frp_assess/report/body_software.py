"""NTC 2018 §10.2, "Analisi e verifiche svolte con l'ausilio di codici di calcolo": the
software, its theoretical basis, field of use, validation cases, and the reasoned judgement
of the results' acceptability, which rests on a hand calculation this module prepares from
the wall's own numbers:

* weight per metre W = γ·B·H [kN/m];
* about the base edge, the moment balance W·B/2 = α₀·W·H/2 gives α₀ = B/H;
  about the crushing pivot (at x/2 inside the compressed zone x = W/(0.85·f_d), as the run
  modelled it) W·(B − x)/2 = α₀·W·H/2 gives α₀ = (B − x)/H;
* the acceleration that starts rocking a_RM = α₀·g, against the run's a_RM.

The judgement itself rests on the independent checks the run computed (results.json
``independent_checks``, :mod:`frp_assess.assess.independent_checks`), each with its value,
reference and tolerance, any of which can fail: :func:`independent_blocks`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from reportlab.lib.units import mm

from frp_assess.report import ida_words
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, grid, h1, h2, keep, key_value, markup
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.report.loads_section import t as loads_words
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult


@dataclass(frozen=True)
class HandCheck:
    """The hand calculation of the unreinforced wall: W [kN/m], x [m] (None about the
    edge), α₀ [-], a_RM by hand and by the run [g]."""

    weight: float
    depth: float | None
    f_d: float | None
    block_factor: float | None
    alpha0: float
    a_rm_run: float

    @property
    def a_rm_diff(self) -> float:
        """Relative difference of the run's a_RM from the hand one [-]."""
        return abs(self.a_rm_run - self.alpha0) / self.alpha0


def hand_check(results: Results) -> HandCheck:
    """:class:`HandCheck` of the results (module docstring)."""
    w = results.wall
    weight = w.unit_weight * w.thickness * w.height
    piv = results.urm.pivot
    ms = results.masonry_strength
    depth = f_d = factor = None
    breadth = w.thickness
    if piv is not None and piv.model_pivot == "crushing" and piv.pivot_shift > 0 and ms:
        f_d, factor = ms.f_d, ms.stress_block_factor
        depth = weight / (factor * f_d * 1000.0)  # kN/m over kN/m² [m]
        breadth = w.thickness - depth
    alpha0 = breadth / w.height
    return HandCheck(weight, depth, f_d, factor, alpha0, w.a_rm)


def section(results: Results, lang: Lang) -> list[Block]:
    n = lang.num
    sw = results.software
    out: list[Block] = [h1(lang.t("h.software"))]
    out.append(markup(lang.t("sw.lead")))
    rows = [
        [lang.t("sw.name"), esc(sw.name)],
        [lang.t("sw.version"), esc(sw.version)],
        [lang.t("sw.producer"), lang.t("sw.producer.value")],
        [lang.t("sw.licence"), lang.t("sw.licence.value")],
    ]
    out.append(key_value(rows))
    out.append(h2(lang.t("h.sw.basis")))
    for i in range(1, 5):
        key = ida_words.rule_key(results, lang, f"sw.basis.{i}")
        out.append(markup("• " + lang.t(key), "bullet"))
    out.append(h2(lang.t("h.sw.field")))
    out.append(markup(lang.t("sw.field")))
    out.append(h2(lang.t("h.sw.validation")))
    out.append(markup(lang.t("sw.validation")))
    for i in range(1, 5):
        out.append(markup("• " + lang.t(f"sw.case.{i}"), "bullet"))
    out.append(markup(lang.t("sw.validation.tests")))
    out.append(h2(lang.t("h.sw.judgement")))
    hc = hand_check(results)
    w = results.wall
    out.append(markup(lang.t("sw.hand.lead")))
    calc = [
        lang.t("sw.hand.weight", gamma=lang.gnum(w.unit_weight), B=n(w.thickness, 3),
               H=n(w.height, 3), W=n(hc.weight, 2)),
    ]  # fmt: skip
    loads = results.loads
    if loads is not None:
        # the wall's own formula does not hold with the loads: α₀ term by term is in the
        # loads' section (Circolare eq. C8.7.1.1), the value where rocking starts compared here
        hc = replace(hc, alpha0=loads.overturning.alpha0_without_ties)
        calc = [
            lang.t("sw.hand.loads", section=loads_words(lang, "h.loads"),
                   alpha0=n(loads.overturning.alpha0_without_ties, 4))
        ]  # fmt: skip
    elif hc.depth is not None and hc.f_d is not None and hc.block_factor is not None:
        calc.append(
            lang.t("sw.hand.depth", W=n(hc.weight, 2), k=lang.gnum(hc.block_factor),
                   f_d=n(hc.f_d, 3), x=n(1000 * hc.depth, 1))
        )  # fmt: skip
        calc.append(
            lang.t("sw.hand.alpha_pivot", B=n(w.thickness, 3), x=n(hc.depth, 4),
                   H=n(w.height, 3), alpha0=n(hc.alpha0, 4))
        )  # fmt: skip
    else:
        calc.append(
            lang.t("sw.hand.alpha_edge", B=n(w.thickness, 3), H=n(w.height, 3),
                   alpha0=n(hc.alpha0, 4))
        )  # fmt: skip
    calc.append(
        lang.t("sw.hand.a_rm", alpha0=n(hc.alpha0, 4), run=n(hc.a_rm_run, 4),
               diff=n(100 * hc.a_rm_diff, 2))
    )  # fmt: skip
    for line in calc:
        out.append(markup(line, "equation"))
    out.append(markup(lang.t("sw.hand.code_alpha0", alpha0=n(results.code_check.alpha0, 4))))
    out += independent_blocks(results, lang)
    if results.numerical_check is None:
        out.append(markup(lang.t("sw.numerical.none"), "small"))
    out.append(markup(lang.t("sw.engineer")))
    return out


def _deviation(value: float, absolute: bool, lang: Lang) -> str:
    return lang.num(value, 4) if absolute else f"{lang.num(100 * value, 3)} %"


def _figure(value: float, unit: str, lang: Lang) -> str:
    return lang.num(value, 5) + ("" if unit == "-" else f" {esc(unit)}")


def independent_blocks(results: Results, lang: Lang) -> list[Block]:
    """The independent checks of the run (NTC 2018 §10.2): a table of what each compares,
    the program's figure, the independent one, the deviation, the tolerance and the result,
    and the judgement that follows from them (a sentence saying they are missing in a
    results file written before them)."""
    checks = results.independent_checks
    if not checks:
        return [markup(lang.t("sw.indep.none"), "verdict_bad")]
    case = results.case(results.recommended or results.closest) or results.urm
    out: list[Block] = [markup(lang.t("sw.indep.lead"))]
    keys = ("sw.col.check", "sw.col.program", "sw.col.reference", "sw.col.deviation",
            "sw.col.tolerance", "sw.col.result")  # fmt: skip
    header: list[str] = [Markup(lang.t(k)) for k in keys]
    rows = []
    for c in checks:
        key = f"indep:{c.name}"
        what = (
            lang.t(key, case=esc(case.name), record=esc(_least_record(case)))
            if lang.has(key)
            else esc(c.detail)
        )
        rows.append([
            Markup(what),
            _figure(c.value, c.unit, lang),
            _figure(c.reference, c.unit, lang),
            _deviation(c.deviation, c.absolute, lang),
            _deviation(c.tolerance, c.absolute, lang),
            lang.t("word.pass" if c.passed else "word.fail"),
        ])  # fmt: skip
    table = grid(TableData(header, rows), [58 * mm, 22 * mm, 24 * mm, 20 * mm, 20 * mm, 26 * mm],
                 wrap=(0,))  # fmt: skip
    out[-1:] = [keep([out[-1], table])]  # the lead stays with its table
    failed = [c for c in checks if not c.passed]
    if failed:
        text = lang.t("sw.indep.bad", n=len(failed), total=len(checks),
                      names=", ".join(esc(c.name) for c in failed))  # fmt: skip
        out.append(markup(text, "verdict_bad"))
    else:
        out.append(markup(lang.t("sw.indep.ok"), "verdict_ok"))
    return out


def _least_record(case: object) -> str:
    """The least favourable record of a case (the smallest a_dyn; one that did not collapse
    counts as infinite): the record the reference integrator re-ran."""
    records = getattr(case, "records", ())
    if not records:
        return "—"
    return str(min(records, key=lambda r: float("inf") if r.a_dyn is None else r.a_dyn).record)
