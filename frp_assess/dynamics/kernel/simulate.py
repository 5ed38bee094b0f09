"""The time-stepping driver: one wall under one scaled record (paper Eq. 10, docs/model.md §3–4).

A newcomer's map: :func:`simulate` is the loop over the record's sample intervals, and
each piece it calls is one paragraph of docs/model.md §3–4.

* The input is the record (plus ``n_tail`` zero samples: :class:`.state.Ground`).  Between
  two samples the ground acceleration is linear; steps never cross a sample, so every step
  sees a smooth input.
* The state is (θ, θ') and the :class:`.state.Regime` (side, rest, intact bars), which only
  the events change.
* At rest nothing is integrated: the instant when the linear ground acceleration exceeds
  g·tan α_x is solved for exactly and rocking starts there (:func:`.jumps.uplift_from_rest`),
  with the same first step proposal every time.
* Rocking: one accepted step of the integrator (:func:`.step_control.try_step`: the method of
  :mod:`.steppers`, retried shorter while its error estimate exceeds the tolerance), scanned
  for events on its dense output (:func:`.step_scan.scan_step`: impact, rupture, toe
  crushing, the collapse level, and the peak).  The first event is located on the integrator
  (:func:`.events.locate_level`), its jump applied there (:func:`.jumps.jump`; a tie's,
  :func:`.jumps.tie_jump`) and the step
  restarts from that instant.
* The collapse rule's verdict (:func:`.collapse_rule.collapse_verdict`) is asked after every
  event, every step of the free vibration and when the input ends: the toe crushing and the
  fall are collapses; ``overturning`` follows the free vibration until the wall falls or can
  no longer fall; ``end-of-record`` and ``first-exceedance`` judge |θ| against α_x.

Everything here is numbers and arrays; the Python face is :mod:`frp_assess.dynamics.rocking`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from numba import njit

from frp_assess.dynamics.kernel import events as ev
from frp_assess.dynamics.kernel.collapse_rule import (
    UNDECIDED,
    alpha_x_crossing,
    collapse_level,
    collapse_verdict,
    peaks_at_rest,
)
from frp_assess.dynamics.kernel.jumps import (
    bounces_die_out,
    ground_input,
    jump,
    tie_jump,
    uplift_from_rest,
)
from frp_assess.dynamics.kernel.params import (
    COLLAPSE_OVERTURNING,
    FATE_AT_REST,
    MAX_EVENTS_PER_INTERVAL,
    MAX_FREE_VIBRATION,
    STATUS_EVENT_OVERFLOW,
    STATUS_FREE_VIBRATION_UNDECIDED,
    STATUS_OK,
    STATUS_STEP_UNDERFLOW,
    TIE_LOST,
    TIE_YIELD,
    KernelParams,
    TieParams,
)
from frp_assess.dynamics.kernel.state import (
    Buffers,
    Ground,
    acting_bar,
    any_tie,
    at_rest,
    bar_stiffness,
    initial_regime,
    plastic_elongations,
    record_rupture,
    record_sample,
    tie_terms,
)
from frp_assess.dynamics.kernel.step_control import stepping, try_step
from frp_assess.dynamics.kernel.step_scan import (
    IMPACT,
    NO_EVENT,
    RUPTURE,
    TIE_DOWN,
    TIE_TURN,
    TIE_UP,
    scan_step,
)


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
    tie_lost: bool  #: a tie's anchorage failed (docs/model.md §12)
    #: each tie level's plastic elongation δ_p at the end [m] (0 beyond the wall's levels)
    tie_plastic: tuple[float, float]


def history_length(n_input: int, dt: float, collapse_mode: int) -> int:
    """Samples a history array needs: the input, plus the longest free vibration followed."""
    if collapse_mode != COLLAPSE_OVERTURNING:
        return n_input
    return n_input + int(math.ceil(MAX_FREE_VIBRATION / dt)) + 1


@njit(cache=True, nogil=True, inline="always")
def reached(x: float, dt: float, h_min: float) -> float:
    """The time x [s] into the sample interval after a step or an event, snapped to the sample
    dt when less than ``h_min`` is left: x + (dt − x) can fall an ulp short of dt, and a step
    of 1e-18 s on that sliver was no step at all — its dense output is round-off, in which a
    yielding tie found a spurious turning point and stopped the wall (θ' set to 0), and the
    next step proposal started from 5e-18 s."""
    return dt if dt - x < h_min else x


@njit(cache=True, nogil=True)
def simulate(
    ground: Ground,
    prm: KernelParams,
    ties: TieParams,
    theta0: float,
    omega0: float,
    record_history: bool,
    out: Buffers,
) -> Outcome:
    """Integrate Eq. 10 from (θ0, θ'0) under the ``ground`` input.

    With ``record_history`` the history arrays of ``out`` (length :func:`history_length`)
    receive θ [rad], θ' [rad/s] and whether the acting bar is intact and stretched (1.0/0.0)
    at every sample; its rupture arrays (length ≥ 2) always receive the first ruptures.
    """
    acc = ground.acc
    dt = ground.dt
    n_rec = acc.shape[0]
    n_input = n_rec + ground.n_tail
    n_free_max = int(math.ceil(MAX_FREE_VIBRATION / dt))
    inv_g = ground.scale / prm.g
    ctl = stepping(dt, prm)
    limit = collapse_level(prm)
    bar_level = min(prm.theta_max, prm.theta_cr, limit)  # the lowest level with the bar intact

    theta = theta0
    omega = omega0
    r = initial_regime(theta0, omega0, prm, ties)
    peak = abs(theta)
    peak_bar = abs(theta) if r.intact_pos else 0.0
    n_impacts = 0
    n_ruptures = 0
    n_steps = 0
    n_rejected = 0
    status = STATUS_OK
    fate = UNDECIDED
    decided_time = math.nan
    collapse_time = math.nan
    last_alpha_up = math.nan
    h = ctl.h_start  # the proposal of the next step [s]
    a1 = math.nan  # θ'' at the start of the next step [rad/s²]
    need_a = True  # not known yet: computed from the state
    samples = 1
    if record_history:
        record_sample(out, 0, theta, omega, False)

    i = 0
    while True:
        free = i >= n_input - 1  # the input is over: zero ground motion from here on
        if free:
            if i - (n_input - 1) >= n_free_max:
                status = STATUS_FREE_VIBRATION_UNDECIDED
                break
            fate, collapse_time = collapse_verdict(
                theta, omega, r, True, NO_EVENT, 0.0, i * dt, last_alpha_up, prm, ties
            )
            if fate != UNDECIDED:
                decided_time = i * dt
                break
        t_i = i * dt
        ua = ground_input(acc, i, n_rec, inv_g)
        ub = ground_input(acc, i + 1, n_rec, inv_g)
        slope = (ub - ua) / dt  # [g/s]
        x = 0.0  # time into the sample interval [s]
        events = 0
        while x < dt:
            if r.resting:  # --- at rest: the instant the input uplifts the wall, if any
                x, r, event = uplift_from_rest(r, ua, slope, x, dt, prm)
                if not r.resting:  # a rocking phase starts at x
                    theta = 0.0
                    omega = 0.0
                    need_a = True
                    h = ctl.h_start
                level = 0.0
                now = t_i + x
            else:
                # --- rocking: one accepted step (a rejected one is retried shorter) ----------
                t0 = 0.0
                t1 = 0.0
                if prm.tie_on:  # the tie's moment in this regime (docs/model.md §12)
                    if r.s * omega <= 0.0 and any_tie(r, TIE_YIELD, ties):
                        # a yielding tie whose wall stopped at the end of a step: it unloads
                        r = tie_jump(TIE_TURN, r.s * theta, theta, r, ties)
                        need_a = True
                    t0, t1 = tie_terms(r, ties)
                k_s = bar_stiffness(r, prm)
                u0 = ua + slope * x
                th1, om1, a_end, a1, hh, h, accepted = try_step(
                    theta, omega, a1, need_a, h, u0, slope, dt - x, r.s, k_s, t0, t1, ctl, prm
                )
                need_a = False
                if not accepted:
                    n_rejected += 1
                    if h < ctl.h_min:
                        status = STATUS_STEP_UNDERFLOW
                        break
                    continue
                n_steps += 1
                # --- the first event on it, and the peaks up to it
                event, u_event, level, peak, peak_bar, y0, y1 = scan_step(
                    theta, omega, a1, th1, om1, hh, u0, slope, r, k_s, t0, t1, peak, peak_bar,
                    bar_level, limit, prm, ties,
                )  # fmt: skip
                if event == NO_EVENT:  # the step holds: the wall moves on
                    last_alpha_up = alpha_x_crossing(
                        y0, y1, t_i + x, hh, prm.alpha_x, last_alpha_up
                    )
                    if y1 < 0.0:
                        # s·θ left its regime without a located crossing: only possible at
                        # round-off level right after an uplift; the wall is at rest.
                        theta = 0.0
                        omega = 0.0
                        r = at_rest(r)
                    else:
                        theta = th1
                        omega = om1
                        a1 = a_end
                        need_a = not ctl.adaptive  # RK4 gives no end acceleration
                    x = reached(x + hh, dt, ctl.h_min)
                    now = t_i + min(x, dt)
                else:
                    # --- an event inside the step: locate it on the integrator, jump, restart
                    events += 1
                    if events > MAX_EVENTS_PER_INTERVAL:
                        status = STATUS_EVENT_OVERFLOW
                        break
                    if event == TIE_TURN:  # θ' = 0: a turning point, not a level
                        tau, level = ev.locate_turn(
                            theta, omega, a1, hh, u_event * hh, u0, slope, r.s, k_s, t0, t1, prm
                        )
                        om_e = 0.0
                    else:
                        tau, om_e, _resid = ev.locate_level(
                            theta, omega, a1, hh, u_event * hh, u0, slope, r.s, k_s, t0, t1,
                            level, prm,
                        )  # fmt: skip
                    last_alpha_up = alpha_x_crossing(
                        y0, level, t_i + x, tau, prm.alpha_x, last_alpha_up
                    )
                    x = reached(x + tau, dt, ctl.h_min)
                    now = t_i + x
                    if event == TIE_UP or event == TIE_DOWN or event == TIE_TURN:
                        theta, omega = r.s * level, om_e  # θ and θ' do not jump
                        r = tie_jump(event, level, theta, r, ties)
                    else:
                        theta, omega, r = jump(event, level, om_e, r, prm)
                    need_a = True
                    if event == IMPACT:
                        n_impacts += 1
                        # bounces that surely die out where the input cannot uplift the wall
                        # are not followed: at rest now, every later instant the same
                        # (docs/model.md §3.3).  With a history they must end in this
                        # interval (its samples are written); without one, before the input
                        # ends.
                        last = i + 1 if record_history else n_input - 1
                        if bounces_die_out(
                            omega, r, free, ground, i, x, last, peak, bar_level, limit, prm
                        ):  # fmt: skip
                            omega = 0.0
                            r = at_rest(r)
                    elif event == RUPTURE:
                        record_rupture(out, n_ruptures, now, r.s)
                        n_ruptures += 1

            # --- the collapse rule's verdict, after an event and in the free vibration
            if event == NO_EVENT and not free:
                continue
            fate, collapse_time = collapse_verdict(
                theta, omega, r, free, event, level, now, last_alpha_up, prm, ties
            )
            if fate != UNDECIDED:
                decided_time = now
                break
        if status != STATUS_OK or fate != UNDECIDED:
            break
        if record_history and i + 1 < out.theta.shape[0]:
            record_sample(out, i + 1, theta, omega, acting_bar(r) and not r.resting)
            samples = i + 2
        i += 1

    if fate == FATE_AT_REST:
        peak, peak_bar = peaks_at_rest(theta, omega, r, peak, peak_bar, prm, ties)
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
        any_tie(r, TIE_LOST, ties),
        plastic_elongations(theta, r, ties),
    )
