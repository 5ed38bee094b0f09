"""The loads a wall carries and the multiplier of simple overturning with them, as results
(results.json's ``loads``; docs/model.md §12, docs/results-json.md).

Plain frozen dataclasses of floats, strings, booleans and tuples.  Units as a practitioner
writes them: forces kN/m (per metre of wall; a tie's anchorage kN per tie), lengths m,
moments kNm/m, areas mm², stresses MPa, moduli GPa.  Written only when the project has loads,
so that a file without them is the file it was before loads existed.
"""

from __future__ import annotations

from dataclasses import dataclass

#: the names of the two terms of α₀ that are not the project's loads (the report words them)
WALL_WEIGHT = "wall weight W"
BASE_REACTION = "base reaction N0 (pivot inside the wall)"


@dataclass(frozen=True)
class TopLoadResult:
    """A vertical load on the top of the wall (a floor, the roof)."""

    name: str
    load: float  #: P [kN/m]
    distance: float  #: d [m] of its line of action from the outer face (its lever about O)
    inertia: str  #: "carried" (its mass moves with the wall) or "restrained"


@dataclass(frozen=True)
class ThrustResult:
    """An outward horizontal force on the inner face (a roof, a vault)."""

    name: str
    force: float  #: F [kN/m]
    height: float  #: h [m] above the rocking base (its lever about O)


@dataclass(frozen=True)
class TieResult:
    """Steel tie-rods at one height, with their per-metre values (rules/tie_rods.py)."""

    name: str
    height: float  #: h_t [m]
    area: float  #: A_s [mm²] of one tie
    diameter: float | None  #: [mm] when given so
    spacing: float  #: i_t [m]
    length: float  #: L_t [m]
    yield_strength: float  #: f_y [MPa]
    elastic_modulus: float  #: E_s [GPa]
    anchorage: float | None  #: F_a [kN per tie]; None: not governing
    stiffness: float  #: k_t = E_s·A_s/(L_t·i_t) [kN/m per m of wall]
    yield_force: float  #: F_y = A_s·f_y/i_t [kN/m]
    anchorage_force: float | None  #: F_a/i_t [kN/m]; None: not governing
    capacity: float  #: min(F_y, F_a/i_t) [kN/m], the force of the linear check's L_i
    #: the steel yields before the anchorage fails: the tie counts in d0 (docs/model.md §12)
    ductile: bool


@dataclass(frozen=True)
class TieOptionResult:
    """The tie-rods a retrofit option adds to the wall's loads, with their steel and cost
    (per tie: its bar, two anchorage plates and its installation, ``costs.tie_*``)."""

    tie: TieResult
    steel_mass_per_m: float  #: ρ·A_s·L_t/i_t [kg per metre of wall]
    steel_mass: float  #: for the wall's length [kg]
    cost_per_tie: float  #: [currency]
    cost_per_m: float  #: [currency per metre of wall]
    cost: float  #: for the wall's length [currency]
    #: some tie price is given in ``costs`` (false: the costs are 0, not given)
    prices_given: bool


@dataclass(frozen=True)
class MomentTerm:
    """One term of α₀ (Circolare 2019 eq. C8.7.1.1), about the outer base corner O for a
    unit virtual rotation: force × lever = moment."""

    name: str
    #: "stabilising" (Σ P·δ_Py; the base reaction's N₀·x₀/2 enters with a minus sign),
    #: "overturning" (Σ F·δ_F), "internal work" (L_i of a tie at its capacity),
    #: "inertia" (Σ (P + Q)·δ_PQx, per g)
    role: str
    force: float  #: [kN/m]
    lever: float  #: [m]
    moment: float  #: [kNm/m], signed as it enters its sum


@dataclass(frozen=True)
class OverturningResult:
    """α₀ of simple overturning with the loads, term by term, and e*, M* of eq. C8.7.1.5:

    α₀ = (Σ stabilising − Σ overturning + Σ internal work) / Σ inertia
    """

    terms: tuple[MomentTerm, ...]
    stabilising: float  #: Σ P·δ_Py [kNm/m] (the base reaction's moment subtracted)
    overturning: float  #: Σ F·δ_F [kNm/m]
    internal_work: float  #: L_i [kNm/m]
    inertia: float  #: Σ (P + Q)·δ_PQx [kNm/m per g]
    alpha0: float  #: α₀ [-]
    #: α₀ without the ties' work, a_RM/g of rocking's start (the capacity curve at θ = 0)
    alpha0_without_ties: float
    e_star: float  #: e* [-], wall and carried loads
    m_star: float  #: M* [kg per metre of wall]
    formula: str  #: α₀ written with the numbers, for a reviewer


@dataclass(frozen=True)
class LoadsResult:
    """What bears on and pushes the wall, and α₀ with them."""

    top: tuple[TopLoadResult, ...]
    thrust: tuple[ThrustResult, ...]
    ties: tuple[TieResult, ...]
    overturning: OverturningResult
    #: what §12 does not model, one sentence each (the report's assumptions)
    not_modelled: tuple[str, ...]
