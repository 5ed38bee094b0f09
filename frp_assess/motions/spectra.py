"""Elastic acceleration response spectra of the codes (horizontal component).

Each clause is a small function citing it; :class:`ElasticSpectrum` is the one object the
rest of the package uses.  Periods in s, accelerations in g.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

# --- EN 1998-1:2004 §3.2.2.2 ----------------------------------------------------------------

#: Table 3.2 (Type 1) and Table 3.3 (Type 2): ground type -> (S, T_B, T_C, T_D) [-, s, s, s]
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


def eta(damping: float) -> float:
    """Damping correction η = √(10/(5 + ξ)) ≥ 0.55, ξ in % (EN 1998-1 Eq. 3.6; NTC 2018 Eq. 3.2.4).

    Args:
        damping: viscous damping ratio ξ [-] (0.05 for 5 %).
    """
    return max(math.sqrt(10.0 / (5.0 + 100.0 * damping)), 0.55)


def ec8_shape(
    periods: NDArray[np.float64],
    ag_s: float,
    t_b: float,
    t_c: float,
    t_d: float,
    eta_: float,
    plateau_factor: float = 2.5,
) -> NDArray[np.float64]:
    """EN 1998-1 Eqs. 3.2–3.5: Se(T) [units of ag_s] from a_g·S, the corner periods [s], η."""
    T = np.asarray(periods, dtype=float)
    top = ag_s * eta_ * plateau_factor
    out = np.where(
        T <= t_b,
        ag_s * (1.0 + T / t_b * (eta_ * plateau_factor - 1.0)),
        np.where(
            T <= t_c,
            top,
            np.where(
                T <= t_d,
                top * t_c / np.maximum(T, 1e-12),
                top * t_c * t_d / np.maximum(T, 1e-12) ** 2,
            ),
        ),
    )
    return out


# --- NTC 2018 §3.2.3.2.1 ----------------------------------------------------------------------


def ntc_ss(soil: str, ag: float, F0: float) -> float:  # noqa: N803 - the code's symbols
    """Stratigraphic amplification S_S (NTC 2018 Tab. 3.2.IV), with its bounds; a_g in g."""
    x = F0 * ag
    rules = {
        "A": (1.0, 1.0, 1.0),
        "B": (1.40 - 0.40 * x, 1.00, 1.20),
        "C": (1.70 - 0.60 * x, 1.00, 1.50),
        "D": (2.40 - 1.50 * x, 0.90, 1.80),
        "E": (2.00 - 1.10 * x, 1.00, 1.60),
    }
    value, lo, hi = rules[soil]
    return min(max(value, lo), hi)


def ntc_cc(soil: str, tc_star: float) -> float:
    """Coefficient C_C of T_C = C_C·T_C* (NTC 2018 Tab. 3.2.IV); T_C* in s."""
    coef = {
        "A": (1.0, 0.0),
        "B": (1.10, -0.20),
        "C": (1.05, -0.33),
        "D": (1.25, -0.50),
        "E": (1.15, -0.40),
    }
    a, b = coef[soil]
    return a * tc_star**b


#: Topographic amplification S_T (NTC 2018 Tab. 3.2.V, maximum values)
NTC_ST: dict[str, float] = {"T1": 1.0, "T2": 1.2, "T3": 1.2, "T4": 1.4}


def ntc_td(ag: float) -> float:
    """T_D = 4·a_g/g + 1.6 [s] (NTC 2018 Eq. 3.2.6), a_g in g."""
    return 4.0 * ag + 1.6


# --- the spectrum object ------------------------------------------------------------------


@dataclass(frozen=True)
class ElasticSpectrum:
    """A target elastic spectrum: ``sa(T)`` in g for periods T in s."""

    name: str
    kind: str  #: "ec8" | "ntc2018" | "table" | "preset"
    pga_g: float  #: zero-period value a_g·S [g]
    T_B: float | None  # noqa: N815
    T_C: float | None  # noqa: N815
    T_D: float | None  # noqa: N815
    parameters: dict[str, object] = field(default_factory=dict)
    description: str = ""
    _fn: Callable[[NDArray[np.float64]], NDArray[np.float64]] | None = field(
        default=None, repr=False, compare=False
    )

    def sa(self, periods: ArrayLike) -> NDArray[np.float64]:
        """Spectral pseudo-acceleration Se(T) [g]."""
        assert self._fn is not None
        return self._fn(np.asarray(periods, dtype=float))


def ec8_spectrum(
    ag: float, ground: str, spectrum_type: int = 1, damping: float = 0.05
) -> ElasticSpectrum:
    """EN 1998-1 §3.2.2.2 horizontal elastic spectrum; a_g [g] is the design ground
    acceleration on type A ground (γ_I already applied)."""
    if spectrum_type not in EC8_TABLE:
        raise ValueError(f"EC8 spectrum type must be 1 or 2, got {spectrum_type!r}")
    if ground not in EC8_TABLE[spectrum_type]:
        raise ValueError(f"EC8 ground type must be one of A-E, got {ground!r}")
    S, tb, tc, td = EC8_TABLE[spectrum_type][ground]
    e = eta(damping)
    return ElasticSpectrum(
        name=f"EC8 type {spectrum_type} ground {ground} ag={ag:g}g",
        kind="ec8",
        pga_g=ag * S,
        T_B=tb,
        T_C=tc,
        T_D=td,
        parameters={
            "ag": ag,
            "ground": ground,
            "spectrum_type": spectrum_type,
            "damping": damping,
            "S": S,
        },
        description=f"EN 1998-1 §3.2.2.2, type {spectrum_type}, ground {ground}, "
        f"a_g = {ag:g} g, S = {S:g}",
        _fn=lambda T: ec8_shape(T, ag * S, tb, tc, td, e),
    )


def ntc2018_spectrum(
    ag: float,
    F0: float,
    Tc_star: float,
    soil: str,
    topography: str = "T1",
    damping: float = 0.05,  # noqa: N803
) -> ElasticSpectrum:
    """NTC 2018 §3.2.3.2.1 horizontal elastic spectrum from the site's a_g [g], F0 [-], T_C* [s]."""
    if soil not in ("A", "B", "C", "D", "E"):
        raise ValueError(f"NTC soil category must be one of A-E, got {soil!r}")
    if topography not in NTC_ST:
        raise ValueError(f"NTC topographic category must be one of T1-T4, got {topography!r}")
    ss = ntc_ss(soil, ag, F0)
    S = ss * NTC_ST[topography]
    tc = ntc_cc(soil, Tc_star) * Tc_star
    tb = tc / 3.0
    td = ntc_td(ag)
    e = eta(damping)
    return ElasticSpectrum(
        name=f"NTC 2018 ag={ag:g}g F0={F0:g} Tc*={Tc_star:g}s soil {soil} {topography}",
        kind="ntc2018",
        pga_g=ag * S,
        T_B=tb,
        T_C=tc,
        T_D=td,
        parameters={
            "ag": ag,
            "F0": F0,
            "Tc_star": Tc_star,
            "soil": soil,
            "topography": topography,
            "damping": damping,
            "S_S": ss,
            "S_T": NTC_ST[topography],
            "S": S,
        },
        description=f"NTC 2018 §3.2.3.2.1, soil {soil}, {topography}: "
        f"S = {S:.3f}, T_C = {tc:.4f} s",
        _fn=lambda T: ec8_shape(T, ag * S, tb, tc, td, e, plateau_factor=F0),
    )


#: The paper's spectra (its Fig. 7): a_g·S = 0.106 g, (T_B, T_C) [s]; plateau 2.5·a_g·S and
#: T_D = 2.0 s are assumptions (MODEL.md §6), as the paper does not state them.
PRESETS: dict[str, tuple[float, float, float]] = {
    "A1": (0.106, 0.103, 0.309),
    "A2": (0.106, 0.146, 0.437),
    "A3": (0.106, 0.130, 0.391),
}


def preset_spectrum(name: str) -> ElasticSpectrum:
    """One of the paper's spectra A1, A2, A3 (EC8 shape, η = 1)."""
    key = name.upper()
    if key not in PRESETS:
        raise ValueError(f"unknown spectrum preset {name!r}; expected one of {', '.join(PRESETS)}")
    ags, tb, tc = PRESETS[key]
    return ElasticSpectrum(
        name=key,
        kind="preset",
        pga_g=ags,
        T_B=tb,
        T_C=tc,
        T_D=2.0,
        parameters={"name": key},
        description=f"paper spectrum {key}: a_g·S = {ags} g, T_B = {tb} s, T_C = {tc} s "
        "(plateau 2.5·a_g·S and T_D = 2.0 s assumed)",
        _fn=lambda T: ec8_shape(T, ags, tb, tc, 2.0, 1.0),
    )


def table_spectrum(
    periods: ArrayLike, accelerations: ArrayLike, name: str = "table"
) -> ElasticSpectrum:
    """A user spectrum: points (T [s], Se [g]), linear in between, constant beyond the ends.

    Its zero-period value (a_g·S) is Se at the first point if that is at T = 0, else the
    linear extrapolation is *not* attempted and the first value is used."""
    T = np.asarray(periods, dtype=float)
    S = np.asarray(accelerations, dtype=float)
    if T.ndim != 1 or T.shape != S.shape or T.size < 2:
        raise ValueError("a table spectrum needs two equal-length lists of at least 2 points")
    if np.any(np.diff(T) <= 0) or T[0] < 0 or np.any(S <= 0):
        raise ValueError("table periods must increase from >= 0 and accelerations be > 0")
    return ElasticSpectrum(
        name=name,
        kind="table",
        pga_g=float(S[0]),
        T_B=None,
        T_C=None,
        T_D=None,
        parameters={"periods": T.tolist(), "accelerations": S.tolist()},
        description=f"user table of {T.size} points, T = {T[0]:g}–{T[-1]:g} s",
        _fn=lambda x: np.interp(x, T, S),
    )
