"""The wall and the bars from practitioners' units (m, kN/m³, GPa, ‰): the one place where
they become the SI units of the dynamics (N/m³, Pa).

The project file, the study file, the command line and the TUI all give the unit weight in
kN/m³ and the bars' modulus in GPa; they build their models here rather than each
multiplying by 1e3 and 1e9.
"""

from __future__ import annotations

import math

from frp_assess.dynamics.loads import Tie
from frp_assess.dynamics.rebars import DEFAULT_STRAIN_FACTOR, Position, Rebars
from frp_assess.dynamics.wall import Wall
from frp_assess.rules.tie_rods import tie_stiffness, tie_yield_force
from frp_assess.rules.wall_loads import Thrust, TopLoad

#: newtons in a kilonewton
N_PER_KN = 1e3
#: pascals in a gigapascal
PA_PER_GPA = 1e9
#: pascals in a megapascal
PA_PER_MPA = 1e6
#: kilopascals in a megapascal and in a gigapascal: the assessment's records are in kN/m, and
#: kN/m over kPa is metres (the rules of frp_assess.rules are homogeneous formulas)
KPA_PER_MPA = 1e3
KPA_PER_GPA = 1e6


def wall_from_practice(
    thickness: float,
    height: float,
    unit_weight_kn: float,
    compressive_strength_mpa: float = math.inf,
) -> Wall:
    """The wall of thickness B [m], height H [m], unit weight w [kN/m³] and design compressive
    strength f_d [MPa] (infinite: not given, the pivot stays at the edge)."""
    return Wall(thickness, height, unit_weight_kn * N_PER_KN, compressive_strength_mpa * PA_PER_MPA)


def rebars_from_practice(
    modulus_gpa: float,
    ultimate_strain: float,
    position: Position,
    ratio_permille: float,
    strain_factor: float = DEFAULT_STRAIN_FACTOR,
) -> Rebars:
    """The bars of modulus E [GPa], ultimate strain ε_u [-], position, ratio ρ [‰] and cyclic
    reduction c [-]."""
    return Rebars(
        modulus_gpa * PA_PER_GPA, ultimate_strain, position, ratio_permille, strain_factor
    )


#: square metres in a square millimetre
M2_PER_MM2 = 1e-6


def top_load_from_practice(load_kn: float, distance: float, carried: bool) -> TopLoad:
    """A vertical load on the top of the wall of P [kN/m] at d [m] from the outer face, its
    mass carried by the wall or not (docs/model.md §12)."""
    return TopLoad(load_kn * N_PER_KN, distance, carried)


def thrust_from_practice(force_kn: float, height: float) -> Thrust:
    """An outward thrust of F [kN/m] at h [m] above the rocking base (docs/model.md §12)."""
    return Thrust(force_kn * N_PER_KN, height)


def tie_from_practice(
    height: float,
    area_mm2: float,
    spacing: float,
    length: float,
    yield_strength_mpa: float,
    modulus_gpa: float,
    anchorage_kn: float | None,
) -> Tie:
    """The ties at h_t [m], each of area A_s [mm²], free length L_t [m], steel f_y [MPa] and
    E_s [GPa], every i_t [m], with an anchorage of F_a [kN per tie] (None: not governing),
    per metre of wall (:mod:`frp_assess.rules.tie_rods`, docs/model.md §12)."""
    area = area_mm2 * M2_PER_MM2
    return Tie.of(
        height,
        tie_stiffness(area, modulus_gpa * PA_PER_GPA, length, spacing),
        tie_yield_force(area, yield_strength_mpa * PA_PER_MPA, spacing),
        None if anchorage_kn is None else anchorage_kn * N_PER_KN,
        spacing,
    )
