"""The time-stepping driver: one wall under one scaled record (paper Eq. 10, docs/model.md §3–4).

A newcomer's map:

* The input is the record (plus ``n_tail`` zero samples).  Between two samples the ground
  acceleration is linear; steps never cross a sample, so every step sees a smooth input.
* At rest nothing is integrated: the instant when the linear ground acceleration exceeds
  g·tan α_x is solved for exactly (:func:`.jumps.uplift`) and rocking starts there, with the
  same first step proposal every time.
* Rocking: one step of the chosen method (:mod:`.steppers`), rejected and retried smaller
  while its error estimate exceeds the tolerance (the step is inlined here:
  :mod:`.inlining`).  An accepted step that is not quiet is scanned for events on its dense
  output (:mod:`.step_scan`) and each event is located on the integrator (:mod:`.events`);
  the jump is applied there (:mod:`.jumps`) and the step restarts from that instant.
  The toe crushing (|θ| reaches θ_cr with the acting bar intact) is a collapse, as is the fall.
* Collapse ``overturning``: after the input the wall moves freely until it falls or can no
  longer fall (:mod:`.fate`).  ``end-of-record`` and ``first-exceedance`` judge |θ| against
  α_x (α with the edge pivot).

Everything here is numbers and arrays; the Python face is :mod:`frp_assess.dynamics.rocking`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel import events as ev
from frp_assess.dynamics.kernel.fate import cannot_fall, remaining_peak
from frp_assess.dynamics.kernel.jumps import (
    chatter_ends,
    ground_input,
    impact,
    rupture,
    uplift,
)
from frp_assess.dynamics.kernel.params import (
    BAR_NONE,
    COLLAPSE_END_OF_RECORD,
    COLLAPSE_FIRST_EXCEEDANCE,
    COLLAPSE_OVERTURNING,
    FATE_AT_REST,
    FATE_CRUSHED,
    FATE_EXCEEDED,
    FATE_FELL,
    FATE_STANDING,
    MAX_EVENTS_PER_INTERVAL,
    MAX_FREE_VIBRATION,
    METHOD_DOPRI5,
    METHOD_RK4,
    MIN_STEP_FRACTION,
    STATUS_EVENT_OVERFLOW,
    STATUS_FREE_VIBRATION_UNDECIDED,
    STATUS_OK,
    STATUS_STEP_UNDERFLOW,
    KernelParams,
)
from frp_assess.dynamics.kernel.step_control import (
    SLIVER,
    grow_threshold,
    quiet,
    step_length,
    step_size,
)
from frp_assess.dynamics.kernel.step_scan import CRUSH, IMPACT, NO_EVENT, RUPTURE, search_step
from frp_assess.dynamics.kernel.steppers import acceleration, step


class Outcome(NamedTuple):
    """What the kernel returns (units: s, rad, rad/s)."""

    status: int  #: STATUS_*
    fate: int  #: FATE_*
    decided_time: float  #: when the fate became certain [s]
    collapse_time: float  #: when the wall fell / met the rule's limit [s]; NaN otherwise
    peak: float  #: peak |θ| [rad], the free vibration included
    peak_with_bar: float  #: peak |θ| while the acting bar was intact [rad]
    impacts: int  #: impacts followed (docs/model.md §3.3)
    ruptures: int
    final_theta: float  #: [rad]
    final_omega: float  #: [rad/s]
    samples: int  #: history samples written
    steps: int  #: accepted integration steps
    rejected: int  #: rejected integration steps


def history_length(n_input: int, dt: float, collapse_mode: int) -> int:
    """Samples a history array needs: the input, plus the longest free vibration followed."""
    if collapse_mode != COLLAPSE_OVERTURNING:
        return n_input
    return n_input + int(math.ceil(MAX_FREE_VIBRATION / dt)) + 1


@njit(cache=True, nogil=True)
def _settled(
    resting: bool,
    theta: float,
    omega: float,
    s: float,
    intact_pos: bool,
    intact_neg: bool,
    prm: KernelParams,
) -> bool:
    """With no more ground motion: the wall is at rest, or can no longer fall."""
    return resting or cannot_fall(theta, omega, s, intact_pos, intact_neg, prm)


@njit(cache=True, nogil=True)
def _record_sample(
    hist_theta: np.ndarray,
    hist_omega: np.ndarray,
    hist_bar: np.ndarray,
    k: int,
    theta: float,
    omega: float,
    bar_acting: bool,
) -> None:
    """Store sample k of the history: θ, θ' and whether an intact bar is stretched."""
    hist_theta[k] = theta
    hist_omega[k] = omega
    hist_bar[k] = 1.0 if bar_acting else 0.0


@njit(cache=True, nogil=True)
def _up_crossing(y0: float, y1: float, t0: float, span: float, level: float, last: float) -> float:
    """The time [s] at which s·θ rose through ``level`` on a piece from (t0, y0) to
    (t0 + span, y1), by linear interpolation, if it did; else ``last``, the previous one."""
    if y0 < level <= y1:
        return t0 + span * (level - y0) / (y1 - y0)
    return last


@njit(cache=True, nogil=True)
def _verdict_at_end(theta: float, last_alpha_up: float, prm: KernelParams) -> tuple[int, float]:
    """(fate, collapse time) of the α_x-based rules when the input ends without a decision:
    `end-of-record` collapses when |θ| ≥ α_x then (at the last upward crossing of α_x)."""
    if prm.collapse_mode == COLLAPSE_END_OF_RECORD and abs(theta) >= prm.alpha_x:
        return FATE_EXCEEDED, last_alpha_up
    return FATE_STANDING, math.nan


@njit(cache=True, nogil=True)
def _peaks_at_rest(
    theta: float,
    omega: float,
    s: float,
    intact_pos: bool,
    intact_neg: bool,
    resting: bool,
    peak: float,
    peak_bar: float,
    prm: KernelParams,
) -> tuple[float, float]:
    """(peak, peak with an intact bar) once the wall can no longer fall: the rotation of the
    rocking still to come is the turning angle its energy reaches (:func:`.fate.remaining_peak`)."""
    if resting:
        return peak, peak_bar
    extra, with_bar = remaining_peak(theta, omega, s, intact_pos, intact_neg, prm)
    return max(peak, extra), (max(peak_bar, extra) if with_bar else peak_bar)


@njit(cache=True, nogil=True)
def simulate(
    acc: np.ndarray,
    dt: float,
    scale: float,
    n_tail: int,
    prm: KernelParams,
    theta0: float,
    omega0: float,
    record_history: bool,
    hist_theta: np.ndarray,
    hist_omega: np.ndarray,
    hist_bar: np.ndarray,
    rupture_time: np.ndarray,
    rupture_side: np.ndarray,
) -> Outcome:
    """Integrate Eq. 10 under scale·acc (acc [m/s²] every dt [s], then n_tail zero samples).

    hist_* (length :func:`history_length`, if ``record_history``) receive θ [rad], θ' [rad/s]
    and whether the acting bar is intact and stretched (1.0/0.0) at every sample;
    rupture_time/rupture_side (length ≥ 2) the first ruptures.
    """
    n_rec = acc.shape[0]
    n_input = n_rec + n_tail
    n_free_max = int(math.ceil(MAX_FREE_VIBRATION / dt))
    overturning = prm.collapse_mode == COLLAPSE_OVERTURNING
    limit = prm.alpha_x if prm.collapse_mode == COLLAPSE_FIRST_EXCEEDANCE else 0.5 * math.pi
    inv_g = scale / prm.g
    adaptive = prm.method != METHOD_RK4
    # step-size exponent: 1/(q + 1), q the order of the embedded error estimate
    order = 5 if prm.method == METHOD_DOPRI5 else 3
    exponent = -1.0 / order
    err_grow_max = grow_threshold(exponent)
    h_enough = (1.0 - SLIVER) * dt  # every step ends at a sample, at most dt away
    bar_level = min(prm.theta_max, prm.theta_cr, limit)  # the lowest level with the bar intact
    h_fixed = dt / max(1, int(math.ceil(dt / prm.fixed_step - 1e-9))) if not adaptive else dt

    theta = theta0
    omega = omega0
    resting = theta0 == 0.0 and omega0 == 0.0
    s = -1.0 if (theta0 < 0.0 or (theta0 == 0.0 and omega0 < 0.0)) else 1.0
    intact_pos = prm.bar_mode != BAR_NONE
    intact_neg = prm.bar_mode != BAR_NONE

    peak = abs(theta)
    peak_bar = abs(theta) if intact_pos else 0.0
    n_impacts = 0
    n_ruptures = 0
    n_steps = 0
    n_rejected = 0
    status = STATUS_OK
    fate = -1
    decided_time = math.nan
    collapse_time = math.nan
    last_alpha_up = math.nan
    # the first proposal of a rocking phase: at the start and again at every uplift from rest,
    # so that a phase does not depend on how the one before it came to rest
    h_start = h_fixed if not adaptive else min(dt, 0.05 / prm.p)
    h = h_start
    a1 = math.nan
    need_a = True
    samples = 1
    if record_history:
        hist_theta[0] = theta
        hist_omega[0] = omega
        hist_bar[0] = 0.0

    i = 0
    while fate < 0 and status == STATUS_OK:
        free = i >= n_input - 1  # zero ground motion from here on
        if free:
            if not overturning:
                break
            if i - (n_input - 1) >= n_free_max:
                status = STATUS_FREE_VIBRATION_UNDECIDED
                break
            if _settled(resting, theta, omega, s, intact_pos, intact_neg, prm):
                fate = FATE_AT_REST
                decided_time = i * dt
                peak, peak_bar = _peaks_at_rest(
                    theta, omega, s, intact_pos, intact_neg, resting, peak, peak_bar, prm
                )
                break
        t_i = i * dt
        ua = ground_input(acc, i, n_rec, inv_g)
        ub = ground_input(acc, i + 1, n_rec, inv_g)
        slope = (ub - ua) / dt  # [g/s]
        x = 0.0
        events = 0
        while x < dt:
            if resting:
                x, side = uplift(ua, slope, x, dt, prm)
                if side != 0.0:
                    resting = False
                    s = side
                    theta = 0.0
                    omega = 0.0
                    need_a = True
                    h = h_start
                    if prm.theta_cr <= 0.0 and (intact_pos if s > 0.0 else intact_neg):
                        # x_W already reaches the bar: the toe crushes as the wall uplifts
                        fate = FATE_CRUSHED
                        collapse_time = t_i + x
                        decided_time = collapse_time
                        break
                continue

            bar_on = intact_pos if s > 0.0 else intact_neg
            k_s = prm.k_bar if bar_on else 0.0
            u0 = ua + slope * x
            if need_a:
                a1 = acceleration(theta, s, u0, k_s, prm)
                need_a = False
            hh = step_length(h if adaptive else h_fixed, dt - x, adaptive)
            th1, om1, a_end, err = step(theta, omega, hh, u0, slope, s, k_s, a1, prm)
            if adaptive:
                accepted, h = step_size(err, hh, h, exponent, err_grow_max, h_enough, order)
                if not accepted:
                    n_rejected += 1
                    if h < MIN_STEP_FRACTION * dt:
                        status = STATUS_STEP_UNDERFLOW
                        break
                    continue
            n_steps += 1

            # dense output of y = s·θ on the step, u ∈ [0, 1], and the first event on it
            y0 = s * theta
            y1 = s * th1
            floor = peak_bar if bar_on else peak
            top = min(floor, bar_level) if bar_on else min(floor, limit)
            m0 = s * omega * hh
            m1 = s * om1 * hh
            if quiet(y0, y1, m0, m1, top):
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
                    bar_on,
                    limit,
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

            if event == NO_EVENT:
                last_alpha_up = _up_crossing(y0, y1, t_i + x, hh, prm.alpha_x, last_alpha_up)
                if y1 < 0.0:
                    # s·θ left its regime without a located crossing: only possible at
                    # round-off level right after an uplift; the wall is at rest.
                    theta = 0.0
                    omega = 0.0
                    resting = True
                else:
                    theta = th1
                    omega = om1
                    a1 = a_end
                    need_a = not adaptive
                x = x + hh
                if free and _settled(resting, theta, omega, s, intact_pos, intact_neg, prm):
                    fate = FATE_AT_REST
                    decided_time = t_i + min(x, dt)
                    peak, peak_bar = _peaks_at_rest(
                        theta, omega, s, intact_pos, intact_neg, resting, peak, peak_bar, prm
                    )
                    break
                continue

            # --- an event inside the step: locate it on the integrator, jump, restart ---------
            events += 1
            if events > MAX_EVENTS_PER_INTERVAL:
                status = STATUS_EVENT_OVERFLOW
                break
            tau, om_e, _resid = ev.locate_level(
                theta, omega, a1, hh, u_event * hh, u0, slope, s, k_s, level, prm
            )
            last_alpha_up = _up_crossing(y0, level, t_i + x, tau, prm.alpha_x, last_alpha_up)
            x = x + tau
            t_event = t_i + x
            theta = s * level
            omega = om_e
            need_a = True
            if event == IMPACT:
                n_impacts += 1
                theta = 0.0
                omega, s, resting = impact(om_e, s, prm)
                # bounces that surely die out where the input cannot uplift the wall are not
                # followed: at rest now, every later instant the same (docs/model.md §3.3)
                if (
                    prm.settle_chatter
                    and not resting
                    and not free
                    and chatter_ends(
                        omega,
                        s,
                        acc,
                        i,
                        x,
                        dt,
                        inv_g,
                        n_rec,
                        # with a history the bounces must end in this interval: its samples
                        # are written; without one, before the input ends
                        i + 1 if record_history else n_input - 1,
                        min(peak, bar_level) if intact_pos or intact_neg else min(peak, limit),
                        prm.k_bar if intact_pos or intact_neg else 0.0,
                        prm,
                    )
                ):
                    omega = 0.0
                    resting = True
            elif event == RUPTURE:
                if n_ruptures < rupture_time.shape[0]:
                    rupture_time[n_ruptures] = t_event
                    rupture_side[n_ruptures] = int(s)
                n_ruptures += 1
                omega, intact_pos, intact_neg = rupture(om_e, s, intact_pos, intact_neg, prm)
            elif event == CRUSH:
                fate = FATE_CRUSHED
                collapse_time = t_event
                decided_time = t_event
                break
            else:
                fate = FATE_FELL if level >= 0.5 * math.pi else FATE_EXCEEDED
                collapse_time = t_event
                decided_time = t_event
                break
            if free and _settled(resting, theta, omega, s, intact_pos, intact_neg, prm):
                fate = FATE_AT_REST
                decided_time = t_event
                peak, peak_bar = _peaks_at_rest(
                    theta, omega, s, intact_pos, intact_neg, resting, peak, peak_bar, prm
                )
                break
        if status != STATUS_OK or fate >= 0:
            break
        if record_history and i + 1 < hist_theta.shape[0]:
            bar_acting = (intact_pos if s > 0.0 else intact_neg) and not resting
            _record_sample(hist_theta, hist_omega, hist_bar, i + 1, theta, omega, bar_acting)
            samples = i + 2
        i += 1

    if fate < 0 and status == STATUS_OK:
        decided_time = (n_input - 1) * dt
        fate, collapse_time = _verdict_at_end(theta, last_alpha_up, prm)
    return Outcome(
        status,
        fate,
        decided_time,
        collapse_time,
        peak,
        peak_bar,
        n_impacts,
        n_ruptures,
        theta,
        omega,
        samples,
        n_steps,
        n_rejected,
    )
