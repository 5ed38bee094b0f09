"""Events inside an accepted step: bracketed on the step's dense output, located on the integrator.

The dense output of a step is the cubic Hermite interpolant of y = s·θ through both ends
(values θ and slopes θ' of the 5th-order solution).  It is monotone between its critical
points, so the *first* crossing of a level is found exactly on the cubic; that bracket is then
refined on the integrator itself — Newton iterations on the length τ of one step taken from
the start of the step — until the Newton correction of the instant is below
EVENT_TIME_TOLERANCE of the step.  The state returned is the integrator's, never the
interpolant's.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import (
    EVENT_ITERATIONS,
    EVENT_TIME_TOLERANCE,
    METHOD_RK4,
    KernelParams,
)
from frp_assess.dynamics.kernel.steppers import acceleration, step

#: The crossing on the cubic is found to this fraction of the step: Newton on the integrator
#: does the rest.
_BRACKET_FRACTION = 1e-9
#: Iterations allowed on the cubic (Newton inside a bracket: in practice a handful).
_CUBIC_ITERATIONS = 60
#: Newton's last correction δ on the integrator is taken on the local Taylor cubic of the
#: integrator's own step (θ, θ', θ'' at its end, the jerk from the step's mean) when
#: |δ| ≤ _TAYLOR_REACH·h: the truncation error, about θ⁗·h·δ²/4 in θ', is then far below
#: the integration tolerance, and one integrator step per event is saved.
_TAYLOR_REACH = 1e-4


@njit(cache=True, nogil=True)
def hermite(y0: float, y1: float, m0: float, m1: float) -> tuple[float, float, float, float]:
    """Coefficients of the cubic through (0, y0) and (1, y1) with slopes m0, m1 (per unit u)."""
    return y0, m0, 3.0 * (y1 - y0) - 2.0 * m0 - m1, 2.0 * (y0 - y1) + m0 + m1


@njit(cache=True, nogil=True)
def cubic(c0: float, c1: float, c2: float, c3: float, u: float) -> float:
    return c0 + u * (c1 + u * (c2 + u * c3))


@njit(cache=True, nogil=True)
def critical_points(c1: float, c2: float, c3: float) -> tuple[float, float]:
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
    q = -0.5 * (qb + math.copysign(sq, qb))  # numerically stable quadratic roots
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
    """Crossing of ``level`` inside [ua, ub], where the cubic is monotone, or −1.

    Newton's method on the cubic kept inside the bracket (a bisection where it would leave
    it), to _BRACKET_FRACTION: a few iterations where bisection took thirty.
    """
    ya = cubic(c0, c1, c2, c3, ua) - level
    yb = cubic(c0, c1, c2, c3, ub) - level
    hit = (ya < 0.0 and yb >= 0.0) if up else (ya > 0.0 and yb <= 0.0)
    if not hit:
        return -1.0
    lo = ua
    hi = ub
    u = ua + (ub - ua) * ya / (ya - yb)  # the secant: inside [ua, ub]
    for _ in range(_CUBIC_ITERATIONS):
        f = cubic(c0, c1, c2, c3, u) - level
        if (f >= 0.0) == up:
            hi = u
        else:
            lo = u
        if hi - lo <= _BRACKET_FRACTION:
            return hi
        df = c1 + u * (2.0 * c2 + 3.0 * c3 * u)
        u_new = u - f / df if df != 0.0 else -1.0
        if not lo < u_new < hi:
            u_new = 0.5 * (lo + hi)
        if abs(u_new - u) <= _BRACKET_FRACTION:
            return u_new
        u = u_new
    return hi


@njit(cache=True, nogil=True)
def first_crossing(
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
def _newton_step(tau: float, f: float, df: float, h: float) -> float:
    """Newton's next step length τ − f/f' kept inside (0, h]: a step that would leave the
    interval goes halfway to the end it points at instead."""
    tau_new = tau - f / df
    if tau_new <= 0.0:
        return 0.5 * tau
    if tau_new > h:
        return 0.5 * (tau + h)
    return tau_new


@njit(cache=True, nogil=True)
def _taylor_level(
    th_e: float,
    om_e: float,
    a_e: float,
    jerk: float,
    s: float,
    level: float,
    reach: float,
    h: float,
) -> tuple[bool, float, float]:
    """Solve s·(θ + θ'·δ + θ''·δ²/2 + j·δ³/6) = level for a small δ [s] by Newton from 0.

    Returns (found: |δ| ≤ reach and the last Newton correction ≤ EVENT_TIME_TOLERANCE·h, δ,
    θ' at δ).
    """
    d = 0.0
    for _ in range(4):
        g = s * (th_e + d * (om_e + d * (0.5 * a_e + d * jerk / 6.0))) - level
        dg = s * (om_e + d * (a_e + 0.5 * jerk * d))
        if dg == 0.0:
            return False, 0.0, om_e
        d -= g / dg
        if abs(d) > reach:
            return False, 0.0, om_e
    g = s * (th_e + d * (om_e + d * (0.5 * a_e + d * jerk / 6.0))) - level
    dg = s * (om_e + d * (a_e + 0.5 * jerk * d))
    if not abs(g) <= EVENT_TIME_TOLERANCE * h * abs(dg):
        return False, 0.0, om_e
    return True, d, om_e + d * (a_e + 0.5 * jerk * d)


@njit(cache=True, nogil=True)
def locate_level(
    theta: float,
    omega: float,
    a1: float,
    h: float,
    tau: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    level: float,
    prm: KernelParams,
) -> tuple[float, float, float]:
    """Step length τ ∈ (0, h] at which s·θ reaches ``level``, starting from the guess ``tau``.

    Newton on τ with one integrator step from (θ, θ') per iteration (slope s·θ').  With an
    adaptive method the last correction, once it is below _TAYLOR_REACH·h, is taken on the
    Taylor cubic of the integrator's step (:func:`_taylor_level`) instead of another step.
    Returns (τ, θ' there, s·θ there − level).
    """
    om_e = omega
    resid = math.nan
    taylor = prm.method != METHOD_RK4
    for _ in range(EVENT_ITERATIONS):
        th_e, om_e, a_e, _err = step(theta, omega, tau, u0, slope, s, k_s, t0, t1, a1, prm)
        resid = s * th_e - level
        dy = s * om_e
        # converged when the instant is known to EVENT_TIME_TOLERANCE·h (θ' there to
        # θ''·that): a bound on θ alone would let a slow crossing's instant drift
        if abs(resid) <= EVENT_TIME_TOLERANCE * h * abs(dy) or resid == 0.0:
            break
        if dy == 0.0:
            break
        if taylor and tau > 0.0:
            found, d, om_d = _taylor_level(
                th_e, om_e, a_e, (a_e - a1) / tau, s, level, _TAYLOR_REACH * h, h
            )
            if found and 0.0 < tau + d <= h:
                return tau + d, om_d, 0.0
        tau_new = _newton_step(tau, resid, dy, h)
        if abs(tau_new - tau) <= 1e-15 * h:
            tau = tau_new
            break
        tau = tau_new
    return tau, om_e, resid


@njit(cache=True, nogil=True, inline="always")
def _end_state(
    theta: float,
    omega: float,
    a1: float,
    tau: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    prm: KernelParams,
) -> tuple[float, float, float]:
    """(θ, θ', θ'') after one integrator step of τ [s]: the searches for θ' = 0
    (:func:`turning_point`, :func:`locate_turn`) take the slope θ'' from it (evaluated when
    the method gives no end acceleration, RK4)."""
    th_e, om_e, a_e, _err = step(theta, omega, tau, u0, slope, s, k_s, t0, t1, a1, prm)
    if math.isnan(a_e):
        a_e = acceleration(th_e, s, u0 + slope * tau, k_s, t0, t1, prm)
    return th_e, om_e, a_e


@njit(cache=True, nogil=True)
def turning_point(
    theta: float,
    omega: float,
    a1: float,
    h: float,
    tau: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    prm: KernelParams,
) -> float:
    """s·θ at the turning point (θ' = 0) inside the step, from the guess ``tau``.

    Newton on τ with one integrator step per iteration (slope θ'' at the end of the step);
    with an adaptive method the last correction below _TAYLOR_REACH·h is taken on the Taylor
    cubic of the integrator's step, as in :func:`locate_level`.
    """
    best = s * theta
    taylor = prm.method != METHOD_RK4
    for _ in range(EVENT_ITERATIONS):
        th_e, om_e, a_e = _end_state(theta, omega, a1, tau, u0, slope, s, k_s, t0, t1, prm)
        best = max(best, s * th_e)
        if a_e == 0.0:
            break
        if taylor and tau > 0.0:
            d = -om_e / a_e
            if abs(d) <= _TAYLOR_REACH * h and 0.0 < tau + d <= h:
                # θ' = 0 on the Taylor quadratic of θ': one more Newton step on it
                jerk = (a_e - a1) / tau
                d -= (om_e + d * (a_e + 0.5 * jerk * d)) / (a_e + jerk * d)
                return max(best, s * (th_e + d * (om_e + d * (0.5 * a_e + d * jerk / 6.0))))
        tau_new = _newton_step(tau, om_e, a_e, h)
        if abs(tau_new - tau) <= 1e-13 * h:
            break
        tau = tau_new
    return best


@njit(cache=True, nogil=True)
def locate_turn(
    theta: float,
    omega: float,
    a1: float,
    h: float,
    tau: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    prm: KernelParams,
) -> tuple[float, float]:
    """Step length τ ∈ (0, h] at which θ' = 0 (the turning point where a yielding tie unloads,
    docs/model.md §12), from the guess ``tau``: (τ, s·θ there).

    Newton on τ with one integrator step per iteration (slope θ'' at the end of the step),
    until the correction of the instant is below EVENT_TIME_TOLERANCE of the step, as for
    :func:`locate_level`; the state is the integrator's.
    """
    th_e = theta
    for _ in range(EVENT_ITERATIONS):
        th_e, om_e, a_e = _end_state(theta, omega, a1, tau, u0, slope, s, k_s, t0, t1, prm)
        if abs(om_e) <= EVENT_TIME_TOLERANCE * h * abs(a_e) or a_e == 0.0:
            break
        tau_new = _newton_step(tau, om_e, a_e, h)
        if abs(tau_new - tau) <= 1e-15 * h:
            tau = tau_new
            break
        tau = tau_new
    return tau, s * th_e
