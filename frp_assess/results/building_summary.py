"""A building's results: its walls' key numbers and the building summary (docs/results-json.md,
"A building's results.json").

Built from the walls' own results (:class:`~frp_assess.results.model.AssessmentResult`, each
written in full in ``walls/<slug>/``) by :func:`building_results`: nothing here is computed
anew, every number is copied from a wall's results, so the summary a reviewer reads first is
the walls' results.json in one table.  Plain frozen dataclasses (as :mod:`frp_assess.results.
model`); :func:`frp_assess.results.json_io.to_json` of :class:`BuildingResults` is the
building's results.json.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from frp_assess.results.as_built import AsBuilt
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.run_inputs import ProjectInfo, Software

#: version of the building's results.json (``building_schema_version``)
BUILDING_SCHEMA_VERSION = 1
#: the value of ``kind`` that tells a building's results.json from a wall's
BUILDING_KIND = "building"
#: the checks of a case, in the order the summary prints them: (key, what it is)
CHECK_COLUMNS: tuple[tuple[str, str], ...] = (
    ("linear", "linear kinematic check, a0*/(a_g·S/q) (Circolare 2019 §C8.7.1.2.1.7)"),
    ("nonlinear_slv", "nonlinear kinematic check SLV, a_g,SLV/a_g (§C8.7.1.2.1.8)"),
    ("nonlinear_slc", "nonlinear kinematic check SLC, a_g,SLC/a_g (§C8.7.1.2.1.8)"),
    ("time_history_slv", "time history SLV, the displacement margin (§C8.7.1.2.1.9)"),
    ("time_history_slc", "time history SLC, the displacement margin (§C8.7.1.2.1.9)"),
    ("ida", "IDA, a_dyn/(FC·a_g·S) (docs/model.md §5)"),
)


@dataclass(frozen=True)
class CaseZeta:
    """ζ_E [-] of every check of one case (None: not made, or unbounded), the governing
    (deciding) check with its margin [-] and whether the case passes every deciding check."""

    case: str
    linear: float | None
    nonlinear_slv: float | None
    nonlinear_slc: float | None
    time_history_slv: float | None
    time_history_slc: float | None
    ida: float | None
    governing_check: str | None
    governing_margin: float | None  #: None: unbounded (nothing moved)
    passes: bool | None


@dataclass(frozen=True)
class BarsBuilt:
    """The proposed retrofit's bars as built (a wall's ``cases[i].as_built``, in short): the
    material and position, Ø [mm], lines (1 centred, 2 external: one per face), whole bars per
    line and in all, their spacing [m], the ratio installed and asked [‰], metres of bar [m]."""

    material: str
    position: str
    diameter: float
    lines: int
    bars_per_line: int
    total_bars: int
    spacing: float
    ratio_installed: float
    ratio_asked: float
    metres: float


@dataclass(frozen=True)
class WallSummary:
    """One wall (local mechanism) of the building: where its results are, its geometry
    (B, H, L [m]; wall_base Z [m], None at ground level), the code check's α₀ [-] and a₀* [g],
    ζ_E of every check unreinforced and with the proposed retrofit, the verdicts, and the
    proposed retrofit's bars as built with their FRP mass [kg] and cost [currency] over the
    wall's length (None: no retrofit proposed)."""

    name: str
    folder: str  #: the wall's results folder, relative to the building's: walls/<slug>
    mechanism: str
    thickness: float
    height: float
    length: float
    wall_base: float | None
    alpha0: float
    a0_star: float
    unreinforced: CaseZeta
    retrofit_required: bool
    #: the proposed (recommended) retrofit: the cheapest option passing every deciding check;
    #: when the wall passes as it is, the cheapest option for extra margin is not proposed
    proposed: str | None
    proposed_checks: CaseZeta | None
    as_built: str | None  #: the proposed retrofit's bars as built, one line (English)
    bars: BarsBuilt | None  #: the same bars, number by number
    frp_mass: float | None  #: the proposed retrofit's FRP bars [kg]
    frp_cost: float | None  #: ... and their cost [currency]
    tie_steel_mass: float | None  #: the proposed retrofit's tie-rods' steel [kg] (0: none)
    cost: float | None  #: the proposed retrofit's cost: bars and tie-rods [currency]
    #: when nothing passes: the option with the largest governing margin; else None
    closest: str | None
    verdict_before: str  #: "passes" | "fails"
    verdict_after: str  #: "passes" | "fails" | "no retrofit needed"
    input_code_compliant: bool


@dataclass(frozen=True)
class BuildingTotals:
    """The building: its walls, how many fail as they are and how many have a proposed
    retrofit, their FRP mass [kg] and cost [currency] summed, and its governing mechanism:
    the wall whose unreinforced governing ζ_E is the smallest."""

    walls: int
    walls_failing: int
    walls_retrofitted: int
    walls_without_solution: int  #: failing walls with no option passing
    frp_mass: float
    frp_cost: float
    tie_steel_mass: float  #: tie-rods' steel of the proposed retrofits [kg]
    cost: float  #: the proposed retrofits' cost, bars and tie-rods [currency]
    currency: str
    governing_wall: str
    governing_check: str | None
    governing_margin: float | None


@dataclass(frozen=True)
class BuildingResults:
    """A building's results.json."""

    kind: str  #: always :data:`BUILDING_KIND`
    building_schema_version: int
    software: Software
    created: str
    input_file: str
    project: ProjectInfo
    walls: tuple[WallSummary, ...]
    totals: BuildingTotals


def case_zeta(results: AssessmentResult, case: CaseResult) -> CaseZeta:
    """ζ_E of every check of ``case`` as its wall's results.json holds them."""
    checks = None
    if results.kinematic_checks is not None:
        checks = next((c for c in results.kinematic_checks.cases if c.case == case.name), None)
    th, th_slc = (None, None) if checks is None else (checks.time_history, checks.time_history_slc)
    return CaseZeta(
        case=case.name,
        linear=None if checks is None else checks.linear.zeta_e,
        nonlinear_slv=None if checks is None else checks.slv.zeta_e,
        nonlinear_slc=None if checks is None else checks.slc.zeta_e,
        time_history_slv=None if th is None else th.zeta_e,
        time_history_slc=None if th_slc is None else th_slc.zeta_e,
        ida=None if checks is None or checks.ida is None else checks.ida.zeta_e,
        governing_check=case.governing_check,
        governing_margin=case.governing_margin,
        passes=case.passes,
    )


def bars_built(b: AsBuilt) -> BarsBuilt:
    """The short form of bars as built."""
    return BarsBuilt(
        b.material,
        b.position,
        b.diameter,
        b.lines,
        b.bars_per_line,
        b.total_bars,
        b.spacing,
        b.ratio_installed,
        b.ratio_asked,
        b.metres,
    )


def _verdict(passes: bool | None) -> str:
    return "passes" if passes else "fails"


def wall_summary(name: str, folder: str, results: AssessmentResult) -> WallSummary:
    """One wall's line of the building summary, from its results."""
    urm = results.urm
    proposed = results.case(results.recommended) if results.retrofit_required else None
    built = None if proposed is None else proposed.as_built
    after = "no retrofit needed"
    if results.retrofit_required:
        after = _verdict(proposed.passes) if proposed is not None else "fails"
    return WallSummary(
        name=name,
        folder=folder,
        mechanism=results.wall.mechanism,
        thickness=results.wall.thickness,
        height=results.wall.height,
        length=results.wall.length,
        wall_base=None if results.building is None else results.building.wall_base,
        alpha0=results.code_check.alpha0,
        a0_star=results.code_check.a0_star,
        unreinforced=case_zeta(results, urm),
        retrofit_required=results.retrofit_required,
        proposed=None if proposed is None else proposed.name,
        proposed_checks=None if proposed is None else case_zeta(results, proposed),
        as_built=None if built is None else built.note,
        bars=None if built is None else bars_built(built),
        frp_mass=None if proposed is None else proposed.frp_mass,
        frp_cost=None if proposed is None else proposed.frp_cost,
        tie_steel_mass=None if proposed is None else proposed.option_mass - proposed.frp_mass,
        cost=None if proposed is None else proposed.option_cost,
        closest=results.closest if results.retrofit_required and proposed is None else None,
        verdict_before=_verdict(urm.passes),
        verdict_after=after,
        input_code_compliant=results.input_code_compliant,
    )


def _margin_key(margin: float | None) -> float:
    """A governing margin for ordering: None (unbounded) above every number."""
    return math.inf if margin is None else margin


def building_results(
    project: ProjectInfo,
    input_file: str,
    walls: Sequence[tuple[str, str, AssessmentResult]],
    *,
    created: str | None = None,
) -> BuildingResults:
    """The building's results from its walls' (name, folder, results), in file order;
    ``created``: the date of the run (default: the first wall's)."""
    if not walls:
        raise ValueError("a building has at least one wall")
    rows = tuple(wall_summary(name, folder, results) for name, folder, results in walls)
    first = walls[0][2]
    governing = min(rows, key=lambda r: _margin_key(r.unreinforced.governing_margin))
    totals = BuildingTotals(
        walls=len(rows),
        walls_failing=sum(r.verdict_before == "fails" for r in rows),
        walls_retrofitted=sum(r.proposed is not None for r in rows),
        walls_without_solution=sum(r.retrofit_required and r.proposed is None for r in rows),
        frp_mass=sum(r.frp_mass or 0.0 for r in rows),
        frp_cost=sum(r.frp_cost or 0.0 for r in rows),
        tie_steel_mass=sum(r.tie_steel_mass or 0.0 for r in rows),
        cost=sum(r.cost or 0.0 for r in rows),
        currency=first.costs.currency,
        governing_wall=governing.name,
        governing_check=governing.unreinforced.governing_check,
        governing_margin=governing.unreinforced.governing_margin,
    )
    return BuildingResults(
        kind=BUILDING_KIND,
        building_schema_version=BUILDING_SCHEMA_VERSION,
        software=first.software,
        created=created or first.created,
        input_file=input_file,
        project=project,
        walls=rows,
        totals=totals,
    )
