"""The annex's section of the code's kinematic checks, side by side for every case, in the
report's language.

Circolare 2019 §C8.7.1 (docs/model.md, "Displacement-based checks"): one table of every check
(linear, nonlinear static SLV and SLC, time history at SLV and at SLC, IDA mean and least
favourable record) with capacity, demand, ζ_E and verdict; one table of the capacity curves
(e*, M*, d0, d_SLV, T_SLV, demand); a line stating FC and its basis, and the floor when the
wall stands above ground.  Built from :mod:`frp_assess.results.checks` (read back from
results.json through :mod:`frp_assess.results.json_io`).

Formats: accelerations in g with 3 decimals, ratios with 2; displacements in mm with 1
decimal; periods in s with 3 decimals.
"""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.numbers import fmt_zeta
from frp_assess.report.annex_design_tables import case_label
from frp_assess.report.annex_input_tables import pass_fail
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, gap, grid, markup
from frp_assess.report.formats import DASH, TableData, run_words
from frp_assess.report.lang import Lang
from frp_assess.results.checks import CaseChecks, KinematicChecks, TimeHistoryResult
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult


def fmt_mm(x: float | None, lang: Lang) -> str:
    """A displacement [m] shown in mm with 1 decimal (2 significant digits below 0.1 mm)."""
    if x is None:
        return DASH
    mm_value = 1e3 * x
    text = f"{mm_value:.2g}" if 0.0 < mm_value < 0.1 else f"{mm_value:.1f}"
    return lang.numbers_in(text)


def fmt_g(x: float | None, lang: Lang) -> str:
    return DASH if x is None else f"{lang.num(x, 3)} g"


def _mm(x: float | None, lang: Lang) -> str:
    return DASH if x is None else f"{fmt_mm(x, lang)} mm"


def _time_history_row(th: TimeHistoryResult, lang: Lang) -> list[str]:
    """One time-history check (Circolare 2019 §C8.7.1.2.1.9) with the condition that governs
    its ζ_E = min(d_lim/mean peak, d0/largest peak): d_SLV or d_SLC [mm] against the mean
    peak of the records scaled to its limit state's a_g·S [g] (when stored), or d0 against
    the largest peak when that is the smaller ratio."""
    ls = th.limit_state
    at = "" if th.a_g is None else lang.t("ax.chk.at", ags=fmt_g(th.a_g, lang))
    verdict = pass_fail(th.passed, lang)
    if not th.d0_respected:
        verdict += lang.t("ax.chk.d0_exceeded")
    by_d0 = (  # (files written before the margin print d_lim/mean: the d_lim pair)
        th.margin is not None
        and th.max_peak is not None
        and th.max_peak > 0.0
        and th.mean_peak is not None
        and th.d0 / th.max_peak < th.d_limit / th.mean_peak
    )
    if by_d0:
        what, capacity, demand = lang.t("ax.chk.by_d0"), th.d0, th.max_peak
    else:
        what, capacity, demand = lang.t("ax.chk.by_dlim", ls=ls), th.d_limit, th.mean_peak
    return [
        "",
        lang.t("ax.chk.th", ls=ls, at=at, what=what),
        _mm(capacity, lang),
        lang.t("ax.chk.fell") if demand is None else _mm(demand, lang),
        lang.numbers_in(fmt_zeta(th.zeta_e)),
        verdict,
    ]


def _case_rows(c: CaseChecks, label: str, lang: Lang) -> list[list[str]]:
    zeta = lambda z: lang.numbers_in(fmt_zeta(z))  # noqa: E731
    rows = [[label, lang.t("ax.chk.linear"), fmt_g(c.linear.a0_star, lang),
             fmt_g(c.linear.demand, lang), zeta(c.linear.zeta_e),
             pass_fail(c.linear.passed, lang)]]  # fmt: skip
    for ls in (c.slv, c.slc):
        rows.append(["", lang.t("ax.chk.static", ls=ls.limit_state),
                     fmt_g(ls.a_g_capacity, lang), fmt_g(ls.a_g, lang), zeta(ls.zeta_e),
                     pass_fail(ls.passed, lang)])  # fmt: skip
    # the time-history checks at SLV and at SLC (each at its own a_g·S; both decide)
    rows += [
        _time_history_row(th, lang) for th in (c.time_history, c.time_history_slc) if th is not None
    ]
    ida = c.ida
    if ida is not None:
        for key, z, deciding in (
            ("ax.chk.ida.mean", ida.zeta_e_mean, ida.design_value == "mean"),
            ("ax.chk.ida.least", ida.zeta_e_least, ida.design_value == "least"),
        ):
            verdict = pass_fail(z >= 1.0, lang)
            verdict += "" if deciding else lang.t("ax.chk.not_deciding")
            rows.append(["", lang.t(key), fmt_g(z * ida.demand, lang), fmt_g(ida.demand, lang),
                         zeta(z), verdict])  # fmt: skip
    return rows


def _labels(results: Results, lang: Lang) -> dict[str, str]:
    return {c.name: case_label(c, lang) for c in results.cases}


def checks_table(results: Results, lang: Lang) -> TableData | None:
    """Every check of every case: capacity, demand, ζ_E = capacity/demand and verdict; None
    without the checks."""
    kc = results.kinematic_checks
    if kc is None:
        return None
    labels = _labels(results, lang)
    rows: list[list[str]] = []
    for c in kc.cases:
        rows.extend(_case_rows(c, labels.get(c.case, c.case), lang))
    header = [lang.t("annex.col.option"), lang.t("ax.col.check"), lang.t("ax.col.capacity"),
              lang.t("ax.col.demand"), Markup("ζ<sub>E</sub>"),
              lang.t("ax.code.verdict")]  # fmt: skip
    return TableData(header, rows)


def curves_table(results: Results, lang: Lang) -> TableData | None:
    """The displacement capacities and demands of every case (Circolare 2019 §C8.7.1.2.1.6-8)."""
    kc = results.kinematic_checks
    if kc is None:
        return None
    labels = _labels(results, lang)
    header = [lang.t("annex.col.option"), "K [-]", "d0 [mm]", Markup("d<sub>SLV</sub> [mm]"),
              Markup("T<sub>SLV</sub> [s]"), Markup("D<sub>SLV</sub> [mm]"),
              Markup("d<sub>SLC</sub> [mm]"), Markup("T<sub>SLC</sub> [s]"),
              Markup("D<sub>SLC</sub> [mm]")]  # fmt: skip
    rows = [
        [labels.get(c.case, c.case), lang.numbers_in(f"{c.capacity.stiffness:.3g}"),
         fmt_mm(c.capacity.d0, lang), fmt_mm(c.slv.d_limit, lang), lang.num(c.slv.period, 3),
         fmt_mm(c.slv.demand, lang), fmt_mm(c.slc.d_limit, lang), lang.num(c.slc.period, 3),
         fmt_mm(c.slc.demand, lang)]
        for c in kc.cases
    ]  # fmt: skip
    return TableData(header, rows)


def basis_text(checks: KinematicChecks, lang: Lang) -> str:
    """Where the demand comes from (ground or floor) and the design intensity."""
    ags = lang.num(checks.a_g, 3)
    f = checks.floor
    if f is None:
        return lang.t("ax.chk.ground", ags=ags)
    return lang.t("ax.chk.floor", z=lang.num(f.z_over_h, 2), n=f.storeys,
                  t1=lang.num(f.period, 3), xi=lang.num(100 * f.damping, 0),
                  ratio=lang.num(f.floor_ratio, 2), ags=ags)  # fmt: skip


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


def checks_section(results: Results, lang: Lang) -> list[Block]:
    """The blocks of the section: the side-by-side table, the capacity curves, FC and the
    basis of the demand (no heading: the annex numbers its sections); [] without checks."""
    kc = results.kinematic_checks
    table, curves = checks_table(results, lang), curves_table(results, lang)
    if kc is None or table is None or curves is None:
        return []
    ok = all(c.passed for c in kc.cases)
    states = intensities_text(results, lang)
    fc = run_words(kc.fc_basis, lang)
    out: list[Block] = [
        markup(lang.t("ax.chk.lead")),
        markup(basis_text(kc, lang), "small"),
        *([markup(states, "small")] if states else []),
        markup(
            lang.t("ax.chk.fc", basis=esc(fc) if fc else f"FC = {lang.gnum(kc.fc)}."), "small"
        ),  # fmt: skip
        gap(4),
        grid(
            table,
            [32 * mm, 54 * mm, 20 * mm, 20 * mm, 12 * mm, 36 * mm],
            wrap=(0, 1, 5),
            numeric_from=2,
        ),  # fmt: skip
        gap(6),
        grid(curves, [34 * mm] + [17 * mm] * 8, wrap=(0,), small=True),
        markup(lang.t("ax.chk.curves.caption"), "caption"),
    ]
    key = "ax.chk.all_pass" if ok else "ax.chk.some_fail"
    out.append(markup(lang.t(key), "verdict_ok" if ok else "verdict_bad"))
    return out
