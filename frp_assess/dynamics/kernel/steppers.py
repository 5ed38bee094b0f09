"""One step of Eq. 10 on (θ, θ'): the right-hand side, Dormand–Prince 5(4) and classical RK4.

Inside a step the ground acceleration is linear, u(τ) = u0 + slope·τ (in g), because steps
never cross a record sample.  The sign regime s = sgn θ and the bar term K_s are frozen for
the step: the events that change them are located by :mod:`.events` and the step restarts.
"""

from __future__ import annotations

import math
from fractions import Fraction

from numba import njit

from frp_assess.dynamics.kernel.inlining import into
from frp_assess.dynamics.kernel.params import METHOD_BS3, METHOD_DOPRI5, KernelParams
from frp_assess.dynamics.kernel.trig import sin_cos


@njit(cache=True, nogil=True, inline="always")
def side_terms(s: float, prm: KernelParams) -> tuple[float, float, float, float, float]:
    """(p²_s, a0_s, a1_s, b0_s, b1_s) of the side s (:class:`.params.KernelParams`)."""
    if s > 0.0:
        return prm.p2_pos, prm.a0_pos, prm.a1_pos, prm.b0_pos, prm.b1_pos
    return prm.p2_neg, prm.a0_neg, prm.a1_neg, prm.b0_neg, prm.b1_neg


@njit(cache=True, nogil=True)
def acceleration(
    theta: float, s: float, u: float, k_s: float, t0: float, t1: float, prm: KernelParams
) -> float:
    """θ'' of Eq. 10 with the base reaction and the loads [rad/s²] in the regime s, ground
    acceleration u = ü_g/g (scaled):

        θ'' = −p²_s·[(a0_s + u·a1_s − s·ξ·n²)·cos θ + (K_s + b0_s + u·b1_s)·sin θ
                     + (t0 + t1·sin θ)·cos θ],
        n = 1 + κ_s·sin(|θ|/2),  κ_s = K_s·κ/K   (docs/model.md §1.1, §12)

    (the last term the tie's moment over W·R in the regime, :func:`.state.tie_terms`), which
    without loads and ties is −p²·[sin(αs − θ) + u·cos(αs − θ) + K_s·sin θ − s·ξ·n²·cos θ].
    With the edge pivot (ξ = 0) the reaction term is skipped: the paper's Eq. 10 bit for bit.
    """
    p2, a0, a1, b0, b1 = side_terms(s, prm)
    return _rhs(theta, s, u, k_s, t0, t1, p2, a0, a1, b0, b1, prm.xi, prm.kappa_per_k)


@njit(cache=True, nogil=True, inline=into("dopri5"))
def _rhs(
    theta: float,
    s: float,
    u: float,
    k_s: float,
    t0: float,
    t1: float,
    p2: float,
    a0: float,
    a1: float,
    b0: float,
    b1: float,
    xi: float,
    kappa_per_k: float,
) -> float:
    """:func:`acceleration` with the side's constants as numbers.  numba inlines it into
    :func:`dopri5`, which evaluates it seven times a step (:mod:`.inlining`); the other
    callers, off the path of every step, go through :func:`acceleration`."""
    # the bracket is A·cosθ + B·sinθ with A = a0 + u·a1 − s ξ n², B = K_s + b0 + u·b1 (without
    # loads a0 = s sinα, a1 = cosα, b0 = −cosα, b1 = s sinα: sin(αs − θ) + u·cos(αs − θ)).
    # A and B do not depend on θ: they are formed while sin θ, cos θ are computed, and the
    # stage's chain of dependent operations from θ to θ'' is the shortest (docs/model.md §4.2).
    a_coef = a0 + u * a1
    b_coef = k_s + b0 + u * b1
    if t0 != 0.0 or t1 != 0.0:
        # a tie holds the wall (docs/model.md §12): its moment cos θ·(t0 + t1·sin θ) in a
        # branch of its own, so that the arithmetic of the others is unchanged
        st, ct = sin_cos(theta)
        if xi != 0.0:
            n = 1.0 + k_s * kappa_per_k * s * math.sin(0.5 * theta)
            a_coef -= s * xi * n * n
        return -p2 * ((a_coef + t0 + t1 * st) * ct + b_coef * st)
    if xi != 0.0 and k_s != 0.0:
        # the bar force needs sin(|θ|/2) = s·sin(θ/2) (smooth across θ = 0 inside a step that
        # overshoots an impact before it is located): one sin/cos pair of θ/2 gives it and
        # sin θ, cos θ by the double-angle formulas, where √ and a division were needed
        sh, ch = sin_cos(0.5 * theta)
        st = 2.0 * sh * ch
        ct = 1.0 - 2.0 * sh * sh
        n = 1.0 + k_s * kappa_per_k * s * sh
        return -p2 * ((a_coef - s * xi * n * n) * ct + b_coef * st)
    if xi != 0.0:  # no bar force: n = 1
        a_coef -= s * xi
    st, ct = sin_cos(theta)
    return (-p2 * a_coef) * ct + (-p2 * b_coef) * st


#: The error norm measures θ against ERROR_FLOOR·α + |θ| and θ' against ERROR_FLOOR·p·α + |θ'|:
#: relative down to rocking a thousand times smaller than α, so small-amplitude rocking between
#: impacts is resolved too (with the floor at α it was not: docs/model.md §4).
ERROR_FLOOR = 1e-3


@njit(cache=True, nogil=True, inline="always")
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
_DP_A: tuple[tuple[Fraction, ...], ...] = (
    (),
    (Fraction(1, 5),),
    (Fraction(3, 40), Fraction(9, 40)),
    (Fraction(44, 45), Fraction(-56, 15), Fraction(32, 9)),
    (Fraction(19372, 6561), Fraction(-25360, 2187), Fraction(64448, 6561), Fraction(-212, 729)),
    (
        Fraction(9017, 3168),
        Fraction(-355, 33),
        Fraction(46732, 5247),
        Fraction(49, 176),
        Fraction(-5103, 18656),
    ),
    # the 5th-order weights b: the seventh stage is evaluated at the new state (FSAL)
    (
        Fraction(35, 384),
        Fraction(0),
        Fraction(500, 1113),
        Fraction(125, 192),
        Fraction(-2187, 6784),
        Fraction(11, 84),
    ),
)
# the 5th-order weights minus the embedded 4th-order ones (b − b*)
_DP_E = (
    Fraction(-71, 57600),
    Fraction(0),
    Fraction(71, 16695),
    Fraction(-71, 1920),
    Fraction(17253, 339200),
    Fraction(-22, 525),
    Fraction(1, 40),
)


def _nystrom(j: int, k: int) -> float:
    """Σ_m A_jm·A_mk (stages numbered from 1): the weight of the acceleration of stage k in
    the rotation of stage j, θ_j = θ + c_j·h·θ' + h²·Σ_k Ā_jk·θ''_k.  Eq. 10's θ'' does not
    depend on θ', so the pair needs the rotations of its stages only (the Nyström form of
    the same method; Hairer, Nørsett & Wanner, Solving ODEs I, §II.14)."""
    row = _DP_A[j - 1]
    return float(sum(row[m - 1] * _DP_A[m - 1][k - 1] for m in range(k + 1, len(row) + 1)))


def _error_nystrom(k: int) -> float:
    """Σ_m E_m·A_mk: the weight of stage k's acceleration in the error of θ, h²·Σ_k Ē_k·θ''_k
    (the term in h·θ' vanishes: Σ E_m = 0)."""
    return float(sum(_DP_E[m - 1] * _DP_A[m - 1][k - 1] for m in range(k + 1, 8)))


_C2, _C3, _C4, _C5 = (float(sum(_DP_A[j])) for j in (1, 2, 3, 4))
# Ā_jk (the rotations of the stages; Ā_j,j−1 = 0: stage j needs the accelerations up to j − 2)
_N31 = _nystrom(3, 1)
_N41, _N42 = _nystrom(4, 1), _nystrom(4, 2)
_N51, _N52, _N53 = _nystrom(5, 1), _nystrom(5, 2), _nystrom(5, 3)
_N61, _N62, _N63, _N64 = _nystrom(6, 1), _nystrom(6, 2), _nystrom(6, 3), _nystrom(6, 4)
_N71, _N73, _N74, _N75 = _nystrom(7, 1), _nystrom(7, 3), _nystrom(7, 4), _nystrom(7, 5)
# the 5th-order weights of θ' and the error weights
_B1, _B3, _B4, _B5, _B6 = (float(_DP_A[6][k]) for k in (0, 2, 3, 4, 5))
_E1, _E3, _E4, _E5, _E6, _E7 = (float(_DP_E[k]) for k in (0, 2, 3, 4, 5, 6))
_F1, _F3, _F4, _F5, _F6 = (_error_nystrom(k) for k in (1, 3, 4, 5, 6))


@njit(cache=True, nogil=True, inline="always")
def dopri5(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One Dormand–Prince step of length h [s] from (θ, θ'), with a1 = θ'' at the start.

    Returns (θ, θ', θ'' at the end, error norm): the 5th-order solution (local
    extrapolation), the end acceleration (the first stage of the next step, FSAL), and the
    estimated local error of the embedded 4th-order solution in units of the tolerance
    (:func:`error_norm`).

    Written in the Nyström form (:func:`_nystrom`): the rotation of each stage is the part
    known in advance plus one product with the latest acceleration it needs, so the chain of
    dependent operations from one evaluation of θ'' to the next is as short as it can be.
    """
    hh = h * h
    p2, a0, a1c, b0, b1 = side_terms(s, prm)
    xi, kpk = prm.xi, prm.kappa_per_k
    t2 = theta + h * _C2 * omega
    a2 = _rhs(t2, s, u0 + slope * _C2 * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    t3 = (theta + h * _C3 * omega) + hh * (_N31 * a1)
    a3 = _rhs(t3, s, u0 + slope * _C3 * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    t4 = (theta + h * _C4 * omega + hh * (_N41 * a1)) + hh * (_N42 * a2)
    a4 = _rhs(t4, s, u0 + slope * _C4 * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    t5 = (theta + h * _C5 * omega + hh * (_N51 * a1 + _N52 * a2)) + hh * (_N53 * a3)
    a5 = _rhs(t5, s, u0 + slope * _C5 * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    t6 = (theta + h * omega + hh * (_N61 * a1 + _N62 * a2 + _N63 * a3)) + hh * (_N64 * a4)
    a6 = _rhs(t6, s, u0 + slope * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    theta1 = (theta + h * omega + hh * (_N71 * a1 + _N73 * a3 + _N74 * a4)) + hh * (_N75 * a5)
    omega1 = omega + h * (_B1 * a1 + _B3 * a3 + _B4 * a4 + _B5 * a5 + _B6 * a6)
    a7 = _rhs(theta1, s, u0 + slope * h, k_s, t0, t1, p2, a0, a1c, b0, b1, xi, kpk)
    err_t = hh * (_F1 * a1 + _F3 * a3 + _F4 * a4 + _F5 * a5 + _F6 * a6)
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
    t0: float,
    t1: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One Bogacki–Shampine 3(2) step (same signature and returns as :func:`dopri5`)."""
    w1 = omega
    t2 = theta + 0.5 * h * w1
    w2 = omega + 0.5 * h * a1
    a2 = acceleration(t2, s, u0 + slope * 0.5 * h, k_s, t0, t1, prm)
    t3 = theta + 0.75 * h * w2
    w3 = omega + 0.75 * h * a2
    a3 = acceleration(t3, s, u0 + slope * 0.75 * h, k_s, t0, t1, prm)
    theta1 = theta + h * (2.0 / 9.0 * w1 + 1.0 / 3.0 * w2 + 4.0 / 9.0 * w3)
    omega1 = omega + h * (2.0 / 9.0 * a1 + 1.0 / 3.0 * a2 + 4.0 / 9.0 * a3)
    a4 = acceleration(theta1, s, u0 + slope * h, k_s, t0, t1, prm)
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
    t0: float,
    t1: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One classical RK4 step (same signature as :func:`dopri5`; no end acceleration, no error)."""
    um = u0 + slope * 0.5 * h
    w2 = omega + 0.5 * h * a1
    a2 = acceleration(theta + 0.5 * h * omega, s, um, k_s, t0, t1, prm)
    w3 = omega + 0.5 * h * a2
    a3 = acceleration(theta + 0.5 * h * w2, s, um, k_s, t0, t1, prm)
    w4 = omega + h * a3
    a4 = acceleration(theta + h * w3, s, u0 + slope * h, k_s, t0, t1, prm)
    theta1 = theta + h / 6.0 * (omega + 2.0 * w2 + 2.0 * w3 + w4)
    omega1 = omega + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    return theta1, omega1, math.nan, 0.0


@njit(cache=True, nogil=True, inline=into("simulate"))
def step(
    theta: float,
    omega: float,
    h: float,
    u0: float,
    slope: float,
    s: float,
    k_s: float,
    t0: float,
    t1: float,
    a1: float,
    prm: KernelParams,
) -> tuple[float, float, float, float]:
    """One step of the method chosen in ``prm`` (see :func:`dopri5` for the returns).

    Without a tie acting (t0 = t1 = 0) Dormand–Prince is called with the constants 0.0, so the
    inlined copy has no tie branch left in its seven evaluations of Eq. 10: the tie costs the
    bare wall one test per step, not seven (docs/model.md §12)."""
    if prm.method == METHOD_DOPRI5:
        if t0 == 0.0 and t1 == 0.0:
            return dopri5(theta, omega, h, u0, slope, s, k_s, 0.0, 0.0, a1, prm)
        return dopri5(theta, omega, h, u0, slope, s, k_s, t0, t1, a1, prm)
    if prm.method == METHOD_BS3:
        return bs3(theta, omega, h, u0, slope, s, k_s, t0, t1, a1, prm)
    return rk4(theta, omega, h, u0, slope, s, k_s, t0, t1, a1, prm)
