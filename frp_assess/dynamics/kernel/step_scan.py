"""The events and the peak of one accepted step of the driver (:mod:`.simulate`).

A step's dense output of y = s·θ is the cubic Hermite through (0, y0), (1, y1) with slopes
m0 = s·θ'·h, m1.  :func:`scan_step` tests first whether the step is quiet (the cubic stays
inside (0, top): :func:`.step_control.quiet`, most steps) and calls :func:`search_step` only
for the others: the first event on the cubic, located on the integrator by :mod:`.events`,
and the largest s·θ before it.

The event kinds are the codes below; :func:`first_event` finds each one's crossing, the
driver locates the earliest (:func:`.events.locate_level`; the turning point of a yielding
tie, :func:`.events.locate_turn`), :func:`.jumps.jump` applies its jump and
:func:`.collapse_rule.collapse_verdict` judges it.  A new kind of event is a code here, its
level in :func:`first_event` and its jump.  The tie's events (docs/model.md §12) are levels of
s·θ held in the regime (:func:`.state.tie_levels`): upward, where it is re-engaged, yields or
is lost; downward, where it goes slack; and the turning point while it yields (it unloads).
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel import events as ev
from frp_assess.dynamics.kernel.params import KernelParams, TieParams
from frp_assess.dynamics.kernel.state import Regime, acting_bar, tie_levels
from frp_assess.dynamics.kernel.step_control import quiet

NO_EVENT = 0
IMPACT = 1
RUPTURE = 2
LIMIT = 3  #: the collapse level: π/2 (fell) or α_x (first exceedance)
CRUSH = 4  #: θ_cr of the intact acting bar: the toe crushes
TIE_UP = 5  #: the tie's upward level: re-engaged (slack), yields or is lost (elastic)
TIE_DOWN = 6  #: the tie's downward level: it goes slack (elastic, δ_p > 0)
TIE_TURN = 7  #: θ' = 0 while the tie yields: it unloads


@njit(cache=True, nogil=True)
def turning_peak(
    theta: float,
    omega: float,
    a1: float,
    h: float,
    u_end: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    floor: float,
    c: tuple[float, float, float, float],
    r1: float,
    r2: float,
    prm: KernelParams,
) -> float:
    """Largest s·θ at a turning point inside u ∈ (0, u_end) of a step, or −inf.

    Only a maximum that the dense output puts above ``floor`` is located on the integrator
    (:func:`.events.turning_point`): the others cannot change a peak.
    """
    c0, c1, c2, c3 = c
    best = -math.inf
    for r in (r1, r2):
        is_max = 2.0 * c2 + 6.0 * c3 * r < 0.0
        if 0.0 < r < u_end and is_max and ev.cubic(c0, c1, c2, c3, r) > floor:
            best = max(
                best, ev.turning_point(theta, omega, a1, h, r * h, u0, slope, s, k_s, t0, t1, prm)
            )
    return best


@njit(cache=True, nogil=True)
def first_event(
    y0: float,
    y1: float,
    c: tuple[float, float, float, float],
    r1: float,
    r2: float,
    bar_on: bool,
    limit: float,
    tie: tuple[float, float, bool],
    prm: KernelParams,
) -> tuple[int, float, float]:
    """The earliest event on the step's dense output ``c`` (from y0 = s·θ to y1):
    (kind, u ∈ (0, 1], level); ``tie``: :func:`.state.tie_levels` (the level of TIE_TURN is
    the cubic's, the driver locates it on the integrator)."""
    c0, c1, c2, c3 = c
    ymin = min(y0, y1)
    ymax = max(y0, y1)
    for r in (r1, r2):
        if r > 0.0:
            yr = ev.cubic(c0, c1, c2, c3, r)
            ymin = min(ymin, yr)
            ymax = max(ymax, yr)
    event = NO_EVENT
    u_event = 2.0
    level = 0.0
    if ymin <= 0.0:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, 0.0, False)
        if u >= 0.0:
            event, u_event, level = IMPACT, u, 0.0
    if bar_on and ymax >= prm.theta_max:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, prm.theta_max, True)
        if 0.0 <= u < u_event:
            event, u_event, level = RUPTURE, u, prm.theta_max
    if bar_on and ymax >= prm.theta_cr:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, prm.theta_cr, True)
        if 0.0 <= u < u_event:
            event, u_event, level = CRUSH, u, prm.theta_cr
    if ymax >= limit:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, limit, True)
        if 0.0 <= u < u_event:
            event, u_event, level = LIMIT, u, limit
    if not prm.tie_on:
        return event, u_event, level
    tie_up, tie_down, tie_turn = tie
    if ymax >= tie_up:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, tie_up, True)
        if 0.0 <= u < u_event:
            event, u_event, level = TIE_UP, u, tie_up
    if tie_down > 0.0 and ymin <= tie_down:
        u = ev.first_crossing(c0, c1, c2, c3, r1, r2, tie_down, False)
        if 0.0 <= u < u_event:
            event, u_event, level = TIE_DOWN, u, tie_down
    if tie_turn:
        for r in (r1, r2):  # the first maximum of s·θ: θ' = 0 while moving outward
            if 0.0 < r < u_event and 2.0 * c2 + 6.0 * c3 * r < 0.0:
                event, u_event, level = TIE_TURN, r, ev.cubic(c0, c1, c2, c3, r)
                break
    return event, u_event, level


@njit(cache=True, nogil=True)
def search_step(
    theta: float,
    omega: float,
    a1: float,
    hh: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    bar_on: bool,
    limit: float,
    tie: tuple[float, float, bool],
    floor: float,
    prm: KernelParams,
    y0: float,
    y1: float,
    m0: float,
    m1: float,
) -> tuple[int, float, float, float]:
    """The first event of an accepted step that is not quiet (:func:`.step_control.quiet`,
    tested by the driver first: most steps are, and need no call) and the largest s·θ up to
    it: (kind, u ∈ (0, 1], level, largest s·θ).  The step's dense output is the cubic
    through (0, y0 = s·θ) and (1, y1) with slopes m0 = s·θ'·h, m1; ``floor``: the peak so far,
    below which a turning point cannot change a peak."""
    c = ev.hermite(y0, y1, m0, m1)
    r1, r2 = ev.critical_points(c[1], c[2], c[3])
    event, u_event, level = first_event(y0, y1, c, r1, r2, bar_on, limit, tie, prm)
    # the largest s·θ of the step up to the event (or its end)
    u_end = 1.0 if event == NO_EVENT else u_event
    step_max = max(
        y0,
        y1 if event == NO_EVENT else level,
        turning_peak(theta, omega, a1, hh, u_end, u0, slope, s, k_s, t0, t1, floor, c, r1, r2, prm),
    )
    return event, u_event, level, step_max


@njit(cache=True, nogil=True, inline="always")
def scan_step(
    theta: float,
    omega: float,
    a1: float,
    th1: float,
    om1: float,
    hh: float,
    u0: float,
    slope: float,
    r: Regime,
    k_s: float,
    t0: float,
    t1: float,
    peak: float,
    peak_bar: float,
    bar_level: float,
    limit: float,
    prm: KernelParams,
    ties: TieParams,
) -> tuple[int, float, float, float, float, float, float]:
    """The first event of the accepted step hh [s] from (θ, θ', θ'' = a1) to (th1, om1) in the
    regime r, and the peaks up to it: (kind, u ∈ (0, 1] or 2.0, level, peak |θ|, peak |θ| with
    an intact bar, y0 = s·θ, y1 = s·th1).

    ``limit``: the collapse level (:func:`.collapse_rule.collapse_level`); ``bar_level``: the lowest
    level with the bar intact, min(θ_max, θ_cr, limit); ``ties``: the tie levels' constants.
    numba inlines it into the driver.
    """
    s = r.s
    bar_on = acting_bar(r)
    y0 = s * theta
    y1 = s * th1
    floor = peak_bar if bar_on else peak
    top = min(floor, bar_level) if bar_on else min(floor, limit)
    m0 = s * omega * hh
    m1 = s * om1 * hh
    if prm.tie_on:  # the tie's levels narrow the band of a quiet step, (0, top) without
        tie = tie_levels(r, ties)
        tie_up, low, tie_turn = tie
        is_quiet = not tie_turn and quiet(y0 - low, y1 - low, m0, m1, min(top, tie_up) - low)
    else:
        tie = (math.inf, 0.0, False)
        is_quiet = quiet(y0, y1, m0, m1, top)
    if is_quiet:
        # the dense output stays inside (0, top): no event, no new peak
        event, u_event, level, step_max = NO_EVENT, 2.0, 0.0, max(y0, y1)
    else:
        event, u_event, level, step_max = search_step(
            theta,
            omega,
            a1,
            hh,
            u0,
            slope,
            s,
            k_s,
            t0,
            t1,
            bar_on,
            limit,
            tie,
            floor,
            prm,
            y0,
            y1,
            m0,
            m1,
        )
    peak = max(peak, step_max)
    if bar_on:
        peak_bar = max(peak_bar, step_max)
    return event, u_event, level, peak, peak_bar, y0, y1
