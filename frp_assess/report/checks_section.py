"""The report section of the code's kinematic checks, side by side for every case.

Circolare 2019 §C8.7.1 (docs/model.md, "Displacement-based checks"): one table of every check
(linear, nonlinear static SLV and SLC, time history at SLV and at SLC, IDA mean and least
favourable record) with capacity, demand, ζ_E and verdict; one table of the capacity curves
(e*, M*, d0, d_SLV, T_SLV, demand); a line stating FC and its basis, and the floor when the
wall stands above ground.  Built from :mod:`frp_assess.results.checks` (read back from
results.json through :mod:`frp_assess.results.json_io`).

Formats as :mod:`frp_assess.report.tables`: accelerations in g with 3 decimals, ratios with 2;
displacements in mm with 1 decimal; periods in s with 3 decimals.
"""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.numbers import fmt_zeta
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, gap, grid, markup, para
from frp_assess.report.tables import DASH, TableData, fmt_acc, pass_fail
from frp_assess.results.checks import CaseChecks, KinematicChecks, TimeHistoryResult
from frp_assess.text_safety import Markup

CHECKS_HEADER = ["case", "check", "capacity", "demand", Markup("ζ<sub>E</sub>"), "verdict"]
CURVE_HEADER = [
    "case",
    "K [-]",
    "d0 [mm]",
    Markup("d<sub>SLV</sub> [mm]"),
    Markup("T<sub>SLV</sub> [s]"),
    Markup("D<sub>SLV</sub> [mm]"),
    Markup("d<sub>SLC</sub> [mm]"),
    Markup("T<sub>SLC</sub> [s]"),
    Markup("D<sub>SLC</sub> [mm]"),
]


def fmt_mm(x: float | None) -> str:
    """A displacement [m] shown in mm with 1 decimal (2 significant digits below 0.1 mm)."""
    if x is None:
        return DASH
    mm_value = 1e3 * x
    return f"{mm_value:.2g} mm" if 0.0 < mm_value < 0.1 else f"{mm_value:.1f} mm"


def fmt_g(x: float | None) -> str:
    return DASH if x is None else f"{fmt_acc(x)} g"


def _time_history_row(th: TimeHistoryResult) -> list[str]:
    """One time-history check (Circolare 2019 §C8.7.1.2.1.9) with the condition that governs
    its ζ_E = min(d_lim/mean peak, d0/largest peak): d_SLV or d_SLC [mm] against the mean
    peak of the records scaled to its limit state's a_g·S [g] (when stored), or d0 against
    the largest peak when that is the smaller ratio."""
    ls = th.limit_state
    at = "" if th.a_g is None else f" at a_g·S = {fmt_g(th.a_g)}"
    verdict = pass_fail(th.passed)
    if not th.d0_respected:
        verdict += " (d0 exceeded)"
    by_d0 = (  # (files written before the margin print d_lim/mean: the d_lim pair)
        th.margin is not None
        and th.max_peak is not None
        and th.max_peak > 0.0
        and th.mean_peak is not None
        and th.d0 / th.max_peak < th.d_limit / th.mean_peak
    )
    if by_d0:
        what, capacity, demand = "d0 vs largest peak", th.d0, th.max_peak
    else:
        what, capacity, demand = f"d_{ls} vs mean peak", th.d_limit, th.mean_peak
    return [
        "",
        f"time history {ls}{at}: {what}",
        fmt_mm(capacity),
        "fell" if demand is None else fmt_mm(demand),
        fmt_zeta(th.zeta_e),
        verdict,
    ]


def _case_rows(c: CaseChecks) -> list[list[str]]:
    rows = [
        [
            c.case,
            "linear: a0* vs demand/q",
            fmt_g(c.linear.a0_star),
            fmt_g(c.linear.demand),
            fmt_zeta(c.linear.zeta_e),
            pass_fail(c.linear.passed),
        ]
    ]
    for ls in (c.slv, c.slc):
        rows.append(
            [
                "",
                f"nonlinear static {ls.limit_state}: a_g,{ls.limit_state} vs a_g·S",
                fmt_g(ls.a_g_capacity),
                fmt_g(ls.a_g),
                fmt_zeta(ls.zeta_e),
                pass_fail(ls.passed),
            ]
        )
    # the time-history checks at SLV and at SLC (each at its own a_g·S; both decide)
    rows += [_time_history_row(th) for th in (c.time_history, c.time_history_slc) if th is not None]
    ida = c.ida
    if ida is not None:
        for label, zeta, deciding in (
            ("IDA, mean: a_dyn/FC vs a_g·S", ida.zeta_e_mean, ida.design_value == "mean"),
            ("IDA, least favourable record", ida.zeta_e_least, ida.design_value == "least"),
        ):
            rows.append(
                [
                    "",
                    label,
                    fmt_g(zeta * ida.demand),
                    fmt_g(ida.demand),
                    fmt_zeta(zeta),
                    pass_fail(zeta >= 1.0) + ("" if deciding else " (not deciding)"),
                ]
            )
    for r in rows[1:]:
        r[0] = ""
    return rows


def checks_table(checks: KinematicChecks) -> TableData:
    """Every check of every case: capacity, demand, ζ_E = capacity/demand and verdict."""
    rows: list[list[str]] = []
    for c in checks.cases:
        rows.extend(_case_rows(c))
    return TableData(list(CHECKS_HEADER), rows)


def curves_table(checks: KinematicChecks) -> TableData:
    """The displacement capacities and demands of every case (Circolare 2019 §C8.7.1.2.1.6-8)."""
    rows = [
        [
            c.case,
            f"{c.capacity.stiffness:.3g}",
            fmt_mm(c.capacity.d0).removesuffix(" mm"),
            fmt_mm(c.slv.d_limit).removesuffix(" mm"),
            f"{c.slv.period:.3f}",
            fmt_mm(c.slv.demand).removesuffix(" mm"),
            fmt_mm(c.slc.d_limit).removesuffix(" mm"),
            f"{c.slc.period:.3f}",
            fmt_mm(c.slc.demand).removesuffix(" mm"),
        ]
        for c in checks.cases
    ]
    return TableData(list(CURVE_HEADER), rows)


def basis_text(checks: KinematicChecks) -> str:
    """Where the demand comes from (ground or floor) and the design intensity."""
    if checks.floor is None:
        where = (
            "The wall stands at ground level: the demand is the elastic ground spectrum "
            f"(a_g·S = {fmt_acc(checks.a_g)} g)."
        )
    else:
        f = checks.floor
        where = (
            f"The wall's base is at Z/H = {f.z_over_h:.2f} of a {f.storeys}-storey building "
            f"(T1 = {f.period:.3f} s, ξ1 = {100 * f.damping:.0f} %): the demand of every check "
            "is the floor spectrum of Circolare 2019 §C7.2.3 (first mode; eq. C8.7.1.12 for "
            f"displacements), whose peak acceleration is {f.floor_ratio:.2f} × a_g·S "
            f"(a_g·S = {fmt_acc(checks.a_g)} g)."
        )
    return where


def checks_section(checks: KinematicChecks) -> list[Block]:
    """The flowables of the section: the side-by-side table, the capacity curves, FC and the
    basis of the demand (no heading: the report numbers its sections)."""
    ok = all(c.passed for c in checks.cases)
    out: list[Block] = [
        para(
            "Circolare 2019 §C8.7.1: the linear check (§C8.7.1.2.1.7), the nonlinear static "
            "checks at SLV and SLC (§C8.7.1.2.1.6-8, bars entering through the internal work "
            "of elastic elements, d0 the bare wall's), the time-history checks at SLV and SLC, "
            "each with the records scaled to its own a_g·S (§C8.7.1.2.1.9), and the IDA. "
            "ζ_E = capacity/demand; the time-history ζ_E = min(d_lim/mean peak, d0/largest "
            "peak) is a ratio of displacements (≥ 1 exactly when both of its conditions hold), "
            "the others of ground accelerations."
        ),
        para(basis_text(checks), "small"),
        *([para(checks.intensity_basis, "small")] if checks.intensity_basis else []),
        markup(f"<b>Confidence factor.</b> {esc(checks.fc_basis)}", "small"),
        gap(4),
        grid(
            checks_table(checks),
            [32 * mm, 54 * mm, 20 * mm, 20 * mm, 12 * mm, 36 * mm],
            wrap=(0, 1, 5),
            numeric_from=2,
        ),
        gap(6),
        grid(curves_table(checks), [34 * mm] + [17 * mm] * 8, wrap=(0,), small=True),
        para(
            "K: bar term of Eq. 10; d0 = d_C(α_x), the centroid's displacement where the bare "
            "wall's restoring moment vanishes (B/2 about the edge, about (B − x_W)/2 with the "
            "base reaction at x_W/2); d_SLV = min(0.40·d0, the displacement where a bar "
            "rupture drops the capacity by more than 50 %), d_SLC = 0.60·d0; T = 1.68π√(d/a) "
            "(SLV), 1.56π√(d/a) (SLC); D: displacement demand at 8 % (SLV) and 10 % (SLC) "
            "damping.",
            "caption",
        ),
    ]
    verdict = (
        "Every code check of every case passes."
        if ok
        else "Some code checks fail: see the verdict column."
    )
    out.append(markup(esc(verdict), "verdict_ok" if ok else "verdict_bad"))
    return out
