"""Building the typed results of an assessment (:mod:`frp_assess.results.model`).

Each function turns one part of the computed assessment into its dataclass; ranking is a
pure function of the cases.  Serialisation is :mod:`frp_assess.results.json_io`.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from typing import Any

import numpy as np

from frp_assess import __version__
from frp_assess.assess.bars_as_built import design_as_built, option_as_built
from frp_assess.assess.code_check import KinematicCheck
from frp_assess.assess.collapse_fraction import collapse_fractions, fraction_fragility
from frp_assess.assess.decision import RANKING_RULE
from frp_assess.assess.floor_input import FloorSpectra
from frp_assess.assess.inputs import (
    UNREINFORCED,
    AssessmentInputs,
    Material,
    RetrofitOption,
)
from frp_assess.assess.kinematic_checks import ida_capacity_demand
from frp_assess.assess.loads_record import loads_result, tie_option_result, tie_prices_result
from frp_assess.assess.pivot_check import case_pivot
from frp_assess.assess.quantities import Quantity, built_quantity
from frp_assess.assess.recorded_inputs import (
    building_result,
    compliance_result,
    floor_spectra_result,
    material_result,
    seismic_result,
    wall_result,
)
from frp_assess.assess.runner import CaseSummary, DesignResult, design_value_rule
from frp_assess.assess.seismic import SeismicInput
from frp_assess.assess.site_result import site_result
from frp_assess.assess.statistics import (
    LognormalFragility,
    fit_lognormal_fragility,
    record_statistics,
)
from frp_assess.assess.verification import NumericalCheck
from frp_assess.dynamics import IdaSettings, RockingModel
from frp_assess.dynamics.effective import COARSE_STEPS, EARLY_STOP_BAND, FIRST_COLLAPSE_MARGIN
from frp_assess.motions import G
from frp_assess.results.checks import KinematicChecks
from frp_assess.results.model import (
    SCHEMA_VERSION,
    AssessmentResult,
    CaseResult,
    CodeCheck,
    Demand,
    DesignRow,
    Fragility,
    Governing,
    HistoryRun,
    NumericalCheckResult,
    RecordInfo,
    RecordResult,
    RuptureResult,
    Scatter,
    Sensitivity,
)
from frp_assess.results.run_inputs import (
    Costs,
    IdaSettingsResult,
    Integration,
    ModelSettings,
    ProjectInfo,
    Software,
)
from frp_assess.results.verdict import InterventionResult, Robustness

#: most points stored per time history in results.json
MAX_HISTORY_POINTS = 2500


def _finite(x: float | None) -> float | None:
    return None if x is None or not math.isfinite(x) else float(x)


def scatter_result(
    summary: CaseSummary, names: Sequence[str], demand: float, settings: IdaSettings
) -> Scatter:
    """How far the case's number can be trusted: record-to-record statistics of a_dyn [g]
    (records without collapse at their lower bound) and a lognormal fragility with
    P(collapse) at the demand a_g·S: with the effective collapse intensity (docs/model.md
    §11) fitted by binomial maximum likelihood to the collapse fraction of the records at each
    sampled intensity (:mod:`frp_assess.assess.collapse_fraction`); with the first collapse,
    to the collapse accelerations (the records without collapse right-censored)."""
    collapsed = [a is not None for a in summary.a_dyn]
    st = record_statistics(summary.a_dyn_bound, collapsed)
    fractions = collapse_fractions(summary.results, settings)
    fit: LognormalFragility | None = None
    if fractions:
        fit = fraction_fragility(fractions)
    else:
        exact = [a for a in summary.a_dyn if a is not None]
        if len(set(exact)) >= 2:
            censored = [
                b for a, b in zip(summary.a_dyn, summary.a_dyn_bound, strict=True) if a is None
            ]
            fit = fit_lognormal_fragility(exact, censored)
    fragility = None
    if fit is not None:
        fragility = Fragility(
            median=fit.median,
            beta=fit.beta,
            method=fit.method,
            p_collapse_at_demand=fit.probability(demand),
        )
    return Scatter(
        median_a_dyn=st.median,
        std_a_dyn=st.std,
        cov=st.cov,
        least_favourable_record=names[st.least_favourable_index],
        records_without_collapse=st.censored,
        fragility=fragility,
        collapse_fraction=fractions,
    )


def case_result(
    inputs: AssessmentInputs,
    option: RetrofitOption | None,
    model: RockingModel,
    summary: CaseSummary,
    names: Sequence[str],
    demand: float,
    urm_design: float,
    *,
    fc: float = 1.0,
    floor_pga: Sequence[float] | None = None,
) -> CaseResult:
    """One case, undecided and unranked (``rank`` None, ``passes`` None: the decision,
    :func:`frp_assess.assess.verdict_pipeline.assess_and_decide`, fills them).

    ``demand`` is a_g·S [g]; ``fc`` the confidence factor dividing the IDA capacity
    (:func:`~frp_assess.assess.kinematic_checks.ida_confidence_factor`), so capacity/demand =
    design a_dyn / (FC·a_g·S) (:func:`~frp_assess.assess.kinematic_checks.ida_capacity_demand`)
    and meets_target and the ranking follow it; the improvement stays a ratio of a_dyn.
    ``floor_pga``: PGA of each record's floor motion [g] for a wall above ground, else None.

    With its pivot check (:func:`~frp_assess.assess.pivot_check.case_pivot`) and, for an option,
    its bars as built (:func:`~frp_assess.assess.bars_as_built.option_as_built`): FRP mass and
    cost are then those of the bars as built (whole bars, bond lengths counted); an option
    that cannot be built (``bars.whole_bars: false``) keeps the smeared quantities of its
    ratio (:func:`~frp_assess.assess.quantities.built_quantity`).
    """
    pgas: Sequence[float | None] = [None] * len(names) if floor_pga is None else floor_pga
    records = tuple(
        RecordResult(
            record=name,
            pga=res.pga / G,
            collapse_multiplier=res.collapse_multiplier,
            survivor_multiplier=res.survivor_multiplier,
            a_dyn=a,
            q=res.q,
            # every time history of the search, by C: (C, collapsed, peak θ/α)
            curve=tuple((p.multiplier, p.collapsed, p.peak_ratio) for p in res.curve),
            floor_pga=fp,
            failure_mode=res.failure_mode,
            first_collapse_multiplier=res.first_collapse,
            windows_below=res.windows_below,
            lower_bound_multiplier=res.bound_multiplier
            if res.collapse_multiplier is None
            else None,
        )
        for name, res, a, fp in zip(names, summary.results, summary.a_dyn, pgas, strict=True)
    )
    built = None if option is None else option_as_built(inputs, option)
    material = None if option is None else option.material
    q = Quantity(0.0, 0.0, 0.0)
    if option is not None and material is not None and option.position is not None:
        q = built_quantity(inputs, built, material, option.position, option.ratio)
    cd = ida_capacity_demand(summary.design_a_dyn, demand, fc)
    return CaseResult(
        name=option.name if option else UNREINFORCED,
        material=material.name if material else None,
        position=option.position if option else None,
        ratio=option.ratio if option else 0.0,
        elastic_modulus=material.elastic_modulus if material else None,
        ultimate_strain=material.ultimate_strain if material else None,
        K=model.K,
        theta_max=_finite(model.theta_max) if material else None,
        records=records,
        mean_a_dyn=summary.mean_a_dyn,
        min_a_dyn=summary.min_a_dyn,
        mean_q=summary.mean_q,
        design_a_dyn=summary.design_a_dyn,
        lower_bound=summary.lower_bound,
        capacity_demand=cd,
        improvement=summary.design_a_dyn / urm_design,
        scatter=scatter_result(summary, names, demand, inputs.ida),
        frp_mass_per_m=q.mass_per_m,
        frp_mass=q.mass,
        frp_cost=q.cost,
        # the IDA check alone; the decision sets it again (false for a dropped option)
        meets_target=cd >= inputs.target,
        rank=None,
        ratio_asked=option.asked if option else None,
        as_built=built,
        pivot=case_pivot(inputs, option).result(),
        fc=fc,
        failure_mode=case_failure_mode(records),
        kind=None if option is None or option.kind == "bars" else option.kind,
        tie=None if option is None else tie_option_result(inputs, option),
    )


def case_failure_mode(records: Sequence[RecordResult]) -> str | None:
    """The failure mode met most often over ``records``; a tie goes to the mode of the least
    favourable record (lowest a_dyn) among the tied; None when none collapsed."""
    counts = Counter(r.failure_mode for r in records if r.failure_mode is not None)
    if not counts:
        return None
    top = max(counts.values())
    tied = {mode for mode, n in counts.items() if n == top}
    worst = min(
        (r for r in records if r.failure_mode in tied and r.a_dyn is not None),
        key=lambda r: r.a_dyn if r.a_dyn is not None else math.inf,
    )
    return worst.failure_mode


def below_collapse(collapse: float, survivor: float | None, tolerance: float) -> float:
    """The multiplier of the "just below collapse" time history.

    It is the largest multiplier the IDA ran without collapse (its bracket's C_lo), so the
    history shown surely survives; within ``tolerance`` of ``collapse``.  When the IDA's first
    try, C₀ (the onset of rocking), already collapsed there is none: C₀·(1 − tolerance) is
    used, below which the wall does not rock at all.
    """
    return survivor if survivor is not None else collapse * (1.0 - tolerance)


def code_check_result(
    check: KinematicCheck, mass: float, above_ground: bool = False, tie_options: bool = False
) -> CodeCheck:
    """The linear check of results.json (of the unreinforced wall's model); ``above_ground``:
    its demand is a_Z/q; ``tie_options``: some option adds a tie, whose α0 counts it."""
    same_alpha0 = (
        "Passive unbonded bars carry no load at rest, so α0 is the same for every bars option; "
        "a tie option's α0 counts its tie at its capacity (the internal work L_i of eq. C8.7.1.1). "
        if tie_options
        else "Passive unbonded bars carry no load at rest, so α0 is the same for every option. "
    )
    at_height = (
        " Above ground the demand is a_Z/q, a_Z the peak acceleration of the floor at the "
        "wall's base (Circolare 2019 eq. C7.2.7, first mode; §C8.7.1.2.1.7)."
        if above_ground
        else ""
    )
    return CodeCheck(
        alpha0=check.alpha0,
        e_star=check.e_star,
        M_star=mass,
        FC=check.fc,
        confidence_factor_level=check.knowledge_level,
        behaviour_factor=check.behaviour_factor,
        a0_star=check.a0_star,
        demand=check.demand,
        ratio=check.ratio,
        passed=check.passed,
        note="α0 = a_RM/g of the model the IDA runs (its moment balance about the corner, the "
        "reaction of the compressed zone at the base included). "
        + same_alpha0
        + "A supporting check: the IDA and the time-history checks decide."
        + at_height,
    )


def design_rows(
    inputs: AssessmentInputs,
    found: Sequence[DesignResult],
    cases: Sequence[str | None] | None = None,
) -> tuple[DesignRow, ...]:
    """Design mode's answers; mass [kg] and cost [currency] are those of the bars as built
    (bond lengths counted) when the answer has a layout, else of the smeared ratio;
    ``cases``: the case each answer is in the results (None: none)."""
    out = []
    names = list(cases) if cases is not None else [None] * len(found)
    for d, case in zip(found, names, strict=True):
        built = design_as_built(inputs, d)
        mass: float | None = None
        cost: float | None = None
        if d.ratio is not None:
            q = built_quantity(inputs, built, d.material, d.position, d.ratio)
            mass, cost = q.mass, q.cost
        out.append(
            DesignRow(
                material=d.material.name,
                position=d.position,
                ratio=d.ratio,
                capacity_demand=d.capacity_demand,
                frp_mass=mass,
                frp_cost=cost,
                message=d.message,
                as_built=built,
                case=case,
            )
        )
    return tuple(out)


def history_run(label: str, multiplier: float, res: Any, alpha: float) -> HistoryRun:
    """One time history, at most :data:`MAX_HISTORY_POINTS` points (every n-th sample)."""
    h = res.history
    n = h.computed
    step = max(1, math.ceil(n / MAX_HISTORY_POINTS))
    sl = slice(0, n, step)
    return HistoryRun(
        label=label,
        multiplier=multiplier,
        collapsed=res.collapsed,
        fate=res.fate,
        decided_time=res.decided_time,
        peak_rotation_ratio=res.max_rotation_ratio,
        peak_strain=res.peak_strain,
        ruptures=tuple(RuptureResult(time=r.time, side=r.side) for r in res.ruptures),
        impacts=res.impacts,
        time=tuple(np.round(h.time[sl], 6).tolist()),
        theta_over_alpha=tuple(np.round(h.theta[sl] / alpha, 8).tolist()),
        strain=tuple(np.round(h.strain[sl], 10).tolist()),
    )


def applied_restitution_ratio(inputs: AssessmentInputs) -> float:
    """The velocity ratio [-] applied at an impact: Eqs. 13–14 at the wall's slenderness α
    (the corners strike, in both pivot models; docs/model.md §1.1)."""
    return inputs.model_for(None).impact_velocity_ratio


def inputs_code_compliant(seismic: SeismicInput, checks: KinematicChecks | None) -> bool:
    """Whether every record set a verdict rests on passes the code's spectrum-compatibility
    checks (EC8 §3.2.3.1.2, NTC 2018 §3.2.3.6): the assessment's set, and the set a limit
    state generated for its own spectrum (the SLC time-history check decides too)."""
    own = () if checks is None else checks.intensities
    return bool(seismic.compliance.passed) and all(i.records_compliant is not False for i in own)


def build_results(
    *,
    inputs: AssessmentInputs,
    seismic: SeismicInput,
    cases: Sequence[CaseResult],
    recommended: str | None,
    check: KinematicCheck,
    design: Sequence[DesignResult] | None,
    governing: Governing | None,
    materials: dict[str, Material],
    created: str,
    numerical_check: NumericalCheck | None = None,
    sensitivity: Sensitivity | None = None,
    floor_spectra: FloorSpectra | None = None,
    kinematic_checks: KinematicChecks | None = None,
    design_cases: Sequence[str | None] | None = None,
    decision_rule: str = "",
    closest: str | None = None,
    robustness: Robustness | None = None,
    intervention: InterventionResult | None = None,
) -> AssessmentResult:
    """The whole result, from the ranked ``cases`` and the rest of the assessment
    (``floor_spectra`` for a wall above ground, :func:`frp_assess.assess.floor_input.floor_spectra`;
    ``kinematic_checks``, :func:`frp_assess.assess.kinematic_checks.kinematic_checks`)."""
    records = tuple(
        RecordInfo(
            name=r.name,
            source=r.source,
            pga=r.pga_g,
            duration=r.duration,
            dt=r.dt,
            scale_factor=seismic.scale_factor,
            sa=tuple(sa.tolist()),
        )
        for r, sa in zip(seismic.records, seismic.compliance.spectra, strict=True)
    )
    m = inputs.model

    return AssessmentResult(
        schema_version=SCHEMA_VERSION,
        software=Software(name="frp-assess", version=__version__),
        created=created,
        input_file=inputs.input_file,
        project=ProjectInfo(**inputs.project),
        wall=wall_result(inputs),
        model=ModelSettings(
            restitution=m.restitution,
            restitution_ratio=applied_restitution_ratio(inputs),
            rupture=m.rupture,
            collapse=m.collapse,
            strain_factor=inputs.strain_factor,
            free_vibration_tail=m.free_vibration_tail,
            integration=Integration(
                method="Dormand-Prince 5(4), local error control",
                tolerance=m.tolerance,
                verify=inputs.verify,
            ),
            ida=IdaSettingsResult(
                step_ratio=inputs.ida.step_ratio,
                tolerance=inputs.ida.tolerance,
                max_multiplier=inputs.ida.max_multiplier,
                capacity=inputs.ida.capacity,
                ladder_ratio=inputs.ida.ladder_ratio,
                offset=inputs.ida.offset,
                early_stop_band=EARLY_STOP_BAND,
                coarse_steps=COARSE_STEPS,
                fine_margin=FIRST_COLLAPSE_MARGIN,
            ),
            target=inputs.target,
            design_value=design_value_rule(len(seismic.records)),
        ),
        materials={k: material_result(v) for k, v in materials.items()},
        costs=Costs(
            currency=inputs.costs.currency,
            installation_per_metre=inputs.costs.installation_per_metre,
            ties=tie_prices_result(inputs),
        ),
        seismic=seismic_result(inputs, seismic),
        demand=Demand(pga=inputs.spectrum.pga_g),
        records=records,
        compliance=compliance_result(seismic),
        code_check=code_check_result(
            check,
            inputs.wall.mass,
            above_ground=inputs.building is not None,
            tie_options=any(o.tie is not None for o in inputs.options),
        ),
        cases=tuple(cases),
        ranking_rule=RANKING_RULE.format(target=inputs.target),
        recommended=recommended,
        # the unreinforced wall fails the decision (or, undecided, the IDA's target)
        retrofit_required=not (
            cases[0].passes if cases[0].passes is not None else cases[0].meets_target
        ),
        design=None if design is None else design_rows(inputs, design, design_cases),
        governing=governing,
        numerical_check=None
        if numerical_check is None
        else numerical_check_result(numerical_check, cases, seismic),
        input_warnings=(*inputs.warnings, *seismic.warnings),
        # false: the records fail the code's spectrum-compatibility checks; the CLI, TUI and
        # report then call the rank-1 option "best ranked", never "recommended"
        input_code_compliant=inputs_code_compliant(seismic, kinematic_checks),
        sensitivity=sensitivity,
        building=None if inputs.building is None else building_result(inputs.building),
        floor_spectra=None if floor_spectra is None else floor_spectra_result(floor_spectra),
        masonry_strength=inputs.masonry_strength,
        kinematic_checks=kinematic_checks,
        decision_rule=decision_rule,
        closest=closest,
        robustness=robustness,
        report=inputs.report,
        site=site_result(inputs.site, inputs.site_limit_state),
        loads=loads_result(inputs),
        intervention=intervention,
    )


def numerical_check_result(
    check: NumericalCheck, cases: Sequence[CaseResult], seismic: SeismicInput
) -> NumericalCheckResult:
    """The verification run of docs/model.md §4.5 (`analysis.integration.verify`)."""
    return NumericalCheckResult(
        tolerance=check.tolerance,
        check_tolerance=check.check_tolerance,
        max_change=None if math.isinf(check.max_change) else check.max_change,
        fate_changed=math.isinf(check.max_change),
        case=cases[check.case].name,
        record=seismic.records[check.record].name,
        changed_pairs=check.changed,
        pairs=check.pairs,
    )
