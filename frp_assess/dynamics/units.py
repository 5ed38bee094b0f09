"""The wall and the bars from practitioners' units (m, kN/m³, GPa, ‰): the one place where
they become the SI units of the dynamics (N/m³, Pa).

The project file, the study file, the command line and the TUI all give the unit weight in
kN/m³ and the bars' modulus in GPa; they build their models here rather than each
multiplying by 1e3 and 1e9.
"""

from __future__ import annotations

import math

from frp_assess.dynamics.rebars import DEFAULT_STRAIN_FACTOR, Position, Rebars
from frp_assess.dynamics.wall import Wall

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
