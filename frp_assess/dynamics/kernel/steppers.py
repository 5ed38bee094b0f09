"""One step of Eq. 10 on (θ, θ'): the right-hand side, Dormand–Prince 5(4) and classical RK4.

Inside a step the ground acceleration is linear, u(τ) = u0 + slope·τ (in g), because steps
never cross a record sample.  The sign regime s = sgn θ and the bar term K_s are frozen for
the step: the events that change them are located by :mod:`.events` and the step restarts.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.params import METHOD_BS3, METHOD_DOPRI5, KernelParams


@njit(cache=True, nogil=True)
def acceleration(theta: float, s: float, u: float, k_s: float, prm: KernelParams) -> float:
    """θ'' of Eq. 10 with the base reaction [rad/s²] in the regime s, ground acceleration
    u = ü_g/g (scaled):

        θ'' = −p²·[sin(αs − θ) + u·cos(αs − θ) + K_s·sin θ − s·ξ·n²·cos θ],
        n = 1 + κ_s·sin(|θ|/2),  κ_s = K_s·κ/K   (docs/model.md §1.1)

    With the edge pivot (ξ = 0) the reaction term is skipped: the paper's Eq. 10 bit for bit.
    """
    sin_a = prm.sin_a
    cos_a = prm.cos_a
    if prm.xi != 0.0 and k_s != 0.0:
        # the bar force needs sin(|θ|/2) = s·sin(θ/2) (smooth across θ = 0 inside a step that
        # overshoots an impact before it is located): one sin/cos pair of θ/2 gives it and
        # sin θ, cos θ by the double-angle formulas, where √ and a division were needed
        sh = math.sin(0.5 * theta)
        ch = math.cos(0.5 * theta)
        st = 2.0 * sh * ch
        ct = 1.0 - 2.0 * sh * sh
        n = 1.0 + k_s * prm.kappa_per_k * s * sh
        # sin(α s − θ) = s sinα cosθ − cosα sinθ ;  cos(α s − θ) = cosα cosθ + s sinα sinθ
        m = s * sin_a * ct - cos_a * st + u * (cos_a * ct + s * sin_a * st) + k_s * st
        return -prm.p2 * (m - s * prm.xi * n * n * ct)
    st = math.sin(theta)
    ct = math.cos(theta)
    m = s * sin_a * ct - cos_a * st + u * (cos_a * ct + s * sin_a * st) + k_s * st
    if prm.xi != 0.0:  # no bar force: n = 1
        m -= s * prm.xi * ct
    return -prm.p2 * m


#: The error norm measures θ against ERROR_FLOOR·α + |θ| and θ' against ERROR_FLOOR·p·α + |θ'|:
#: relative down to rocking a thousand times smaller than α, so small-amplitude rocking between
#: impacts is resolved too (with the floor at α it was not: docs/model.md §4).
ERROR_FLOOR = 1e-3


@njit(cache=True, nogil=True)
def error_norm(
    theta: float,
    omega: float,
    theta1: float,
    omega1: float,
    err_t: float,
    err_w: float,
    prm: KernelParams,
) -> float:
    """Local error of a step in units of the tolerance (≤ 1 accepts the step)."""
    scale_t = prm.tolerance * (ERROR_FLOOR * prm.alpha + max(abs(theta), abs(theta1)))
    scale_w = prm.tolerance * (ERROR_FLOOR * prm.p * prm.alpha + max(abs(omega), abs(omega1)))
    return max(abs(err_t) / scale_t, abs(err_w) / scale_w)


# Dormand & Prince (1980), "A family of embedded Runge-Kutta formulae", J. Comp. Appl. Math.
# 6(1):19-26, the RK5(4)7M pair (as in Hairer, Nørsett & Wanner, Solving ODEs I, Table 5.2).
_C2, _C3, _C4, _C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
_A21 = 1.0 / 5.0
_A31, _A32 = 3.0 / 40.0, 9.0 / 40.0
_A41, _A42, _A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
_A51, _A52, _A53, _A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
_A61, _A62, _A63 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0
_A64, _A65 = 49.0 / 176.0, -5103.0 / 18656.0
_B1, _B3, _B4, _B5, _B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
# error coefficients: 5th-order weights minus the embedded 4th-order ones
_E1, _E3, _E4 = -71.0 / 57600.0, 71.0 / 16695.0, -71.0 / 1920.0
_E5, _E6, _E7 = 17253.0 / 339200.0, -22.0 / 525.0, 1.0 / 40.0


@njit(cache=True, nogil=True)
def dopri5(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One Dormand–Prince step of length h [s] from (θ, θ'), with a1 = θ'' at the start.

    Returns (θ, θ', θ'' at the end, error norm): the 5th-order solution (local
    extrapolation), the end acceleration (the first stage of the next step, FSAL), and the
    estimated local error of the embedded 4th-order solution in units of the tolerance
    (:func:`error_norm`).
    """
    w1 = omega
    t2 = theta + h * _A21 * w1
    w2 = omega + h * _A21 * a1
    a2 = acceleration(t2, s, u0 + slope * _C2 * h, k_s, prm)
    t3 = theta + h * (_A31 * w1 + _A32 * w2)
    w3 = omega + h * (_A31 * a1 + _A32 * a2)
    a3 = acceleration(t3, s, u0 + slope * _C3 * h, k_s, prm)
    t4 = theta + h * (_A41 * w1 + _A42 * w2 + _A43 * w3)
    w4 = omega + h * (_A41 * a1 + _A42 * a2 + _A43 * a3)
    a4 = acceleration(t4, s, u0 + slope * _C4 * h, k_s, prm)
    t5 = theta + h * (_A51 * w1 + _A52 * w2 + _A53 * w3 + _A54 * w4)
    w5 = omega + h * (_A51 * a1 + _A52 * a2 + _A53 * a3 + _A54 * a4)
    a5 = acceleration(t5, s, u0 + slope * _C5 * h, k_s, prm)
    t6 = theta + h * (_A61 * w1 + _A62 * w2 + _A63 * w3 + _A64 * w4 + _A65 * w5)
    w6 = omega + h * (_A61 * a1 + _A62 * a2 + _A63 * a3 + _A64 * a4 + _A65 * a5)
    a6 = acceleration(t6, s, u0 + slope * h, k_s, prm)
    theta1 = theta + h * (_B1 * w1 + _B3 * w3 + _B4 * w4 + _B5 * w5 + _B6 * w6)
    omega1 = omega + h * (_B1 * a1 + _B3 * a3 + _B4 * a4 + _B5 * a5 + _B6 * a6)
    a7 = acceleration(theta1, s, u0 + slope * h, k_s, prm)
    w7 = omega1
    err_t = h * (_E1 * w1 + _E3 * w3 + _E4 * w4 + _E5 * w5 + _E6 * w6 + _E7 * w7)
    err_w = h * (_E1 * a1 + _E3 * a3 + _E4 * a4 + _E5 * a5 + _E6 * a6 + _E7 * a7)
    return theta1, omega1, a7, error_norm(theta, omega, theta1, omega1, err_t, err_w, prm)


# Bogacki & Shampine (1989), "A 3(2) pair of Runge-Kutta formulas", Appl. Math. Lett.
# 2(4):321-325 (FSAL; the 3rd-order solution is kept).
_BS_E1, _BS_E2, _BS_E3, _BS_E4 = -5.0 / 72.0, 1.0 / 12.0, 1.0 / 9.0, -1.0 / 8.0


@njit(cache=True, nogil=True)
def bs3(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One Bogacki–Shampine 3(2) step (same signature and returns as :func:`dopri5`)."""
    w1 = omega
    t2 = theta + 0.5 * h * w1
    w2 = omega + 0.5 * h * a1
    a2 = acceleration(t2, s, u0 + slope * 0.5 * h, k_s, prm)
    t3 = theta + 0.75 * h * w2
    w3 = omega + 0.75 * h * a2
    a3 = acceleration(t3, s, u0 + slope * 0.75 * h, k_s, prm)
    theta1 = theta + h * (2.0 / 9.0 * w1 + 1.0 / 3.0 * w2 + 4.0 / 9.0 * w3)
    omega1 = omega + h * (2.0 / 9.0 * a1 + 1.0 / 3.0 * a2 + 4.0 / 9.0 * a3)
    a4 = acceleration(theta1, s, u0 + slope * h, k_s, prm)
    w4 = omega1
    err_t = h * (_BS_E1 * w1 + _BS_E2 * w2 + _BS_E3 * w3 + _BS_E4 * w4)
    err_w = h * (_BS_E1 * a1 + _BS_E2 * a2 + _BS_E3 * a3 + _BS_E4 * a4)
    return theta1, omega1, a4, error_norm(theta, omega, theta1, omega1, err_t, err_w, prm)


@njit(cache=True, nogil=True)
def rk4(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One classical RK4 step (same signature as :func:`dopri5`; no end acceleration, no error)."""
    um = u0 + slope * 0.5 * h
    w2 = omega + 0.5 * h * a1
    a2 = acceleration(theta + 0.5 * h * omega, s, um, k_s, prm)
    w3 = omega + 0.5 * h * a2
    a3 = acceleration(theta + 0.5 * h * w2, s, um, k_s, prm)
    w4 = omega + h * a3
    a4 = acceleration(theta + h * w3, s, u0 + slope * h, k_s, prm)
    theta1 = theta + h / 6.0 * (omega + 2.0 * w2 + 2.0 * w3 + w4)
    omega1 = omega + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    return theta1, omega1, math.nan, 0.0


@njit(cache=True, nogil=True)
def step(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One step of the method chosen in ``prm`` (see :func:`dopri5` for the returns)."""
    if prm.method == METHOD_DOPRI5:
        return dopri5(theta, omega, h, u0, slope, s, k_s, a1, prm)
    if prm.method == METHOD_BS3:
        return bs3(theta, omega, h, u0, slope, s, k_s, a1, prm)
    return rk4(theta, omega, h, u0, slope, s, k_s, a1, prm)
