"""Vector charts (reportlab ``Drawing`` flowables) as pure functions of the typed results;
the axes and the other primitives are in :mod:`frp_assess.report.chart_axes`."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from reportlab.graphics.shapes import Circle, Drawing, Group, String

from frp_assess.report import styles as st
from frp_assess.report.chart_axes import (
    FS,
    Axes,
    _text,
    legend,
    log_ticks,
    new_drawing,
    nice_range,
)
from frp_assess.report.formats import fmt_permille
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult


# --- the charts ---------------------------------------------------------------------------


def spectra_chart(
    results: Results, *, width: float = st.FRAME_WIDTH, height: float = 230, log_x: bool = True
) -> Drawing:
    """Target spectrum, every record's 5 % spectrum and their mean, Sa [g] against T [s]."""
    s = results.seismic
    periods = [float(t) for t in s.periods]
    target = [float(v) for v in s.target_sa]
    mean = [float(v) for v in s.mean_sa]
    rec_sa = [[float(v) for v in r.sa] for r in results.records if r.sa]
    d = new_drawing(width, height)
    x0, y0 = 46.0, 34.0
    w, h = width - x0 - 150, height - y0 - 10
    if log_x:
        pos = [t for t in periods if t > 0]
        xlim = (min(pos), max(pos))
        xticks = log_ticks(*xlim)
    else:
        xlim0, xlim1, xticks = nice_range(0.0, max(periods))
        xlim = (xlim0, xlim1)
    top = max([*target, *mean, *(v for sa in rec_sa for v in sa)], default=1.0)
    ylo, yhi, yticks = nice_range(0.0, top * 1.05)
    ax = Axes(d, x0, y0, w, h, xlim, (ylo, yhi), xlog=log_x)
    ax.frame(
        "period T [s]" + (" (log scale)" if log_x else ""),
        "spectral acceleration Sa [g]",
        xticks,
        yticks,
    )
    keep = [i for i, t in enumerate(periods) if (t > 0 or not log_x)]

    def sel(vals: Sequence[float]) -> tuple[list[float], list[float]]:
        return [periods[i] for i in keep], [vals[i] for i in keep]

    for sa in rec_sa:
        ax.line(*sel(sa), color=st.RECORD_LINE, width=0.6)
    ax.line(*sel([0.9 * v for v in target]), color=st.TARGET, width=0.8, dash=[1.5, 2])
    ax.line(*sel(target), color=st.TARGET, width=1.6)
    ax.line(*sel(mean), color=st.MEAN_LINE, width=1.4, dash=[5, 2])
    legend(
        d,
        x0 + w + 14,
        y0 + h - FS,
        [
            ("target spectrum", {"color": st.TARGET, "width": 1.6}),
            ("90 % of target", {"color": st.TARGET, "width": 0.8, "dash": [1.5, 2]}),
            (
                f"mean of {len(rec_sa)} records",
                {"color": st.MEAN_LINE, "width": 1.4, "dash": [5, 2]},
            ),
            ("each record (5 % damping)", {"color": st.RECORD_LINE, "width": 0.8}),
        ],
    )
    return d


SERIES_KEYS = ("material", "position")


def option_series(results: Results) -> dict[tuple[str, str], list[CaseResult]]:
    """Options grouped by (material, position), each sorted by FRP mass."""
    groups: dict[tuple[str, str], list[CaseResult]] = {}
    for c in results.cases:
        if c.material is None or c.position is None:
            continue
        groups.setdefault((c.material, c.position), []).append(c)
    for v in groups.values():
        v.sort(key=lambda c: (c.frp_mass, c.ratio))
    return dict(sorted(groups.items()))


def ratio_note(groups: Mapping[tuple[str, str], Sequence[CaseResult]]) -> str:
    """The legend note on the ratios ρ [‰] plotted along the lines of the options chart:
    the list when every line has the same ratios, else their range."""
    per_line = [sorted({float(c.ratio) for c in cs}) for cs in groups.values()]
    every = sorted({r for line in per_line for r in line})
    if not every:
        return ""
    if all(line == per_line[0] for line in per_line):
        shown = ", ".join(fmt_permille(r) for r in per_line[0])
        return f"ρ = {shown} ‰ along each line" if len(per_line) > 1 else f"ρ = {shown} ‰"
    return f"ρ from {fmt_permille(every[0])} to {fmt_permille(every[-1])} ‰"


def _series_style(key: tuple[str, str], i: int) -> dict[str, Any]:
    mat, pos = key
    color = st.MATERIAL_COLOURS.get(mat, st.SERIES[i % len(st.SERIES)])
    centred = pos == "centred"
    return {
        "color": color,
        "width": 1.1,
        "dash": [3, 2] if centred else None,
        "marker": "o" if centred else "s",
    }


def options_chart(
    results: Results, quantity: str, *, width: float = st.FRAME_WIDTH, height: float = 215
) -> Drawing:
    """``quantity`` ('improvement' or 'capacity_demand', a field of
    :class:`~frp_assess.results.model.CaseResult`) against the FRP mass of the wall [kg]."""
    if quantity not in ("improvement", "capacity_demand"):
        raise ValueError(f"cannot chart {quantity!r}")
    labels = {
        "improvement": "level of seismic improvement I [–]",
        "capacity_demand": "capacity / demand [–]",
    }
    groups = option_series(results)
    urm = results.urm
    d = new_drawing(width, height)
    x0, y0 = 46.0, 34.0
    w, h = width - x0 - 150, height - y0 - 10
    cases = [c for v in groups.values() for c in v] + [urm]
    xs = [float(c.frp_mass) for c in cases]
    ys = [float(getattr(c, quantity)) for c in cases]
    target = float(results.model.target)
    if quantity == "capacity_demand":
        ys.append(target)
    xlo, xhi, xticks = nice_range(0.0, max(xs) * 1.03 or 1.0)
    ylo, yhi, yticks = nice_range(0.0, max(ys) * 1.05)
    ax = Axes(d, x0, y0, w, h, (xlo, xhi), (ylo, yhi))
    ax.frame("FRP installed on the whole wall [kg]", labels[quantity], xticks, yticks)
    if quantity == "capacity_demand":
        ax.hline(target, st.PASS, label=f"target = {target:g}")
    else:
        ax.hline(1.0, st.MUTED, dash=(2, 2), label="unreinforced = 1")
    items: list[tuple[str, dict[str, Any]]] = []
    any_bound = False
    for i, (key, cs) in enumerate(groups.items()):
        sty = _series_style(key, i)
        ax.line(
            [c.frp_mass for c in cs],
            [getattr(c, quantity) for c in cs],
            sty["color"],
            sty["width"],
            sty["dash"],
        )
        for c in cs:
            lb = c.lower_bound
            any_bound |= lb
            ax.marker(
                c.frp_mass, getattr(c, quantity), sty["color"], shape=sty["marker"], hollow=lb
            )
        items.append((f"{key[0]} {key[1]}", sty))
    ax.marker(urm.frp_mass, getattr(urm, quantity), st.INK, shape="^")
    items.append(("unreinforced wall", {"color": st.INK, "width": 0, "marker": "^"}))
    dropped = [c for c in results.options if c.pivot is not None and c.pivot.dropped]
    for c in dropped:  # crossed out: the pivot check drops them from the ranking
        ax.marker(c.frp_mass, getattr(c, quantity), st.FAIL, shape="x")
    if dropped:
        items.append(("dropped: pivot check", {"color": st.FAIL, "width": 0, "marker": "x"}))
    rec = next((c for c in results.cases if c.name == results.recommended), None)
    if rec is not None:
        px, py = ax.tx(rec.frp_mass), ax.ty(getattr(rec, quantity))
        d.add(Circle(px, py, 6.5, fillColor=None, strokeColor=st.INK, strokeWidth=0.9))
        if not results.input_code_compliant:
            ringed = "best ranked (ringed)"
        elif not results.retrofit_required:  # the wall passes: optional margin, not advice
            ringed = "optional margin (ringed)"
        else:
            ringed = "recommended (ringed)"
        items.append((ringed, {"color": st.INK, "width": 0, "marker": "o", "hollow": True}))
    legend(d, x0 + w + 14, y0 + h - FS, items)
    note_y = y0 + h - FS - (len(items) + 0.6) * FS * 1.55
    d.add(_text(x0 + w + 14, note_y, ratio_note(groups), color=st.MUTED))
    if any_bound:
        d.add(_text(x0 + w + 14, note_y - FS * 1.4, "open marker: lower bound", color=st.MUTED))
        d.add(_text(x0 + w + 14, note_y - FS * 2.6, "(no collapse ≤ C_max)", color=st.MUTED))
    return d


def _clip_series(
    t: Sequence[float], y: Sequence[float], ymax: float
) -> tuple[list[float], list[float], float | None]:
    """Cut the series where it first exceeds ``ymax`` (interpolated); return the cut time."""
    xs: list[float] = []
    ys: list[float] = []
    for i, (a, b) in enumerate(zip(t, y, strict=True)):
        if b > ymax:
            if i > 0:
                a0, b0 = t[i - 1], y[i - 1]
                tc = a0 + (a - a0) * (ymax - b0) / (b - b0)
                xs.append(tc)
                ys.append(ymax)
                return xs, ys, tc
            return xs, ys, a
        xs.append(a)
        ys.append(b)
    return xs, ys, None


def _thin(t: Sequence[float], *ys: Sequence[float], n_max: int = 1800) -> list[list[float]]:
    step = max(1, math.ceil(len(t) / n_max))
    return [list(t[::step])] + [list(y[::step]) for y in ys]


def history_chart(
    results: Results, *, width: float = st.FRAME_WIDTH, height: float = 400
) -> Drawing | None:
    """θ/α(t) and bar strain ε(t) [‰] of the governing case, at collapse and just below."""
    gov = results.governing
    if not gov or not gov.runs:
        return None
    runs = gov.runs
    rupture = gov.rupture_strain
    has_strain = rupture is not None or any(any(r.strain or []) for r in runs)
    d = new_drawing(width, height)
    x0 = 46.0
    w = width - x0 - 150
    panel_h = (height - 2 * 40) / 2 if has_strain else height - 44
    t_end = max(max(r.time) for r in runs if r.time)
    xlo, xhi, xticks = nice_range(0.0, t_end)
    below = [r for r in runs if not r.collapsed]
    peak_below = max((max(abs(v) for v in r.theta_over_alpha) for r in below), default=1.0)
    ymax_theta = max(1.5, math.ceil(peak_below * 1.4 * 2) / 2)
    ymin_theta = min(0.0, min(min(r.theta_over_alpha) for r in runs))
    ymin_theta = max(ymin_theta, -ymax_theta)
    ylo, yhi, yticks = nice_range(ymin_theta, ymax_theta)
    y_theta = 40.0 + (panel_h + 40 if has_strain else 0)
    ax = Axes(d, x0, y_theta, w, panel_h, (xlo, xhi), (ylo, yhi))
    ax.frame("time t [s]", "rotation θ/α [–]", xticks, yticks)
    ax.hline(1.0, st.MUTED, dash=(3, 2), label="θ = α")
    if ylo < 0:
        ax.hline(-1.0, st.MUTED, dash=(3, 2))
    items = []
    notes = []
    for run in runs:
        color = st.COLLAPSE_RUN if run.collapsed else st.BELOW_RUN
        t, th, _ = _thin(run.time, run.theta_over_alpha, run.strain or [0.0] * len(run.time))
        xs, ys, cut = _clip_series(t, [max(v, ylo) for v in th], yhi)
        ax.line(xs, ys, color, 0.8)
        if cut is not None:
            ax.marker(cut, yhi, color, shape="^", size=3)
            notes.append((color, f"leaves the plot at t = {cut:.2f} s"))
        items.append((f"{run.label}, C = {run.multiplier:.3f}", {"color": color, "width": 1.4}))
    legend(d, x0 + w + 14, y_theta + panel_h - FS, items)
    ny = y_theta + panel_h - FS - (len(items) + 0.5) * FS * 1.55
    for color, text in notes:
        d.add(_text(x0 + w + 14, ny, "▲ " + text, color=color))
        d.add(_text(x0 + w + 14, ny - FS * 1.3, "(overturns)", color=color))
        ny -= FS * 3
    if has_strain:
        strains = [1e3 * abs(v) for r in runs for v in (r.strain or [0.0])]
        top = max([*strains, 1e3 * (rupture or 0.0)])
        slo, shi, sticks = nice_range(0.0, top * 1.1 or 1.0)
        ax2 = Axes(d, x0, 40.0, w, panel_h, (xlo, xhi), (slo, shi))
        ax2.frame("time t [s]", "bar strain ε [‰]", xticks, sticks)
        if rupture is not None:
            ax2.hline(1e3 * rupture, st.TARGET, label=f"rupture ε_max = {1e3 * rupture:.2f} ‰")
        for run in runs:
            color = st.COLLAPSE_RUN if run.collapsed else st.BELOW_RUN
            t, sn = _thin(run.time, run.strain or [0.0] * len(run.time))
            ax2.line(t, [1e3 * abs(v) for v in sn], color, 0.8)
        legend(d, x0 + w + 14, 40.0 + panel_h - FS, items)
    return d


def relabel(d: Drawing, label: Callable[[str], str]) -> Drawing:
    """``d`` with every string passed through ``label`` (in place; returned for chaining)."""

    def walk(node: object) -> None:
        if isinstance(node, String):
            node.text = label(str(node.text))
        elif isinstance(node, Group):
            for child in node.contents:
                walk(child)

    for s in d.contents:
        walk(s)
    return d


def localize_drawing(d: Drawing, lang: Lang) -> Drawing:
    """``d`` with every string in ``lang`` (:meth:`Lang.chart_label`; in place)."""
    return d if lang.code == "en" else relabel(d, lang.chart_label)
