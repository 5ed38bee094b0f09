"""Linear kinematic check of the unreinforced wall (NTC 2018 §8.7.1, Circolare 2019 §C8.7.1).

For the simple overturning of a monolithic wall about its base with no other loads, the
activation multiplier is α0 = B/H (moment of the self-weight about the base edge over the
moment of the horizontal inertia force), the whole mass participates (M* = m, e* = 1), and
the spectral acceleration of activation is a0* = α0·g/(e*·FC).  At ground level the check is
a0* ≥ a_g·S/q with q = 2 (Circolare 2019 Eq. C8.7.1.9).  Passive unbonded bars are unstressed
at rest, so they do not change α0: this check is the same for every retrofit option.
"""

from __future__ import annotations

from dataclasses import dataclass

#: confidence factors by knowledge level (Circolare 2019 Tab. C8.5.IV): the one table, rules'
from frp_assess.rules.kinematic import a_star
from frp_assess.rules.masonry import CONFIDENCE_FACTORS, confidence_factor

__all__ = [
    "CONFIDENCE_FACTORS",
    "KinematicCheck",
    "overturning_check",
    "simple_overturning_check",
]


@dataclass(frozen=True)
class KinematicCheck:
    alpha0: float  #: activation multiplier [-]
    e_star: float  #: participating mass fraction [-]
    fc: float  #: confidence factor [-]
    knowledge_level: str
    behaviour_factor: float  #: q [-]
    a0_star: float  #: spectral acceleration of activation [g]
    demand: float  #: a_g·S/q [g] (a_Z/q above ground)

    @property
    def ratio(self) -> float:
        return self.a0_star / self.demand

    @property
    def passed(self) -> bool:
        return self.a0_star >= self.demand


def simple_overturning_check(
    thickness: float,
    height: float,
    ag_s: float,
    knowledge_level: str = "LC1",
    behaviour_factor: float = 2.0,
) -> KinematicCheck:
    """Args: B, H [m]; a_g·S [g] of the site (a_Z, the floor's peak acceleration at the
    wall's base, for a wall above ground); knowledge level LC1–LC3; q [-]."""
    return overturning_check(thickness / height, 1.0, ag_s, knowledge_level, behaviour_factor)


def overturning_check(
    alpha0: float, e_star: float, ag_s: float, knowledge_level: str, behaviour_factor: float
) -> KinematicCheck:
    """The linear check a0* = α0·g/(e*·FC) ≥ a_g·S/q of any α0 and e* (Circolare 2019
    eqs. C8.7.1.1, C8.7.1.3, C8.7.1.9): :func:`simple_overturning_check` for the wall alone,
    or α0 and e* with the loads (:mod:`frp_assess.assess.loaded_overturning`)."""
    if knowledge_level not in CONFIDENCE_FACTORS:
        raise ValueError(f"knowledge level must be LC1, LC2 or LC3, got {knowledge_level!r}")
    fc = confidence_factor(knowledge_level)
    a0 = a_star(alpha0, e_star, fc, g=1.0)  # in g
    return KinematicCheck(
        alpha0, e_star, fc, knowledge_level, behaviour_factor, a0, ag_s / behaviour_factor
    )
