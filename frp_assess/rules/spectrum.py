"""The elastic response spectrum of the codes (periods [s], accelerations in g, damping ratios
as fractions): EN 1998-1:2004 §3.2.2.2 (Tables 3.2 and 3.3, Eqs. 3.2–3.6) and NTC 2018
§3.2.3.2.1 (Tabs. 3.2.IV and 3.2.V, Eqs. 3.2.2–3.2.7).

The tables and the coefficients; the spectrum object built from them, and the checks of a
project's values with their input errors, are :mod:`frp_assess.motions.spectra`.
"""

from __future__ import annotations

import math

#: EN 1998-1 Table 3.2 (type 1) and Table 3.3 (type 2): ground -> (S [-], T_B, T_C, T_D [s])
EC8_TABLE: dict[int, dict[str, tuple[float, float, float, float]]] = {
    1: {
        "A": (1.00, 0.15, 0.40, 2.0),
        "B": (1.20, 0.15, 0.50, 2.0),
        "C": (1.15, 0.20, 0.60, 2.0),
        "D": (1.35, 0.20, 0.80, 2.0),
        "E": (1.40, 0.15, 0.50, 2.0),
    },
    2: {
        "A": (1.00, 0.05, 0.25, 1.2),
        "B": (1.35, 0.05, 0.25, 1.2),
        "C": (1.50, 0.10, 0.25, 1.2),
        "D": (1.80, 0.10, 0.30, 1.2),
        "E": (1.60, 0.05, 0.25, 1.2),
    },
}

#: EN 1998-1 Eqs. (3.2)-(3.5): the plateau is 2.5·η·a_g·S
EC8_PLATEAU = 2.5

#: NTC 2018 Tab. 3.2.IV, S_S = a − b·F0·a_g/g bounded to [lo, hi]: soil -> (a, b, lo, hi)
NTC_SS_TABLE: dict[str, tuple[float, float, float, float]] = {
    "A": (1.00, 0.00, 1.00, 1.00),
    "B": (1.40, 0.40, 1.00, 1.20),
    "C": (1.70, 0.60, 1.00, 1.50),
    "D": (2.40, 1.50, 0.90, 1.80),
    "E": (2.00, 1.10, 1.00, 1.60),
}

#: NTC 2018 Tab. 3.2.IV, C_C = c·(T_C*)^e: soil -> (c, e)
NTC_CC_TABLE: dict[str, tuple[float, float]] = {
    "A": (1.00, 0.00),
    "B": (1.10, -0.20),
    "C": (1.05, -0.33),
    "D": (1.25, -0.50),
    "E": (1.15, -0.40),
}

#: NTC 2018 Tab. 3.2.V, topographic amplification S_T (the values at the top of the relief;
#: the code lets S_T decrease linearly to 1 at its base -- not modelled here)
NTC_ST: dict[str, float] = {"T1": 1.0, "T2": 1.2, "T3": 1.2, "T4": 1.4}


def eta(damping: float) -> float:
    """Damping correction factor η = √(10/(5 + ξ)) ≥ 0.55 [-], ξ in percent: ``damping`` the
    viscous damping ratio ξ [-] (0.05 for 5 %, η = 1); EN 1998-1 §3.2.2.2(3) Eq. (3.6),
    NTC 2018 §3.2.3.2.1 Eq. (3.2.4)."""
    return max(math.sqrt(10.0 / (5.0 + 100.0 * damping)), 0.55)


def s_s(soil: str, ag: float, f0: float) -> float:
    """Stratigraphic amplification S_S = a − b·F0·a_g/g within its bounds [-], NTC 2018
    Tab. 3.2.IV: ``soil`` A–E, ``ag`` a_g/g [g], ``f0`` F0 [-] (KeyError: another soil)."""
    a, b, lo, hi = NTC_SS_TABLE[soil]
    return min(max(a - b * f0 * ag, lo), hi)


def c_c(soil: str, tc_star: float) -> float:
    """C_C = c·(T_C*)^e [-] of T_C = C_C·T_C*, NTC 2018 Tab. 3.2.IV: ``soil`` A–E, ``tc_star``
    T_C* [s] (KeyError: another soil)."""
    c, e = NTC_CC_TABLE[soil]
    return float(c * tc_star**e)  # float ** float is typed Any


def s_t(topography: str) -> float:
    """Topographic amplification S_T [-] of a category T1–T4, NTC 2018 Tab. 3.2.V
    (KeyError: another category)."""
    return NTC_ST[topography]


def t_c(c_c_value: float, tc_star: float) -> float:
    """T_C = C_C·T_C* [s], NTC 2018 Eq. (3.2.6): C_C [-], T_C* [s]."""
    return c_c_value * tc_star


def t_b(t_c_value: float) -> float:
    """T_B = T_C/3 [s], NTC 2018 Eq. (3.2.5): T_C [s]."""
    return t_c_value / 3.0


def t_d(ag: float) -> float:
    """T_D = 4·a_g/g + 1.6 [s], NTC 2018 Eq. (3.2.7): a_g/g [g]."""
    return 4.0 * ag + 1.6
