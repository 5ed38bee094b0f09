"""The code's kinematic checks of the wall and of every retrofit option, side by side.

Circolare 2019 §C8.7.1 (docs/model.md, "Displacement-based checks"), assembled from the
clause functions of :mod:`frp_assess.assess.kinematic_nonlinear` and
:mod:`frp_assess.assess.code_check`:

Every check uses the wall model the IDA runs (docs/model.md §1.1): its α0 = a_RM/g (the
moment balance about the pivot, the base reaction included), its restraint term K and its
bar rupture rotation θ_max; the block turns about its base corner, so displacements keep the
wall's geometry.  A wall carrying loads (docs/model.md §12.1) has α0, e* and the capacity curve
with them (:mod:`~frp_assess.assess.loaded_overturning`,
:mod:`~frp_assess.assess.loaded_capacity`).

* the linear check a0* ≥ demand/q (§C8.7.1.2.1.7), with α0 of the model: the bars, unstressed
  at rest, do not change α0, so it differs between options only where their models' α0 do;
* the nonlinear static SLV and SLC checks on the capacity curve of that model *with its
  bars* (the K·sin θ of Eq. 10): d0 is the bare wall's (where its restoring moment vanishes:
  the bars break brittly and are not surely present up to collapse), d_SLV = min(0.40·d0,
  the displacement where a bar rupture drops the capacity by more than 50 %), demand from the
  elastic displacement spectrum at 8 % / 10 % damping, a_g,SLV not below a_g,SLD;
* the time-history check of §C8.7.1.2.1.9 at SLV and at SLC: the rocking model under every
  record at that limit state's intensity (×FC when FC enters the dynamics), d0 never
  exceeded, mean peak ≤ d_SLV (≤ d_SLC);
* the IDA's ζ_E = a_dyn/(FC·a_g·S), mean and least favourable record, at the assessment's
  limit state (deciding) and at the a_g·S of SLV and of SLC (stated beside it).

Each limit state is checked at its own spectrum when the site is given by its coordinates
(:mod:`frp_assess.assess.limit_states`): the linear and SLV checks at the SLV spectrum, the
SLC checks at the SLC spectrum, with records generated for it (artificial) or scaled to its
a_g·S (recorded).  A project that gives one spectrum by its parameters has every limit state
checked at that one intensity (the SLC check is then implied by the SLV one).

The time-history checks and the IDA decide (:mod:`frp_assess.assess.decision`); the linear
and nonlinear static checks are supporting checks.

A wall above ground (Circolare 2019 §C7.2.3) takes its demand from the floor spectrum
(eq. C8.7.1.12) and, in the time-history check, its base motion from the floor filter of
:mod:`frp_assess.motions.floor`.  The building is any object with the attributes of
:class:`Building` (the project's ``building`` block,
:class:`~frp_assess.assess.inputs.BuildingSettings`, or a :class:`FloorPosition`).

Units: ground accelerations in g (a_g·S); records in m/s²; displacements in m.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frp_assess.assess.check_demand import (
    Building,
    FloorPosition,
    LimitStateDemand,
    base_motions,
    building_period,
    displacement_spectrum,
    floor_ratio,
    limit_state_demand,
)
from frp_assess.assess.code_check import (
    KinematicCheck,
    overturning_check,
    simple_overturning_check,
)
from frp_assess.assess.inputs import AssessmentInputs, CodeCheckSettings
from frp_assess.assess.kinematic_nonlinear import (
    CapacityCurve,
    DisplacementSpectrum,
    LimitStateCheck,
    capacity_curve,
    control_displacement,
    limit_state_check,
    time_history_check,
)
from frp_assess.assess.limit_states import (
    CHECKED_STATES,
    intensity,
    intensity_basis,
    limit_state_spectrum,
    own_spectra,
)
from frp_assess.assess.loaded_capacity import loaded_capacity_curve
from frp_assess.assess.loaded_overturning import loaded_alpha0, loaded_e_star
from frp_assess.dynamics import RockingModel
from frp_assess.motions import G, Record
from frp_assess.results.checks import (
    CapacitySummary,
    CaseChecks,
    FloorBasis,
    IdaCheck,
    KinematicChecks,
    LimitStateResult,
    LinearCheck,
    TimeHistoryResult,
)
from frp_assess.rules.masonry import confidence_factor
from frp_assess.rules.record_sets import design_statistic, design_value

__all__ = [
    "Building",
    "FloorPosition",
    "IdaSummary",
    "LimitStateDemand",
    "base_motions",
    "building_period",
    "case_checks",
    "checks_at",
    "displacement_spectrum",
    "fc_basis",
    "floor_ratio",
    "ida_capacity_demand",
    "ida_check",
    "ida_confidence_factor",
    "kinematic_checks",
    "limit_state_demand",
    "limit_state_demands",
    "linear_check",
    "model_capacity_curve",
    "peak_displacements",
    "time_history_result",
]

# --- the confidence factor in the IDA verdict ---------------------------------------------


def fc_basis(settings: CodeCheckSettings) -> str:
    """One sentence stating FC and where it comes from (for the report and results.json)."""
    fc = confidence_factor(settings.knowledge_level)
    rule = (
        "Circolare 2019 §C8.7.1.2.1.3: a rigid block whose masonry has infinite compressive "
        f"strength uses the FC of LC1, {confidence_factor('LC1'):g}"
    )
    if settings.knowledge_level == "LC1":
        text = f"FC = {fc:g} (knowledge level LC1; {rule})."
    else:
        text = (
            f"FC = {fc:g} from knowledge level {settings.knowledge_level} (Tab. C8.5.IV), "
            f"as asked in the project; note that {rule}."
        )
    if settings.fc_in_ida:
        return text + " It divides the IDA capacity too: capacity/demand = a_dyn/(FC·a_g·S)."
    return text + " The IDA capacity is not divided by it (code_check.fc_in_ida: false)."


def ida_confidence_factor(settings: CodeCheckSettings) -> float:
    """FC [-] that divides the IDA capacity: the knowledge level's (Circolare 2019
    Tab. C8.5.IV; LC1's 1.35 by default, the rule for a rigid block, §C8.7.1.2.1.3), or 1
    when ``fc_in_ida`` is turned off."""
    return confidence_factor(settings.knowledge_level) if settings.fc_in_ida else 1.0


def ida_capacity_demand(design_a_dyn: float, demand: float, fc: float) -> float:
    """capacity/demand = a_dyn / (FC·demand) [-] of the IDA verdict (issue 15 §3).

    Args:
        design_a_dyn: the design value of a_dyn [g] (mean over ≥ 7 records, else the least
            favourable record).
        demand: a_g·S [g].
        fc: confidence factor [-] (:func:`ida_confidence_factor`).
    """
    if not (demand > 0.0 and fc > 0.0):
        raise ValueError(f"demand and FC must be > 0, got {demand!r}, {fc!r}")
    return design_a_dyn / (fc * demand)


@dataclass(frozen=True)
class IdaSummary:
    """What the IDA of one case gives to the side-by-side table."""

    mean_a_dyn: float  #: mean a_dyn over the records [g]
    least_a_dyn: float  #: least favourable record's a_dyn [g]
    records: int  #: number of records (≥ 7: the mean decides)


def ida_check(
    ida: IdaSummary, demand: float, fc: float, limit_state: str | None = None
) -> IdaCheck:
    """ζ_E of the IDA, mean and least favourable record, and the verdict on the design value
    (the mean with ≥ 7 records, else the least favourable; docs/model.md §5), against the
    a_g·S ``demand`` [g] of ``limit_state``."""
    mean = ida_capacity_demand(ida.mean_a_dyn, demand, fc)
    least = ida_capacity_demand(ida.least_a_dyn, demand, fc)
    rule = design_statistic(ida.records)
    zeta = design_value(mean, least, ida.records)
    return IdaCheck(fc, demand, mean, least, rule, zeta, zeta >= 1.0, limit_state)


# --- the checks of one case ----------------------------------------------------------------


def model_capacity_curve(model: RockingModel, fc: float) -> CapacityCurve:
    """The capacity curve of the model the IDA runs (docs/model.md §1.1): its slenderness α
    (tan α = a_RM/g, the base reaction included), its K and its θ_max, the block turning
    about its base corner (d_C of the wall's geometry); with loads, docs/model.md §12's
    (:mod:`frp_assess.assess.loaded_capacity`)."""
    if model.loads:
        return loaded_capacity_curve(model, fc)
    return capacity_curve(
        model.wall,
        model.rebars,
        fc=fc,
        slenderness=model.alpha,
        stiffness=model.K,
        rupture_rotation=model.theta_max,
    )


def peak_displacements(
    model: RockingModel,
    motions: Sequence[tuple[NDArray[np.float64], float]],
    scale: float = 1.0,
) -> tuple[float, ...]:
    """Peak displacement d_C [m] of the control point under each motion times ``scale``
    (the free vibration after the record included), the block turning about its base corner
    (:func:`~frp_assess.assess.kinematic_nonlinear.control_displacement` of the peak
    rotation); inf where the collapse rule says the wall fell."""
    peaks = []
    for acc, dt in motions:
        res = model.run(acc, dt, scale)
        peaks.append(
            math.inf if res.collapsed else control_displacement(res.max_rotation, model.wall)
        )
    return tuple(peaks)


def linear_check(
    model: RockingModel, a_z: float, knowledge_level: str, behaviour_factor: float
) -> KinematicCheck:
    """The linear check a0* = α0·g/(e*·FC) ≥ a_Z/q (Circolare 2019 §C8.7.1.2.1.7, eq.
    C8.7.1.9) with α0 = a_RM/g of the model the IDA runs (its moment balance about the pivot,
    the base reaction included; the bars, unstressed at rest, do not change it); e* = 1 for
    one block.  ``a_z`` [g]: a_g·S at ground level, the floor's peak acceleration above it.
    With loads, α0 and e* of eqs. C8.7.1.1 and C8.7.1.5 with them, the ties at their capacity
    as the internal work (:mod:`frp_assess.assess.loaded_overturning`)."""
    if model.loads:
        return overturning_check(
            loaded_alpha0(model), loaded_e_star(model), a_z, knowledge_level, behaviour_factor
        )
    # α0 = (B − x)/H of the moment balance (x = 0 about the edge): the clause's B/H with the
    # lever width the model's a_RM/g gives, B − x = (a_RM/g)·H
    height = model.wall.height
    return simple_overturning_check(
        model.a_rm_g * height, height, a_z, knowledge_level, behaviour_factor
    )


def time_history_result(
    peaks: Sequence[float],
    d0: float,
    d_limit: float,
    scale: float,
    limit_state: str,
    a_g: float | None = None,
) -> TimeHistoryResult:
    """The §C8.7.1.2.1.9 check of ``peaks`` [m] against d0 and d_limit [m], as results;
    ``a_g`` [g] the limit state's a_g·S the records were scaled to."""
    th = time_history_check(peaks, d0, d_limit)
    return TimeHistoryResult(
        scale=scale,
        peaks=tuple(_optional(p) for p in th.peaks),
        mean_peak=_optional(th.mean_peak),
        max_peak=_optional(th.max_peak),
        d0=th.d0,
        d_limit=th.d_limit,
        d0_respected=th.d0_respected,
        mean_respected=th.mean_respected,
        ratio=_optional(th.ratio) if math.isfinite(th.mean_peak) else 0.0,
        passed=th.passed,
        limit_state=limit_state,
        margin=th.margin,
        a_g=a_g,
    )


def _optional(x: float) -> float | None:
    return x if math.isfinite(x) else None


def _limit_state(check: LimitStateCheck, a_g_sld_value: float) -> LimitStateResult:
    return LimitStateResult(
        limit_state=check.limit_state,
        d_limit=check.d_limit,
        a_limit=check.a_limit,
        period=check.period,
        damping=check.damping,
        demand=check.demand,
        a_g=check.a_g,
        a_g_sld=a_g_sld_value,
        a_g_capacity=check.a_g_capacity,
        zeta_e=check.zeta_e,
        passed=check.passed,
    )


def case_checks(
    name: str,
    model: RockingModel,
    *,
    a_g: float,
    sd: DisplacementSpectrum,
    settings: CodeCheckSettings,
    floor_ratio_value: float = 1.0,
    motions: Sequence[tuple[NDArray[np.float64], float]] | None = None,
    ida: IdaSummary | None = None,
    slc: LimitStateDemand | None = None,
    ida_demand: float | None = None,
    ida_state: str | None = None,
) -> CaseChecks:
    """Every code check of one case (the wall of ``model`` with its bars, if any).

    Args:
        name: the case's name.
        model: its rocking model (wall, bars, options: the time-history check runs it).
        a_g: a_g·S of SLV [g], the demand of the linear and SLV checks.
        sd: elastic displacement spectrum at that intensity (:func:`displacement_spectrum`).
        settings: knowledge level, q, whether FC enters the dynamics.
        floor_ratio_value: a_Z,1/(a_g·S) (:func:`floor_ratio`; 1 at ground level).
        motions: the base motions at a_g (:func:`base_motions`); they are run ×FC when FC
            enters the dynamics; None: the time-history checks are not made.
        ida: the IDA's a_dyn of this case; None: no IDA line.
        slc: the action of SLC, its own spectrum; None: SLC is checked at the SLV action
            (one spectrum known).
        ida_demand: a_g·S [g] the deciding IDA line divides by (the assessment's limit state);
            None: ``a_g``.
        ida_state: the limit state of ``ida_demand`` (for the results).
    """
    fc = confidence_factor(settings.knowledge_level)
    curve = model_capacity_curve(model, fc)
    at_slv = LimitStateDemand(a_g, sd, floor_ratio_value, motions)
    at_slc = at_slv if slc is None else slc
    # a_g,SLD = a0*/(a_Z per unit a_g·S) (eq. C8.7.1.8), in g: a0* is in m/s²
    sld = curve.a0 / G / at_slv.floor_ratio
    sld_slc = curve.a0 / G / at_slc.floor_ratio
    slv_check = limit_state_check(curve, "SLV", at_slv.sd, at_slv.a_g, a_g_sld_value=sld)
    slc_check = limit_state_check(curve, "SLC", at_slc.sd, at_slc.a_g, a_g_sld_value=sld_slc)
    lin = linear_check(
        model, a_g * floor_ratio_value, settings.knowledge_level, settings.behaviour_factor
    )
    linear = LinearCheck(
        lin.a0_star, lin.demand, lin.behaviour_factor, lin.ratio, lin.passed, lin.alpha0
    )
    capacity = CapacitySummary(
        e_star=curve.e_star,
        m_star=curve.m_star,
        a0_star=curve.a0,
        a_max=curve.a_max,
        d0=curve.d0,
        stiffness=curve.stiffness,
        rupture_displacement=_optional(curve.rupture_displacement),
        rupture_limit=_optional(curve.rupture_limit),
    )
    scale = fc if settings.fc_in_ida else 1.0
    time_history = time_history_slc = None
    if at_slv.motions is not None:
        peaks = peak_displacements(model, at_slv.motions, scale)
        time_history = time_history_result(
            peaks, curve.d0, slv_check.d_limit, scale, "SLV", at_slv.a_g
        )
    if at_slc.motions is not None:
        if at_slc.motions is not at_slv.motions:
            peaks = peak_displacements(model, at_slc.motions, scale)
        time_history_slc = time_history_result(
            peaks, curve.d0, slc_check.d_limit, scale, "SLC", at_slc.a_g
        )
    ida_result = None
    ida_states: tuple[IdaCheck, ...] = ()
    if ida is not None:
        ida_fc = ida_confidence_factor(settings)
        demand = a_g if ida_demand is None else ida_demand
        ida_result = ida_check(ida, demand, ida_fc, ida_state)
        ida_states = (
            ida_check(ida, at_slv.a_g, ida_fc, "SLV"),
            ida_check(ida, at_slc.a_g, ida_fc, "SLC"),
        )
    return CaseChecks(
        case=name,
        capacity=capacity,
        linear=linear,
        slv=_limit_state(slv_check, sld),
        slc=_limit_state(slc_check, sld_slc),
        time_history=time_history,
        ida=ida_result,
        time_history_slc=time_history_slc,
        ida_limit_states=ida_states,
    )


def limit_state_demands(
    inputs: AssessmentInputs,
    records: Sequence[Record] | None,
    building: Building | None,
    state_records: Mapping[str, Sequence[Record]] | None = None,
) -> dict[str, LimitStateDemand]:
    """The action of every checked limit state (SLV, SLC) at its own spectrum
    (:func:`~frp_assess.assess.limit_states.limit_state_spectrum`), its motions from
    ``state_records`` where that state has its own set, else ``records``."""
    own = state_records or {}
    return {
        state: limit_state_demand(
            limit_state_spectrum(inputs, state), building, own.get(state, records)
        )
        for state in CHECKED_STATES
    }


def checks_at(
    name: str,
    model: RockingModel,
    inputs: AssessmentInputs,
    demands: Mapping[str, LimitStateDemand],
    ida: IdaSummary | None = None,
) -> CaseChecks:
    """:func:`case_checks` of one model at the actions of :func:`limit_state_demands`; the
    deciding IDA line at the assessment's limit state."""
    at_slv = demands["SLV"]
    return case_checks(
        name,
        model,
        a_g=at_slv.a_g,
        sd=at_slv.sd,
        settings=inputs.code_check,
        floor_ratio_value=at_slv.floor_ratio,
        motions=at_slv.motions,
        ida=ida,
        slc=demands["SLC"] if own_spectra(inputs) else None,
        ida_demand=inputs.spectrum.pga_g,
        ida_state=inputs.site_limit_state,
    )


def kinematic_checks(
    inputs: AssessmentInputs,
    *,
    records: Sequence[Record] | None = None,
    ida: Mapping[str, IdaSummary] | None = None,
    building: Building | None = None,
    state_records: Mapping[str, Sequence[Record]] | None = None,
) -> KinematicChecks:
    """The code checks of the unreinforced wall and of every retrofit option, each limit
    state at its own spectrum when the site is known (:mod:`~frp_assess.assess.limit_states`).

    Args:
        inputs: the assessment (wall, options, spectrum a_g·S, code-check settings).
        records: the ground records (each is scaled to PGA = a_g·S of the limit state here,
            :func:`base_motions`); None: no time-history check.
        ida: the IDA's a_dyn by case name; a case missing from it gets no IDA line.
        building: the building around a wall above ground; None: ``inputs.building`` (None
            there too: ground level).
        state_records: the records of a limit state that has its own set (artificial records
            generated for its spectrum, :func:`frp_assess.assess.seismic.build_records`);
            a state missing from it uses ``records``.
    """
    if building is None:
        building = inputs.building
    settings = inputs.code_check
    demands = limit_state_demands(inputs, records, building, state_records)
    cases = tuple(
        checks_at(name, model, inputs, demands, None if ida is None else ida.get(name))
        for name, model in zip(inputs.case_names(), inputs.case_models(), strict=True)
    )
    floor = None
    if building is not None and building.wall_base > 0.0:
        floor = FloorBasis(
            z_over_h=building.wall_base / building.height,
            storeys=building.storeys,
            period=building_period(building),
            damping=building.damping,
            floor_ratio=floor_ratio(inputs.spectrum, building),
        )
    return KinematicChecks(
        knowledge_level=settings.knowledge_level,
        fc=confidence_factor(settings.knowledge_level),
        fc_basis=fc_basis(settings),
        fc_in_ida=settings.fc_in_ida,
        a_g=inputs.spectrum.pga_g,
        floor=floor,
        cases=cases,
        intensities=tuple(
            intensity(inputs, state, (state_records or {}).get(state)) for state in CHECKED_STATES
        ),
        intensity_basis=intensity_basis(inputs),
    )
