"""The Results tab's views of issues 15-16: fragility curves, bars as built, the pivot check,
the code's kinematic checks and the sensitivity table, built from the typed results.

Pure functions from :class:`~frp_assess.results.model.AssessmentResult` to Rich tables and
plot series (the widgets are in :mod:`frp_assess.tui.results_pane`).  Fields that a run may leave
None (``as_built``, ``pivot``, ``kinematic_checks``, ``floor_spectra``): a view with nothing
to show says so.
"""

from __future__ import annotations

from typing import Any

from rich import box
from rich.table import Table
from rich.text import Text

from frp_assess.numbers import (
    fmt_against,
    fmt_zeta,
    recommendation_label,
    recommendation_text,
)
from frp_assess.results.checks import TimeHistoryResult
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.verdict_words import category_line
from frp_assess.tui.core.fragility import lognormal_cdf, pga_axis
from frp_assess.tui.core.text import printable
from frp_assess.tui.literal import literal
from frp_assess.tui.plots import Rule, Series

#: line styles of the cases in the fragility plot (repeated past the last)
CASE_STYLES = ("green", "yellow", "magenta", "cyan", "bright_blue", "red", "bright_green")
#: with more curves than this the plot has no legend (the table below names the styles)
LEGEND_MAX = 8


def case_style(index: int) -> str:
    """The style of case ``index`` (0: the unreinforced wall, white)."""
    return "white" if index == 0 else CASE_STYLES[(index - 1) % len(CASE_STYLES)]


def _table(title: str) -> Table:
    return Table(
        title=Text(title, "bold"),
        title_justify="left",
        box=box.SIMPLE_HEAD,
        expand=True,
        padding=(0, 1),
    )


def _ok(passed: bool | None, yes: str = "OK", no: str = "FAILS") -> Text:
    if passed is None:
        return Text("—", "dim")
    return Text(yes, "green") if passed else Text(no, "bold red")


# ----------------------------------------------------------------------------- fragility
def fragility_plot(r: AssessmentResult) -> tuple[list[Series], dict[str, Any]]:
    """P(collapse) against PGA of every case with a lognormal fit, and the plot options
    (the decision's demand FC·a_g·S as a vertical rule).  No series when no case has a fit."""
    fitted = [
        (i, c, c.scatter.fragility)
        for i, c in enumerate(r.cases)
        if c.scatter is not None and c.scatter.fragility is not None
    ]
    demand = decision_demand(r)
    if not fitted:
        return [], {}
    xs = pga_axis([f.median for _, _, f in fitted], [f.beta for _, _, f in fitted], demand)
    series = [
        Series(
            xs,
            [lognormal_cdf(x, f.median, f.beta) for x in xs],
            style=case_style(i),
            label=c.name,
        )
        for i, c, f in fitted
    ]
    options = {
        "x_range": (0.0, xs[-1]),
        "y_range": (0.0, 1.0),
        "rules": [Rule(demand, "x", "red", f"demand FC·a_g·S = {demand:.3f} g")],
        "x_label": "PGA [g]",
        "y_label": "P(collapse)",
        "legend": len(series) <= LEGEND_MAX,
    }
    return series, options


def decision_demand(r: AssessmentResult) -> float:
    """FC·a_g·S [g]: the demand of the decision's checks (the knowledge level's FC of the
    unreinforced wall, the same for every case), at which P(collapse) is stated."""
    return r.urm.fc * r.demand.pga


def fragility_table(r: AssessmentResult) -> Table:
    """Every case's lognormal fit: median, β, method and P(collapse) at the decision's
    demand FC·a_g·S (from the fit's median and β: results.json's ``p_collapse_at_demand``
    is at a_g·S)."""
    demand = decision_demand(r)
    t = _table(f"Lognormal fragility: P(collapse) at FC·a_g·S = {demand:.3f} g")
    t.add_column(Text("case"), ratio=3)
    for heading in ("median [g]", "β"):
        t.add_column(Text(heading), justify="right", no_wrap=True)
    t.add_column(Text("fit"), no_wrap=True)
    t.add_column(Text("P(collapse) at FC·a_g·S"), justify="right", no_wrap=True)
    for i, c in enumerate(r.cases):
        fr = c.scatter.fragility if c.scatter is not None else None
        label = literal(f"━ {c.name}", case_style(i))
        if fr is None:
            t.add_row(label, "—", "—", Text("no fit (< 2 distinct collapses)", "dim"), "—")
            continue
        p = lognormal_cdf(demand, fr.median, fr.beta)
        t.add_row(
            label,
            f"{fr.median:.4f}",
            f"{fr.beta:.2f}",
            literal(fr.method),
            Text("< 0.1 %" if p < 1e-3 else f"{p:.1%}", "yellow" if p >= 0.1 else ""),
        )
    return t


def floor_spectra_plot(r: AssessmentResult) -> tuple[list[Series], dict[str, Any]]:
    """5 % spectra at the wall's base (``floor_spectra``, a wall above ground): the mean of
    the records' floor motions, the code's floor spectrum and the ground target, in g.  No
    series when the results have none."""
    fs = r.floor_spectra
    if fs is None or not fs.periods:
        return [], {}
    series = [
        Series(fs.periods, fs.code, style="white", label="code floor spectrum"),
        Series(fs.periods, fs.mean, style="cyan", label="mean of the records' floor motions"),
        Series(fs.periods, fs.ground, style="grey50", label="ground target"),
    ]
    top = max([*fs.code, *fs.mean, *fs.ground, 0.0])
    return series, {
        "x_range": (0.0, max(fs.periods)),
        "y_range": (0.0, 1.1 * top if top > 0 else 1.0),
        "x_label": "T [s]",
        "y_label": "Sa at the wall's base [g]",
    }


# ------------------------------------------------------------------------- bars and pivot
def bars_text(built: Any) -> str:
    """``9 × Ø16`` (centred) or ``2 × 9 × Ø16`` (external: one line per face)."""
    d = f"Ø{built.diameter:g}"
    if built.lines > 1:
        return f"{built.lines} × {built.bars_per_line} × {d}"
    return f"{built.bars_per_line} × {d}"


def design_bars(built: Any) -> Text:
    """A design-mode answer's bars: ``2 × 9 × Ø16 at 0.28 m, ρ 1.206 ‰``."""
    face = " /face" if built.lines > 1 else ""
    return Text(
        f"{bars_text(built)} at {built.spacing:.2f} m{face}, ρ {built.ratio_installed:.3f} ‰"
    )


def anchorage_text(built: Any) -> Text:
    """OK / FAILS of the pull-out cone, with the bond length needed at each end."""
    a = built.anchorage
    out = _ok(a.cone_ok) if a.cone_ok is not None else Text("not checked", "dim")
    if a.length_required is not None:
        out.append(f", bond {a.length_required * 1e3:.0f} mm", "")
    return out


def bars_table(r: AssessmentResult) -> Table | Text:
    """Per option: the bars as built (count × diameter, spacing, ratio installed vs asked,
    bar force and anchorage)."""
    rows = [(c, c.as_built) for c in r.options]
    if not any(b is not None for _, b in rows):
        return Text("No bar layout in these results.", "dim")
    t = _table("Bars as built (whole bars over the wall length)")
    t.caption = (
        "s: spacing of the bar axes; ρ: ratio installed by whole bars / asked; F: force in one "
        "bar at the model's rupture strain; anchorage: the pull-out cone, and the bond length "
        "needed at each end"
    )
    t.caption_justify = "left"
    t.add_column(Text("option"), ratio=1)
    t.add_column(Text("bars"), no_wrap=True)
    t.add_column(Text("s [m]"), justify="right", no_wrap=True)
    t.add_column(Text("ρ inst./asked ‰"), justify="right", no_wrap=True)
    t.add_column(Text("F [kN]"), justify="right", no_wrap=True)
    t.add_column(Text("anchorage"), no_wrap=True)
    for c, b in rows:
        if b is None:
            t.add_row(literal(c.name), Text("cannot be built in whole bars", "yellow"))
            continue
        spacing = f"{b.spacing:.2f}" + (" /face" if b.lines > 1 else "")
        asked = b.ratio_asked if c.ratio_asked is None else c.ratio_asked
        t.add_row(
            literal(c.name),
            bars_text(b),
            spacing,
            f"{b.ratio_installed:.3f} / {asked:g}",
            f"{b.anchorage.design_force:.1f}",
            anchorage_text(b),
        )
    return t


def pivot_table(r: AssessmentResult) -> Table | Text:
    """Per case: the compressed zone at the pivot (x/B), the pivot used, dropped and why."""
    rows = [(c, c.pivot) for c in r.cases]
    if not any(p is not None for _, p in rows):
        return Text("No pivot check in these results.", "dim")
    t = _table("Masonry at the pivot: compressed zone x of 0.85·f_d")
    t.add_column(Text("case"), ratio=2)
    t.add_column(Text("N [kN/m]"), justify="right", no_wrap=True)
    t.add_column(Text("x/B"), justify="right", no_wrap=True)
    t.add_column(Text("pivot"), no_wrap=True)
    t.add_column(Text("verdict"), no_wrap=True)
    t.add_column(Text("why"), ratio=4)
    for c, p in rows:
        if p is None:
            continue
        t.add_row(
            literal(c.name),
            f"{p.force:.0f}",
            Text(f"{p.depth_ratio:.3f}", "red" if p.dropped else ""),
            literal(p.model_pivot),
            Text("dropped", "bold red") if p.dropped else Text("holds", "green"),
            literal(pivot_reason(c.name, p.reason), "dim"),
        )
    return t


def pivot_reason(case: str, reason: str) -> str:
    """The pivot check's line without the case's name in front (the row names it)."""
    head = f"{case}: "
    return reason[len(head) :] if reason.startswith(head) else reason


def case_details(c: CaseResult) -> Text:
    """Lines for the case summary: its bars as built and its pivot check (empty if none)."""
    out = Text()
    b = c.as_built
    if b is not None:
        asked = b.ratio_asked if c.ratio_asked is None else c.ratio_asked
        out.append(
            f"\nbars: {bars_text(b)} {b.material} at {b.spacing:.2f} m"
            + (" per face" if b.lines > 1 else "")
            + f", ρ installed {b.ratio_installed:.3f} ‰ (asked {asked:g} ‰); anchorage "
        )
        out.append_text(anchorage_text(b))
    p = c.pivot
    if p is not None:
        out.append(f"\npivot: x/B = {p.depth_ratio:.3f} ({p.model_pivot}) ")
        out.append("DROPPED" if p.dropped else "holds", "bold red" if p.dropped else "green")
        out.append_text(literal(f": {pivot_reason(c.name, p.reason)}", "dim"))
    return out


# --------------------------------------------------------------------- checks, sensitivity
def _zeta(value: float | None, passed: bool) -> Text:
    return (
        Text("—", "dim") if value is None else Text(fmt_zeta(value), "green" if passed else "red")
    )


def kinematic_table(r: AssessmentResult) -> Table | Text:
    """The code's checks of every case side by side (Circolare 2019 §C8.7.1): ζ_E of the
    linear, SLV, SLC, time-history and IDA checks, and the verdict."""
    kc = r.kinematic_checks
    if kc is None:
        return Text("No kinematic checks in these results.", "dim")
    where = ""
    if kc.floor is not None:
        where = f"; wall on a floor at Z/H = {kc.floor.z_over_h:.2f}"
    t = _table(
        f"Code checks (Circolare 2019 §C8.7.1): ζ_E = capacity/demand, a_g·S = {kc.a_g:.3f} g"
        f"; {kc.knowledge_level}, FC = {kc.fc:.2f}"
        + (" also in the IDA" if kc.fc_in_ida else " (not in the IDA)")
        + where
    )
    t.caption = (
        "† supporting checks (they do not decide).  * time history (§C8.7.1.2.1.9), deciding: "
        "min(d_lim/mean peak, d0/largest peak) of the records at the design intensity (a ratio "
        "of displacements; 'falls': a record topples the wall).  verdict: the decision "
        f"(IDA and time histories).  {kc.fc_basis}"
    )
    t.caption_justify = "left"
    t.add_column(Text("case"), ratio=3)
    for name in ("linear†", "SLV†", "SLC†", "TH SLV*", "TH SLC*", "IDA"):
        t.add_column(Text(name), justify="right", no_wrap=True)
    t.add_column(Text("verdict"), no_wrap=True)
    for cc in kc.cases:
        ida = cc.ida
        case = r.case(cc.case)
        decided = None if case is None else case.passes
        t.add_row(
            literal(cc.case),
            _zeta(cc.linear.zeta_e, cc.linear.passed),
            _zeta(cc.slv.zeta_e, cc.slv.passed),
            _zeta(cc.slc.zeta_e, cc.slc.passed),
            _th_cell(cc.time_history),
            _th_cell(cc.time_history_slc),
            Text("—", "dim") if ida is None else _zeta(ida.zeta_e, ida.passed),
            _ok(cc.passed if decided is None else decided, "pass", "FAIL"),
        )
    return t


def _th_cell(th: TimeHistoryResult | None) -> Text:
    """A time-history check's margin (its ratio in files written before the margin)."""
    if th is None:
        return Text("—", "dim")
    if th.ratio == 0:
        return Text("falls", "bold red")
    value = th.zeta_e
    if value is None:
        return Text("no rocking", "green" if th.passed else "red")
    return _zeta(value, th.passed)


def sensitivity_table(r: AssessmentResult) -> Table | Text:
    """The recommended (or best ranked) option under each model convention."""
    s = r.sensitivity
    if s is None or not s.rows:
        return Text("No sensitivity table in these results.", "dim")
    t = _table("Sensitivity to the model conventions")
    t.add_column(literal(s.case), ratio=3)
    t.add_column(Text("design a_dyn [g]"), justify="right", no_wrap=True)
    t.add_column(Text("capacity/demand"), justify="right", no_wrap=True)
    base = s.rows[0].capacity_demand
    t.add_column(Text("vs first row"), justify="right", no_wrap=True)
    for row in s.rows:
        bound = "≥ " if row.lower_bound else ""
        change = row.capacity_demand / base - 1.0 if base > 0 else 0.0
        t.add_row(
            literal(row.variant),
            f"{bound}{row.design_a_dyn:.4f}",
            Text(
                f"{bound}{row.capacity_demand:.2f}",
                "green" if row.capacity_demand >= r.model.target else "red",
            ),
            f"{change:+.1%}",
        )
    return t


def summary_text(r: AssessmentResult) -> Text:
    """The header of the Ranking view: the decision's demand FC·a_g·S, the wall, the
    unreinforced case, the code check and the recommendation in words."""
    w, urm, cc = r.wall, r.cases[0], r.code_check
    demand = r.demand.pga
    t = Text()
    t.append(f"Demand FC·a_g·S = {urm.fc * demand:.3f} g (FC {urm.fc:g} × a_g·S ")
    t.append(f"{demand:.3f} g);  wall α = {w.alpha_deg:.2f}°, ")
    t.append(f"a_RM = {w.a_rm:.3f} g;  unreinforced a_dyn = {urm.design_a_dyn:.3f} g, ")
    cd = fmt_against(urm.capacity_demand, r.model.target, urm.meets_target)
    t.append(f"C/D = {cd}", "green" if urm.meets_target else "red")
    t.append(f"\nDesign value: {r.model.design_value};  target C/D ≥ ")
    t.append(f"{r.model.target:g};  code check (§C8.7.1): a0* = {cc.a0_star:.3f} g ")
    t.append(f"vs {cc.demand:.3f} g → ")
    t.append("satisfied" if cc.passed else "NOT satisfied", "green" if cc.passed else "red")
    t.append("\nCategory: ", "bold")
    t.append(printable(category_line(r)))
    building = r.building
    if building is not None:
        t.append("\nShaken by: ", "bold")
        t.append(printable(building.shaken_by))
    if not r.input_code_compliant:
        t.append(
            "\nINPUT NOT CODE-COMPLIANT: the records fail the code's spectrum checks "
            "(Compliance tab); no option is recommended",
            "bold red",
        )
    t.append(f"\n{recommendation_label(r)}: ", "bold")
    ok = r.recommended is not None or not r.retrofit_required
    t.append(printable(recommendation_text(r)), "bold green" if ok else "red")
    return t
