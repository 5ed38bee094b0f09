"""The category of the intervention (NTC 2018 §8.4): the ζ_E a retrofit option must reach.

ζ_E (NTC 2018 §8.3) is the ratio of the largest seismic action the structure bears to the
action a new construction on the same site is designed for; here each deciding check of the
mechanism gives one (capacity/demand [-], passes the assessment at ≥ 1), and the
mechanism's ζ_E is the smallest of them (its governing check).  What an option must reach:

* ``local`` (*riparazione o intervento locale*, §8.4.1): the mechanism's safety improves and
  nothing gets worse: the check(s) that govern the unreinforced wall above their unreinforced
  ζ_E (so the mechanism's ζ_E rises), every other check at least at its unreinforced ζ_E or
  at the ζ_E that passes the assessment (1): a check with margin may lose part of it, the
  mechanism's safety does not;
* ``improvement`` (*miglioramento*, §8.4.2): ζ_E may stay below 1; for a construction of use
  class III used as a school, or of class IV, ζ_E after the intervention at least 0.6; for
  the other constructions of class III and those of class II ζ_E raised by at least 0.1.
  The clause says nothing of class I: it is given the rule of class II (at least 0.1 more);
* ``upgrade`` (*adeguamento*, §8.4.3): ζ_E ≥ 1.0 (the value of §8.4.3 cases a, b and d).
  The ζ_E ≥ 0.80 the clause allows in cases c and e is not offered: §8.4.3 states it for
  the check of the whole structure and keeps the local checks of the single parts.

Pure functions of plain numbers, the standard library only.
"""

from __future__ import annotations

from typing import Literal

Category = Literal["local", "improvement", "upgrade"]

#: the categories of NTC 2018 §8.4, in the order of the clause (§8.4.1, §8.4.2, §8.4.3)
CATEGORIES: tuple[Category, ...] = ("local", "improvement", "upgrade")
#: the clause of each category (NTC 2018 §8.4.1-§8.4.3)
CATEGORY_CLAUSE: dict[str, str] = {
    "local": "NTC 2018 §8.4.1",
    "improvement": "NTC 2018 §8.4.2",
    "upgrade": "NTC 2018 §8.4.3",
}
#: ζ_E after an improvement of a class III school or a class IV construction, at least
#: (NTC 2018 §8.4.2) [-]
IMPROVEMENT_MINIMUM = 0.6
#: the least increase of ζ_E of an improvement of the other constructions (NTC 2018 §8.4.2) [-]
IMPROVEMENT_INCREASE = 0.1
#: ζ_E after an upgrade (NTC 2018 §8.4.3, cases a, b, d) [-]
UPGRADE_ZETA = 1.0


def improvement_has_minimum(use_class: str, school: bool) -> bool:
    """NTC 2018 §8.4.2: the improvement of this construction is bound by ζ_E ≥ 0.6 (class
    III used as a school, class IV), not by an increase of 0.1 (the others).  ``use_class``
    "I"-"IV" [-]; ``school`` [-]: used as a school."""
    return use_class == "IV" or (use_class == "III" and school)


def improvement_zeta(zeta_as_is: float, use_class: str, school: bool) -> float:
    """ζ_E [-] an improvement must reach (NTC 2018 §8.4.2): 0.6 for a class III school or a
    class IV construction, else the unreinforced mechanism's ``zeta_as_is`` [-] + 0.1."""
    if improvement_has_minimum(use_class, school):
        return IMPROVEMENT_MINIMUM
    return zeta_as_is + IMPROVEMENT_INCREASE


def local_requirement(
    zeta_check_as_is: float, zeta_as_is: float, passing: float = UPGRADE_ZETA
) -> tuple[float, bool]:
    """(ζ_E [-] a deciding check must reach in a local intervention, whether it must be
    exceeded), NTC 2018 §8.4.1.  The mechanism's safety improves: the check that governs the
    unreinforced wall (its ζ_E ``zeta_check_as_is`` [-] is the mechanism's ``zeta_as_is``
    [-]) must exceed it.  Nothing gets worse: another check keeps its unreinforced ζ_E, or
    at least the ζ_E that passes the assessment, ``passing`` [-] (1; the IDA's target)."""
    if zeta_check_as_is <= zeta_as_is:
        return zeta_check_as_is, True
    return min(zeta_check_as_is, passing), False


def meets(zeta: float | None, required: float, strict: bool = False) -> bool:
    """A check's ζ_E [-] reaches ``required`` [-] (NTC 2018 §8.4; above it when ``strict``);
    None is an unbounded ζ_E (nothing moved): it meets any requirement."""
    if zeta is None:
        return True
    return zeta > required if strict else zeta >= required
