"""NTC 2018 §10.2, "Analisi e verifiche svolte con l'ausilio di codici di calcolo": the
software, its theoretical basis, field of use, validation cases, and the reasoned judgement
of the results' acceptability, which rests on a hand calculation this module prepares from
the wall's own numbers:

* weight per metre W = γ·B·H [kN/m];
* about the base edge, the moment balance W·B/2 = α₀·W·H/2 gives α₀ = B/H;
  about the crushing pivot (at x/2 inside the compressed zone x = W/(0.85·f_d), as the run
  modelled it) W·(B − x)/2 = α₀·W·H/2 gives α₀ = (B − x)/H;
* the acceleration that starts rocking a_RM = α₀·g, against the run's a_RM;
* the static activation multiplier of each record C₀ = a_RM/PGA, against the first multiplier
  of the record's IDA (the IDA starts at C₀, docs of the method).
"""

from __future__ import annotations

from dataclasses import dataclass

from reportlab.lib.units import mm

from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, grid, h1, h2, key_value, markup
from frp_assess.report.lang import Lang
from frp_assess.report.tables import TableData
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult

#: relative difference [-] between the hand calculation and the run accepted without comment
AGREEMENT = 0.01


@dataclass(frozen=True)
class HandCheck:
    """The hand calculation of the unreinforced wall: W [kN/m], x [m] (None about the
    edge), α₀ [-], a_RM by hand and by the run [g], and per record (name, PGA at the wall's
    base [g], C₀ by hand [-], first IDA multiplier [-] or None)."""

    weight: float
    depth: float | None
    f_d: float | None
    block_factor: float | None
    alpha0: float
    a_rm_run: float
    records: tuple[tuple[str, float, float, float | None], ...]

    @property
    def a_rm_diff(self) -> float:
        """Relative difference of the run's a_RM from the hand one [-]."""
        return abs(self.a_rm_run - self.alpha0) / self.alpha0

    @property
    def c0_diff(self) -> float | None:
        """Largest relative difference of an IDA's first multiplier from C₀ [-]."""
        diffs = [abs(c - h) / h for _, _, h, c in self.records if c is not None and h > 0]
        return max(diffs) if diffs else None


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
    rows = []
    for r in results.urm.records:
        pga = r.floor_pga if r.floor_pga is not None else r.pga
        first = min((p[0] for p in r.curve), default=None)
        rows.append((r.record, pga, alpha0 / pga if pga > 0 else float("nan"), first))
    return HandCheck(weight, depth, f_d, factor, alpha0, w.a_rm, tuple(rows))


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
        out.append(markup("• " + lang.t(f"sw.basis.{i}"), "bullet"))
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
    if hc.depth is not None and hc.f_d is not None and hc.block_factor is not None:
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
    header: list[str] = [Markup(lang.t(k)) for k in ("col.record", "sw.col.pga", "sw.col.c0_hand",
                                         "sw.col.c0_ida", "sw.col.diff")]  # fmt: skip
    body = []
    for name, pga, c0, first in hc.records:
        diff = "—" if first is None or c0 <= 0 else n(100 * abs(first - c0) / c0, 2)
        body.append([name, n(pga, 3), n(c0, 4), n(first, 4) if first is not None else "—", diff])
    out.append(
        grid(TableData(header, body), [50 * mm, 30 * mm, 30 * mm, 30 * mm, 30 * mm], wrap=(0,))
    )
    worst = hc.c0_diff
    ok = hc.a_rm_diff <= AGREEMENT and (worst is None or worst <= AGREEMENT)
    out.append(
        markup(
            lang.t(
                "sw.judgement.ok" if ok else "sw.judgement.bad",
                limit=n(100 * AGREEMENT, 0),
                worst=n(100 * (worst or 0.0), 2),
            ),
            "verdict_ok" if ok else "verdict_bad",
        )
    )
    nc = results.numerical_check
    if nc is not None:
        if nc.fate_changed or nc.max_change is None:
            text = lang.t("sw.numerical.fate", case=esc(nc.case), record=esc(nc.record),
                          moved=nc.changed_pairs, pairs=nc.pairs)  # fmt: skip
        else:
            text = lang.t("sw.numerical.ok", tol=f"{nc.tolerance:g}",
                          check=f"{nc.check_tolerance:g}", change=n(100 * nc.max_change, 2),
                          moved=nc.changed_pairs, pairs=nc.pairs)  # fmt: skip
        out.append(markup(text))
    else:
        out.append(markup(lang.t("sw.numerical.none"), "small"))
    out.append(markup(lang.t("sw.engineer")))
    return out
