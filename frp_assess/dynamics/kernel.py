"""Compiled time-stepping kernel for the restrained rocking wall (paper Eq. 10, MODEL.md §3–4).

The scheme (a newcomer's map of this file):

* Between two record samples the ground acceleration is linear, so the right-hand side is
  known exactly at any instant.  Each sample interval is split into ``nsub`` equal sub-steps
  (``nsub`` chosen by the caller from the stiffest frequency of the system) and each sub-step
  is one classical Runge–Kutta 4 step on (θ, θ') with the sign regime s = sgn θ frozen.
* After a trial step, the cubic Hermite interpolant of s·θ through both ends (values and
  slopes, 4th-order accurate) is scanned for the first crossing of an event level: 0 going
  down (impact), θ_max going up (rupture of an intact acting bar), the collapse level going up.
* The earliest event is then *located on the integrator itself*: Newton iterations on the
  length τ of a single RK4 step from the start of the sub-step, until s·θ(τ) hits the level to
  ~1e-13 rad.  The jump is applied there and the sub-step is restarted from that instant —
  never postponed to the next sample.
* At rest (θ = θ' = 0) nothing is integrated: the instant when the linear ground acceleration
  exceeds g·tan α is solved for exactly, and rocking starts from there.

Everything here is plain numbers and arrays; the Python wrapper is :mod:`.rocking`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# Codes shared with the Python wrapper.
BAR_NONE = 0  #: unreinforced
BAR_SHARED = 1  #: centred bar: acts for both signs of θ, one rupture removes it for both
BAR_PER_SIDE = 2  #: external bars: the bar opposite the pivot acts; each side breaks on its own

RUPTURE_ENERGY_TRANSFER = 0  #: Eq. 12: ½I0θ'₊² = ½I0θ'₋² + U_r(θ_max)
RUPTURE_VELOCITY_CONTINUOUS = 1  #: θ' unchanged at rupture

COLLAPSE_END_OF_RECORD = 0  #: |θ| ≥ α at the end of the input (or |θ| reaches π/2 earlier)
COLLAPSE_FIRST_EXCEEDANCE = 1  #: |θ| reaches α at any time

STATUS_OK = 0
STATUS_EVENT_OVERFLOW = 1  #: too many events in one sample interval (Zeno chatter guard)

_EVENT_NONE = 0
_EVENT_IMPACT = 1
_EVENT_RUPTURE = 2
_EVENT_COLLAPSE = 3

#: After an impact, a velocity below REST_VELOCITY·p [rad/s] means the wall is at rest.
REST_VELOCITY = 1e-7
#: Most events tolerated in one sample interval before giving up (never seen in practice).
MAX_EVENTS_PER_INTERVAL = 100_000


@njit(cache=True, nogil=True)
def _rhs(
    theta: float, s: float, u: float, p2: float, sin_a: float, cos_a: float, k_s: float
) -> float:
    """θ'' of Eq. 10 in the regime s, ground acceleration u = ü_g/g (already scaled)."""
    st = math.sin(theta)
    ct = math.cos(theta)
    # sin(α s − θ) = s sinα cosθ − cosα sinθ ;  cos(α s − θ) = cosα cosθ + s sinα sinθ
    return -p2 * (s * sin_a * ct - cos_a * st + u * (cos_a * ct + s * sin_a * st) + k_s * st)


@njit(cache=True, nogil=True)
def _rk4(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    um: float,
    u1: float,
    s: float,
    p2: float,
    sin_a: float,
    cos_a: float,
    k_s: float,
) -> tuple[float, float]:
    """One classical RK4 step of length h; u0, um, u1: ground acceleration at 0, h/2, h."""
    a1 = _rhs(theta, s, u0, p2, sin_a, cos_a, k_s)
    w2 = omega + 0.5 * h * a1
    a2 = _rhs(theta + 0.5 * h * omega, s, um, p2, sin_a, cos_a, k_s)
    w3 = omega + 0.5 * h * a2
    a3 = _rhs(theta + 0.5 * h * w2, s, um, p2, sin_a, cos_a, k_s)
    w4 = omega + h * a3
    a4 = _rhs(theta + h * w3, s, u1, p2, sin_a, cos_a, k_s)
    theta1 = theta + h / 6.0 * (omega + 2.0 * w2 + 2.0 * w3 + w4)
    omega1 = omega + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    return theta1, omega1


@njit(cache=True, nogil=True)
def _cubic(c0: float, c1: float, c2: float, c3: float, u: float) -> float:
    return c0 + u * (c1 + u * (c2 + u * c3))


@njit(cache=True, nogil=True)
def _critical_points(c1: float, c2: float, c3: float) -> tuple[float, float]:
    """Roots in (0, 1) of the derivative c1 + 2c2·u + 3c3·u², sorted; −1 where absent."""
    r1 = -1.0
    r2 = -1.0
    qa = 3.0 * c3
    qb = 2.0 * c2
    qc = c1
    if abs(qa) <= 1e-14 * (abs(qb) + abs(qc)):
        if qb != 0.0:
            r = -qc / qb
            if 0.0 < r < 1.0:
                r1 = r
        return r1, r2
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return r1, r2
    sq = math.sqrt(disc)
    # numerically stable quadratic roots
    q = -0.5 * (qb + math.copysign(sq, qb))
    x1 = q / qa
    x2 = qc / q if q != 0.0 else x1
    lo = min(x1, x2)
    hi = max(x1, x2)
    if 0.0 < lo < 1.0:
        r1 = lo
        if 0.0 < hi < 1.0 and hi > lo:
            r2 = hi
    elif 0.0 < hi < 1.0:
        r1 = hi
    return r1, r2


@njit(cache=True, nogil=True)
def _crossing_in_piece(
    c0: float, c1: float, c2: float, c3: float, ua: float, ub: float, level: float, up: bool
) -> float:
    """Crossing of ``level`` inside [ua, ub], where the cubic is monotone, or −1."""
    ya = _cubic(c0, c1, c2, c3, ua) - level
    yb = _cubic(c0, c1, c2, c3, ub) - level
    hit = (ya < 0.0 and yb >= 0.0) if up else (ya > 0.0 and yb <= 0.0)
    if not hit:
        return -1.0
    lo = ua
    hi = ub
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        ym = _cubic(c0, c1, c2, c3, mid) - level
        if (ym >= 0.0) == up:
            hi = mid
        else:
            lo = mid
        if hi - lo < 1e-9:  # a starting guess: Newton on the RK4 step does the rest
            break
    return hi


@njit(cache=True, nogil=True)
def _first_crossing(
    c0: float, c1: float, c2: float, c3: float, r1: float, r2: float, level: float, up: bool
) -> float:
    """First u in (0, 1] where the cubic crosses ``level`` (upwards if ``up``), or −1.

    The cubic is monotone between the breakpoints 0, r1, r2, 1 (r1 < r2; −1 where absent),
    so the first piece whose ends straddle the level holds the first crossing.
    """
    start = 0.0
    if r1 > 0.0:
        u = _crossing_in_piece(c0, c1, c2, c3, start, r1, level, up)
        if u >= 0.0:
            return u
        start = r1
    if r2 > 0.0:
        u = _crossing_in_piece(c0, c1, c2, c3, start, r2, level, up)
        if u >= 0.0:
            return u
        start = r2
    return _crossing_in_piece(c0, c1, c2, c3, start, 1.0, level, up)


@njit(cache=True, nogil=True)
def simulate_kernel(
    acc: np.ndarray,
    dt: float,
    scale: float,
    n_tail: int,
    nsub: int,
    g: float,
    p2: float,
    alpha: float,
    one_sided: bool,
    bar_mode: int,
    k_bar: float,
    theta_max: float,
    lever_over_height: float,
    e_impact: float,
    rupture_mode: int,
    collapse_mode: int,
    theta0: float,
    omega0: float,
    record_history: bool,
    hist_theta: np.ndarray,
    hist_omega: np.ndarray,
    hist_strain: np.ndarray,
    rupture_time: np.ndarray,
    rupture_side: np.ndarray,
) -> tuple[int, bool, float, float, int, int, float, float]:
    """Integrate Eq. 10 over the record (plus ``n_tail`` zero samples).

    Args:
        acc: ground acceleration samples [m/s²] (unscaled), first at t = 0.
        dt: sampling interval [s].
        scale: IDA multiplier C applied to ``acc``.
        n_tail: number of zero samples appended (free-vibration tail).
        nsub: RK4 sub-steps per sample interval.
        g: gravity [m/s²].
        p2: p² [1/s²].
        alpha: slenderness α [rad].
        one_sided: only θ ≥ 0, rebound at θ = 0.
        bar_mode: BAR_NONE, BAR_SHARED (centred) or BAR_PER_SIDE (external).
        k_bar: K of Eq. 10 (while the acting bar is intact).
        theta_max: rupture rotation θ_max [rad] (``inf`` = never).
        lever_over_height: b_r/H, for the bar strain 2·(b_r/H)·sin(|θ|/2).
        e_impact: velocity ratio |θ'₊/θ'₋| at an impact.
        rupture_mode: RUPTURE_ENERGY_TRANSFER or RUPTURE_VELOCITY_CONTINUOUS.
        collapse_mode: COLLAPSE_END_OF_RECORD or COLLAPSE_FIRST_EXCEEDANCE.
        theta0, omega0: initial state [rad], [rad/s] (both 0: at rest).
        record_history: fill hist_* at every sample.
        hist_theta, hist_omega, hist_strain: outputs, length len(acc) + n_tail (if recording).
        rupture_time, rupture_side: outputs of length ≥ 2.

    Returns:
        (status, collapsed, collapse_time [s] or NaN, peak |θ| [rad], impacts, ruptures,
        final θ [rad], final θ' [rad/s])
    """
    n_rec = acc.shape[0]
    n_total = n_rec + n_tail
    sin_a = math.sin(alpha)
    cos_a = math.cos(alpha)
    tan_a = sin_a / cos_a
    p = math.sqrt(p2)
    omega_rest = REST_VELOCITY * p
    collapse_level = alpha if collapse_mode == COLLAPSE_FIRST_EXCEEDANCE else 0.5 * math.pi
    # energy handed to the wall by a rupture (Eq. 12), per unit I0, times 2
    rupture_boost = 2.0 * p2 * k_bar * (1.0 - math.cos(theta_max)) if bar_mode != BAR_NONE else 0.0
    h_sub = dt / nsub
    inv_g = scale / g

    theta = theta0
    omega = omega0
    resting = theta0 == 0.0 and omega0 == 0.0
    s = 1.0
    if theta0 < 0.0 or (theta0 == 0.0 and omega0 < 0.0):
        s = -1.0
    # intact[0]: bar acting for s = +1, intact[1]: for s = -1
    intact_pos = bar_mode != BAR_NONE
    intact_neg = bar_mode != BAR_NONE

    peak = abs(theta)
    n_impacts = 0
    n_ruptures = 0
    collapsed = False
    collapse_time = math.nan
    last_alpha_up = math.nan
    status = STATUS_OK

    if record_history:
        hist_theta[0] = theta
        hist_omega[0] = omega
        hist_strain[0] = 0.0
        for k in range(1, n_total):
            hist_theta[k] = math.nan
            hist_omega[k] = math.nan
            hist_strain[k] = math.nan

    done = False
    for i in range(n_total - 1):
        t_i = i * dt
        ua = acc[i] * inv_g if i < n_rec else 0.0
        ub = acc[i + 1] * inv_g if i + 1 < n_rec else 0.0
        slope = (ub - ua) / dt  # [g/s]
        x = 0.0
        events = 0
        for j in range(nsub):
            x_end = dt if j == nsub - 1 else (j + 1) * h_sub
            while x < x_end:
                events += 1
                if events > MAX_EVENTS_PER_INTERVAL:
                    status = STATUS_EVENT_OVERFLOW
                    done = True
                    break
                if resting:
                    # uplift: ü_g/g < -tan α starts s = +1; (two-sided) > tan α starts s = -1
                    ux = ua + slope * x
                    ue = ua + slope * x_end
                    if ux < -tan_a:
                        resting = False
                        s = 1.0
                    elif (not one_sided) and ux > tan_a:
                        resting = False
                        s = -1.0
                    elif ue < -tan_a:
                        x = x + (-tan_a - ux) / slope
                        resting = False
                        s = 1.0
                    elif (not one_sided) and ue > tan_a:
                        x = x + (tan_a - ux) / slope
                        resting = False
                        s = -1.0
                    else:
                        x = x_end
                    if not resting:
                        theta = 0.0
                        omega = 0.0
                    continue

                # --- rocking: trial RK4 step from x to x_end -----------------------------
                hh = x_end - x
                bar_on = intact_pos if s > 0.0 else intact_neg
                k_s = k_bar if bar_on else 0.0
                u0 = ua + slope * x
                um = ua + slope * (x + 0.5 * hh)
                u1 = ua + slope * x_end
                th1, om1 = _rk4(theta, omega, hh, u0, um, u1, s, p2, sin_a, cos_a, k_s)

                # Hermite cubic of y = s·θ on the step, in u ∈ [0, 1]
                y0 = s * theta
                y1 = s * th1
                m0 = s * omega * hh
                m1 = s * om1 * hh
                c0 = y0
                c1 = m0
                c2 = 3.0 * (y1 - y0) - 2.0 * m0 - m1
                c3 = 2.0 * (y0 - y1) + m0 + m1
                r1, r2 = _critical_points(c1, c2, c3)
                ymin = min(y0, y1)
                ymax = max(y0, y1)
                if r1 > 0.0:
                    yr = _cubic(c0, c1, c2, c3, r1)
                    ymin = min(ymin, yr)
                    ymax = max(ymax, yr)
                if r2 > 0.0:
                    yr = _cubic(c0, c1, c2, c3, r2)
                    ymin = min(ymin, yr)
                    ymax = max(ymax, yr)

                event = _EVENT_NONE
                u_event = 2.0
                level = 0.0
                if ymin <= 0.0:
                    ue_ = _first_crossing(c0, c1, c2, c3, r1, r2, 0.0, False)
                    if ue_ >= 0.0:
                        event = _EVENT_IMPACT
                        u_event = ue_
                        level = 0.0
                if bar_on and ymax >= theta_max:
                    ue_ = _first_crossing(c0, c1, c2, c3, r1, r2, theta_max, True)
                    if ue_ >= 0.0 and ue_ < u_event:
                        event = _EVENT_RUPTURE
                        u_event = ue_
                        level = theta_max
                if ymax >= collapse_level:
                    ue_ = _first_crossing(c0, c1, c2, c3, r1, r2, collapse_level, True)
                    if ue_ >= 0.0 and ue_ < u_event:
                        event = _EVENT_COLLAPSE
                        u_event = ue_
                        level = collapse_level

                if event == _EVENT_NONE:
                    if ymax > peak:
                        peak = ymax
                    if collapse_mode == COLLAPSE_END_OF_RECORD and y0 < alpha <= y1:
                        last_alpha_up = t_i + x + hh * (alpha - y0) / (y1 - y0)
                    if y1 < 0.0:
                        # s·θ left its regime without a located crossing: only possible at
                        # round-off level right after an uplift or a rest; the wall is at rest.
                        theta = 0.0
                        omega = 0.0
                        resting = True
                    else:
                        theta = th1
                        omega = om1
                    x = x_end
                    continue

                # --- locate the event on the integrator: Newton on the step length τ -------
                tau = u_event * hh
                th_e = th1
                om_e = om1
                for _ in range(30):
                    um_e = ua + slope * (x + 0.5 * tau)
                    u1_e = ua + slope * (x + tau)
                    th_e, om_e = _rk4(theta, omega, tau, u0, um_e, u1_e, s, p2, sin_a, cos_a, k_s)
                    resid = s * th_e - level
                    if abs(resid) <= 1e-13:
                        break
                    slope_y = s * om_e
                    if slope_y == 0.0:
                        break
                    tau_new = tau - resid / slope_y
                    if tau_new <= 0.0:
                        tau_new = 0.5 * tau
                    elif tau_new > hh:
                        tau_new = 0.5 * (tau + hh)
                    if abs(tau_new - tau) <= 1e-15 * hh:
                        tau = tau_new
                        break
                    tau = tau_new
                # the peak of the piece before the event
                if 0.0 < r1 < u_event:
                    peak = max(peak, _cubic(c0, c1, c2, c3, r1))
                if 0.0 < r2 < u_event:
                    peak = max(peak, _cubic(c0, c1, c2, c3, r2))
                x = x + tau
                t_event = t_i + x
                theta = s * level
                omega = om_e
                if level > peak:
                    peak = level
                if collapse_mode == COLLAPSE_END_OF_RECORD and y0 < alpha <= level:
                    last_alpha_up = t_i + x - tau + tau * (alpha - y0) / (level - y0)

                if event == _EVENT_IMPACT:
                    n_impacts += 1
                    theta = 0.0
                    if one_sided:
                        omega = -e_impact * om_e
                    else:
                        omega = e_impact * om_e
                        s = -s
                    if abs(omega) < omega_rest:
                        omega = 0.0
                        resting = True
                elif event == _EVENT_RUPTURE:
                    if n_ruptures < rupture_time.shape[0]:
                        rupture_time[n_ruptures] = t_event
                        rupture_side[n_ruptures] = int(s)
                    n_ruptures += 1
                    if bar_mode == BAR_SHARED:
                        intact_pos = False
                        intact_neg = False
                    elif s > 0.0:
                        intact_pos = False
                    else:
                        intact_neg = False
                    if rupture_mode == RUPTURE_ENERGY_TRANSFER:
                        omega = math.copysign(math.sqrt(om_e * om_e + rupture_boost), om_e)
                else:  # collapse
                    collapsed = True
                    collapse_time = t_event
                    done = True
                    break
            if done:
                break
        if record_history:
            hist_theta[i + 1] = theta
            hist_omega[i + 1] = omega
            on = intact_pos if s > 0.0 else intact_neg
            hist_strain[i + 1] = (
                2.0 * lever_over_height * math.sin(0.5 * abs(theta)) if on and not resting else 0.0
            )
        if done:
            break

    if not collapsed and collapse_mode == COLLAPSE_END_OF_RECORD and abs(theta) >= alpha:
        collapsed = True
        collapse_time = last_alpha_up
    return status, collapsed, collapse_time, peak, n_impacts, n_ruptures, theta, omega
