"""Horizontal elastic acceleration response spectra of the codes, and the paper's presets.

Each clause is a small pure function citing it; :class:`ElasticSpectrum` is the one object the
rest of the package (generator, compliance check, CLI, reports) uses.  Periods are in s,
spectral accelerations and a_g in g, damping ratios as fractions (0.05 for 5 %).

References:
    EN 1998-1:2004 (Eurocode 8), §3.2.2.2, Eqs. (3.2)-(3.6), Tables 3.2 and 3.3.
    NTC 2018 (D.M. 17/01/2018), §3.2.3.2.1, Eqs. (3.2.2)-(3.2.8), Tabs. 3.2.IV and 3.2.V.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frp_assess.errors import InputError
from frp_assess.motions.table_limits import check_table_range
from frp_assess.rules import spectrum as rule

# the code's tables, written once in rules/ (re-exported)
from frp_assess.rules.spectrum import EC8_PLATEAU as EC8_PLATEAU
from frp_assess.rules.spectrum import EC8_TABLE as EC8_TABLE
from frp_assess.rules.spectrum import NTC_CC_TABLE as NTC_CC_TABLE
from frp_assess.rules.spectrum import NTC_SS_TABLE as NTC_SS_TABLE
from frp_assess.rules.spectrum import NTC_ST as NTC_ST

# --- EN 1998-1:2004 §3.2.2.2 ----------------------------------------------------------------


def damping_correction(damping: float) -> float:
    """Damping correction factor η = √(10 / (5 + ξ)) ≥ 0.55 with ξ in percent [-].

    EN 1998-1 §3.2.2.2(3), Eq. (3.6); NTC 2018 §3.2.3.2.1, Eq. (3.2.4).

    Args:
        damping: viscous damping ratio ξ [-] (0.05 for 5 %, giving η = 1).
    """
    if not (math.isfinite(damping) and 0.0 <= damping < 1.0):
        raise InputError(f"damping ratio must be in [0, 1), got {damping!r}", key="damping")
    return rule.eta(damping)


def ec8_shape(
    periods: ArrayLike,
    ag_s: float,
    t_b: float,
    t_c: float,
    t_d: float,
    eta: float,
    plateau_factor: float = EC8_PLATEAU,
) -> NDArray[np.float64]:
    """The four-branch elastic shape Se(T) [units of ``ag_s``], EN 1998-1 Eqs. (3.2)-(3.5).

    With ``plateau_factor`` = F0 it is also NTC 2018 Eqs. (3.2.2) (the NTC shape).

    Args:
        periods: natural periods T ≥ 0 [s].
        ag_s: zero-period value a_g·S (NTC: a_g·S·... with S = S_S·S_T).
        t_b, t_c, t_d: corner periods [s], 0 < T_B < T_C < T_D.
        eta: damping correction η [-].
        plateau_factor: plateau amplification (2.5 in EC8, F0 in NTC) [-].
    """
    T = np.asarray(periods, dtype=float)
    top = ag_s * eta * plateau_factor
    safe = np.maximum(T, 1e-12)
    return np.where(
        T <= t_b,
        ag_s * (1.0 + T / t_b * (eta * plateau_factor - 1.0)),
        np.where(T <= t_c, top, np.where(T <= t_d, top * t_c / safe, top * t_c * t_d / safe**2)),
    )


def ec8_parameters(ground: str, spectrum_type: int = 1) -> tuple[float, float, float, float]:
    """(S [-], T_B, T_C, T_D [s]) of EN 1998-1 Table 3.2 (type 1) or Table 3.3 (type 2)."""
    if spectrum_type not in EC8_TABLE:
        raise InputError(
            f"EC8 spectrum type must be 1 or 2, got {spectrum_type!r}", key="spectrum_type"
        )
    key = str(ground).strip().upper()
    if key not in EC8_TABLE[spectrum_type]:
        raise InputError(f"EC8 ground type must be one of A-E, got {ground!r}", key="ground")
    return EC8_TABLE[spectrum_type][key]


# --- NTC 2018 §3.2.3.2.1 ----------------------------------------------------------------------


def _ntc_soil(soil: str) -> str:
    key = str(soil).strip().upper()
    if key not in NTC_SS_TABLE:
        raise InputError(f"NTC soil category must be one of A-E, got {soil!r}", key="soil")
    return key


def ntc_ss(soil: str, ag: float, F0: float) -> float:  # noqa: N803 - the code's symbols
    """Stratigraphic amplification S_S [-] with its bounds, NTC 2018 Tab. 3.2.IV.

    Args:
        soil: subsoil category A-E.
        ag: site peak acceleration on rock a_g/g [g].
        F0: maximum amplification of the spectrum [-].
    """
    return rule.s_s(_ntc_soil(soil), ag, F0)


def ntc_cc(soil: str, tc_star: float) -> float:
    """Coefficient C_C [-] of T_C = C_C·T_C*, NTC 2018 Tab. 3.2.IV; T_C* in s."""
    return rule.c_c(_ntc_soil(soil), tc_star)


def ntc_st(topography: str) -> float:
    """Topographic amplification S_T [-], NTC 2018 Tab. 3.2.V (T1 1.0, T2 1.2, T3 1.2, T4 1.4)."""
    key = str(topography).strip().upper()
    if key not in NTC_ST:
        raise InputError(
            f"NTC topographic category must be one of T1-T4, got {topography!r}",
            key="topography",
        )
    return rule.s_t(key)


def ntc_corner_periods(soil: str, tc_star: float, ag: float) -> tuple[float, float, float]:
    """(T_B, T_C, T_D) [s], NTC 2018 Eqs. (3.2.5)-(3.2.7).

    T_C = C_C·T_C*, T_B = T_C/3, T_D = 4·a_g/g + 1.6 (a_g in g).
    """
    t_c = rule.t_c(ntc_cc(soil, tc_star), tc_star)
    return rule.t_b(t_c), t_c, ntc_td(ag)


def ntc_td(ag: float) -> float:
    """T_D = 4·a_g/g + 1.6 [s], NTC 2018 Eq. (3.2.7); a_g in g."""
    return rule.t_d(ag)


# --- the spectrum object ------------------------------------------------------------------


@dataclass(frozen=True)
class ElasticSpectrum:
    """A target horizontal elastic spectrum: :meth:`sa` gives Se(T) [g] for T [s].

    Attributes:
        name: short label (``"A2"``, ``"EC8 type 1 ground B, ag=0.25g"``...).
        kind: ``"ec8"``, ``"ntc2018"``, ``"table"`` or ``"preset"``.
        pga_g: zero-period value a_g·S [g] (what the mean PGA of a record set must reach).
        T_B, T_C, T_D: corner periods [s] (None for a table).
        parameters: the inputs and derived coefficients (S, η, S_S, C_C...), for reports.
        description: one line citing the clause and the values used.
        eta: damping correction η [-] applied to the shape.
        plateau_factor: 2.5 (EC8, presets) or F0 (NTC) [-].
        table: for ``kind == "table"``, the points ((T...), (Se...)).
    """

    name: str
    kind: str
    pga_g: float
    T_B: float | None  # noqa: N815 - the codes' symbols
    T_C: float | None  # noqa: N815
    T_D: float | None  # noqa: N815
    parameters: dict[str, object] = field(default_factory=dict, compare=False)
    description: str = ""
    eta: float = 1.0
    plateau_factor: float = EC8_PLATEAU
    table: tuple[tuple[float, ...], tuple[float, ...]] | None = None

    def sa(self, periods: ArrayLike) -> NDArray[np.float64]:
        """Spectral pseudo-acceleration Se(T) [g], vectorised over the periods T [s]."""
        T = np.asarray(periods, dtype=float)
        if self.table is not None:
            return np.interp(T, np.asarray(self.table[0]), np.asarray(self.table[1]))
        assert self.T_B is not None and self.T_C is not None and self.T_D is not None
        return ec8_shape(T, self.pga_g, self.T_B, self.T_C, self.T_D, self.eta, self.plateau_factor)

    @property
    def plateau_g(self) -> float:
        """The largest spectral value [g] (the plateau for the code shapes)."""
        if self.table is not None:
            return float(max(self.table[1]))
        return self.pga_g * self.eta * self.plateau_factor


def _positive(value: float, key: str) -> float:
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"{key} must be a positive number, got {value!r}", key=key)
    return float(value)


def ec8_spectrum(
    ag: float, ground: str, spectrum_type: int = 1, damping: float = 0.05
) -> ElasticSpectrum:
    """EN 1998-1 §3.2.2.2 horizontal elastic spectrum (Eqs. 3.2-3.5, Tables 3.2/3.3).

    Args:
        ag: design ground acceleration on type A ground a_g [g] (γ_I already applied).
        ground: ground type A-E.
        spectrum_type: 1 (M_s > 5.5) or 2.
        damping: viscous damping ratio [-] (η from Eq. 3.6).
    """
    ag = _positive(ag, "ag")
    S, t_b, t_c, t_d = ec8_parameters(ground, spectrum_type)
    g = str(ground).strip().upper()
    eta = damping_correction(damping)
    return ElasticSpectrum(
        name=f"EC8 type {spectrum_type} ground {g}, ag={ag:g}g",
        kind="ec8",
        pga_g=ag * S,
        T_B=t_b,
        T_C=t_c,
        T_D=t_d,
        parameters={
            "ag": ag,
            "ground": g,
            "spectrum_type": spectrum_type,
            "damping": damping,
            "S": S,
            "eta": eta,
        },
        description=f"EN 1998-1 §3.2.2.2, type {spectrum_type}, ground {g}: a_g = {ag:g} g, "
        f"S = {S:g}, T_B/T_C/T_D = {t_b:g}/{t_c:g}/{t_d:g} s, η = {eta:.3f}",
        eta=eta,
    )


def ntc2018_spectrum(
    ag: float,
    F0: float,  # noqa: N803 - the code's symbols
    Tc_star: float,  # noqa: N803
    soil: str,
    topography: str = "T1",
    damping: float = 0.05,
) -> ElasticSpectrum:
    """NTC 2018 §3.2.3.2.1 horizontal elastic spectrum (Eqs. 3.2.2-3.2.7).

    Args:
        ag: site peak acceleration on rock a_g/g [g] (Allegato A of NTC 2008 / the INGV grid).
        F0: maximum spectral amplification on rock [-].
        Tc_star: T_C* [s], the start of the constant-velocity branch on rock.
        soil: subsoil category A-E (S_S and C_C of Tab. 3.2.IV).
        topography: T1-T4 (S_T of Tab. 3.2.V, the value at the top of the relief).
        damping: viscous damping ratio [-] (η from Eq. 3.2.4).
    """
    ag = _positive(ag, "ag")
    F0 = _positive(F0, "F0")
    Tc_star = _positive(Tc_star, "Tc_star")
    s = _ntc_soil(soil)
    ss, st = ntc_ss(s, ag, F0), ntc_st(topography)
    topo = str(topography).strip().upper()
    t_b, t_c, t_d = ntc_corner_periods(s, Tc_star, ag)
    eta = damping_correction(damping)
    S = ss * st
    return ElasticSpectrum(
        name=f"NTC 2018 ag={ag:g}g F0={F0:g} Tc*={Tc_star:g}s soil {s} {topo}",
        kind="ntc2018",
        pga_g=ag * S,
        T_B=t_b,
        T_C=t_c,
        T_D=t_d,
        parameters={
            "ag": ag,
            "F0": F0,
            "Tc_star": Tc_star,
            "soil": s,
            "topography": topo,
            "damping": damping,
            "S_S": ss,
            "C_C": ntc_cc(s, Tc_star),
            "S_T": st,
            "S": S,
            "eta": eta,
        },
        description=f"NTC 2018 §3.2.3.2.1, soil {s}, {topo}: a_g = {ag:g} g, F0 = {F0:g}, "
        f"S_S = {ss:.3f}, S_T = {st:g}, T_B/T_C/T_D = {t_b:.4f}/{t_c:.4f}/{t_d:.3f} s",
        eta=eta,
        plateau_factor=F0,
    )


#: The paper's spectra: name -> (a_g·S [g], T_B [s], T_C [s]).  The plateau 2.5·a_g·S and
#: T_D = 2.0 s are assumptions (docs/model.md §6): the paper does not state them.
PRESETS: dict[str, tuple[float, float, float]] = {
    "A1": (0.106, 0.103, 0.309),
    "A2": (0.106, 0.146, 0.437),
    "A3": (0.106, 0.130, 0.391),
}
#: T_D [s] assumed for the presets
PRESET_TD = 2.0


def preset_spectrum(name: str) -> ElasticSpectrum:
    """One of the paper's spectra A1, A2, A3: EC8-shaped (Eqs. 3.2-3.5), 5 % damping (η = 1),
    a_g·S = 0.106 g, plateau 2.5·a_g·S, T_D = 2.0 s."""
    key = str(name).strip().upper()
    if key not in PRESETS:
        raise InputError(
            f"unknown spectrum preset {name!r}; expected one of {', '.join(PRESETS)}",
            key="spectrum",
        )
    ags, t_b, t_c = PRESETS[key]
    return ElasticSpectrum(
        name=key,
        kind="preset",
        pga_g=ags,
        T_B=t_b,
        T_C=t_c,
        T_D=PRESET_TD,
        parameters={"preset": key},
        description=f"paper spectrum {key}: a_g·S = {ags} g, T_B = {t_b} s, T_C = {t_c} s "
        f"(EC8 shape; plateau 2.5·a_g·S and T_D = {PRESET_TD} s assumed)",
    )


def table_spectrum(
    periods: ArrayLike, accelerations: ArrayLike, name: str = "table"
) -> ElasticSpectrum:
    """A user spectrum from points (T [s], Se [g]).

    Linear interpolation between the points; beyond the ends the end values are held constant
    (no extrapolation: the user states where the spectrum ends).  The zero-period value
    ``pga_g`` (a_g·S) is Se at the first point, which should therefore be at T = 0.
    """
    T = np.asarray(periods, dtype=float)
    S = np.asarray(accelerations, dtype=float)
    if T.ndim != 1 or T.shape != S.shape or T.size < 2:
        raise InputError(
            "a table spectrum needs two equal-length lists of at least 2 points", key="spectrum"
        )
    if not (np.all(np.isfinite(T)) and np.all(np.isfinite(S))):
        raise InputError("table spectrum values must be finite numbers", key="spectrum")
    if np.any(np.diff(T) <= 0) or T[0] < 0 or np.any(S <= 0):
        raise InputError(
            "table periods must increase from T >= 0 and accelerations be > 0", key="spectrum"
        )
    check_table_range(T, S)  # the range of a project's table
    return ElasticSpectrum(
        name=name,
        kind="table",
        pga_g=float(S[0]),
        T_B=None,
        T_C=None,
        T_D=None,
        parameters={"periods": T.tolist(), "accelerations": S.tolist()},
        description=f"user table of {T.size} points, T = {T[0]:g}-{T[-1]:g} s "
        "(linear between points, constant beyond the ends)",
        table=(tuple(T.tolist()), tuple(S.tolist())),
    )


# --- the text form used by the CLI -------------------------------------------------------------

SPECTRUM_HELP = (
    "target spectrum: a preset of the paper (A1, A2, A3); "
    "'ec8:type=1,ground=B,ag=0.25[,damping=0.05]' (EN 1998-1 §3.2.2.2, ag in g on rock); "
    "'ntc:ag=0.261,F0=2.36,tc=0.347,soil=B[,topo=T1,damping=0.05]' (NTC 2018 §3.2.3.2.1, "
    "tc = T_C* in s); or 'table:T/Se,T/Se,...' (periods in s, Se in g, linear between points)"
)

_ALIASES = {
    "type": "spectrum_type",
    "spectrum_type": "spectrum_type",
    "ground": "ground",
    "soil": "soil",
    "ag": "ag",
    "f0": "F0",
    "tc": "Tc_star",
    "tc*": "Tc_star",
    "tcstar": "Tc_star",
    "tc_star": "Tc_star",
    "topo": "topography",
    "topography": "topography",
    "st": "topography",
    "damping": "damping",
    "xi": "damping",
}


def _keywords(body: str, allowed: set[str], text: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for item in filter(None, (p.strip() for p in body.split(","))):
        key, sep, value = item.partition("=")
        name = _ALIASES.get(key.strip().lower())
        if not sep or name is None or name not in allowed:
            raise InputError(
                f"cannot read {item!r} in spectrum {text!r}; expected key=value with keys "
                f"{', '.join(sorted(allowed))}",
                key="spectrum",
            )
        out[name] = value.strip()
    return out


def _number(kw: dict[str, str], key: str, text: str, default: float | None = None) -> float:
    if key not in kw:
        if default is None:
            raise InputError(f"spectrum {text!r} lacks {key}=", key="spectrum")
        return default
    try:
        return float(kw[key])
    except ValueError:
        raise InputError(
            f"{key} must be a number in spectrum {text!r}, got {kw[key]!r}", key="spectrum"
        ) from None


def parse_spectrum(text: str) -> ElasticSpectrum:
    """The spectrum described by a one-line string (the CLI form; see :data:`SPECTRUM_HELP`).

    Examples: ``A2``; ``ec8:type=1,ground=B,ag=0.25``;
    ``ntc:ag=0.261,F0=2.36,tc=0.347,soil=B,topo=T1``; ``table:0/0.3,0.15/0.75,2/0.19``.
    """
    raw = str(text).strip()
    head, sep, body = raw.partition(":")
    kind = head.strip().lower()
    if not sep:
        return preset_spectrum(raw)
    if kind == "ec8":
        kw = _keywords(body, {"spectrum_type", "ground", "ag", "damping"}, raw)
        stype = _number(kw, "spectrum_type", raw, 1.0)
        if stype not in (1.0, 2.0):
            raise InputError(f"EC8 type must be 1 or 2 in {raw!r}", key="spectrum")
        if "ground" not in kw:
            raise InputError(f"spectrum {raw!r} lacks ground=", key="spectrum")
        return ec8_spectrum(
            _number(kw, "ag", raw), kw["ground"], int(stype), _number(kw, "damping", raw, 0.05)
        )
    if kind in ("ntc", "ntc2018"):
        allowed = {"ag", "F0", "Tc_star", "soil", "topography", "damping"}
        kw = _keywords(body, allowed, raw)
        if "soil" not in kw:
            raise InputError(f"spectrum {raw!r} lacks soil=", key="spectrum")
        return ntc2018_spectrum(
            _number(kw, "ag", raw),
            _number(kw, "F0", raw),
            _number(kw, "Tc_star", raw),
            kw["soil"],
            kw.get("topography", "T1"),
            _number(kw, "damping", raw, 0.05),
        )
    if kind == "table":
        points: list[tuple[float, float]] = []
        for item in filter(None, (p.strip() for p in body.split(","))):
            t, slash, s = item.partition("/")
            try:
                points.append((float(t), float(s)))
            except ValueError:
                raise InputError(
                    f"table point {item!r} is not 'T/Se' (two numbers)", key="spectrum"
                ) from None
            if not slash:
                raise InputError(f"table point {item!r} is not 'T/Se'", key="spectrum")
        if len(points) < 2:
            raise InputError("a table spectrum needs at least 2 points", key="spectrum")
        return table_spectrum([p[0] for p in points], [p[1] for p in points])
    raise InputError(
        f"unknown spectrum {raw!r}; expected a preset (A1, A2, A3), 'ec8:...', 'ntc:...' or "
        "'table:...'",
        key="spectrum",
    )
