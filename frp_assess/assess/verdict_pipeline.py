"""From the IDAs of a run to one verdict an engineer can sign (docs/results-json.md, "The
decision").

After the IDA of every case: design mode (the smallest grid ratio passing every deciding
check, each answer added as a case), the code's kinematic checks of every case (the
time-history checks among them), the decision (:mod:`frp_assess.assess.decision`), the
sensitivity of the recommended (else the closest) case to the model conventions, and how
firm the verdict is: P(collapse) at FC·a_g·S, the decision with each record left out, the
case under each convention and who takes over when it fails.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import asdict, dataclass, replace

from frp_assess.assess.convention_sensitivity import convention_variants, sensitivity
from frp_assess.assess.decision import (
    IDA_CHECK,
    PIVOT_CHECK,
    TH_SLC,
    TH_SLV,
    Decision,
    Evidence,
    Requirements,
    Verdict,
    decide,
    decision_rule,
    intervention_result,
    requirements,
    time_history_deciding_check,
    verdict,
)
from frp_assess.assess.demand_window import near_demand, time_histories_pass
from frp_assess.assess.explain import remark
from frp_assess.assess.inputs import AssessmentInputs, RetrofitOption
from frp_assess.assess.kinematic_checks import (
    IdaSummary,
    checks_at,
    kinematic_checks,
    limit_state_demands,
)
from frp_assess.assess.results import case_result
from frp_assess.assess.robustness import robustness
from frp_assess.assess.runner import CaseSummary, DesignResult, IdaRunner, design_search, summarise
from frp_assess.config.schema import format_ratio
from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel
from frp_assess.motions import Record
from frp_assess.results.checks import CaseChecks, KinematicChecks, TimeHistoryResult
from frp_assess.results.model import CaseResult, Sensitivity, SensitivityRowResult
from frp_assess.results.verdict import ConventionOutcome, InterventionResult, Robustness

#: how many further options are tried, per failing convention, for the one that takes over
TAKE_OVER_CANDIDATES = 3

Report = Callable[[str, int, int], None]


class CheckContext:
    """The code checks of any model of one assessment, each limit state at its own action
    (:func:`~frp_assess.assess.kinematic_checks.limit_state_demands`)."""

    def __init__(
        self,
        inputs: AssessmentInputs,
        records: Sequence[Record],
        state_records: Mapping[str, Sequence[Record]] | None = None,
    ) -> None:
        self.inputs = inputs
        self.demands = limit_state_demands(inputs, records, inputs.building, state_records)
        #: what the category of the intervention asks of an option's checks (None: ζ_E ≥ 1)
        self.required: Requirements | None = None

    def checks(self, name: str, model: RockingModel) -> CaseChecks:
        """Every code check of ``model`` (the time histories at each limit state's action)."""
        return checks_at(name, model, self.inputs, self.demands)

    def screen(self, model: RockingModel) -> bool:
        """The time-history checks at SLV and SLC pass (design mode's cheap first test),
        against :attr:`required` when the category of the intervention asks another ζ_E."""
        c = self.checks("design", model)
        if self.required is None:
            return all(t is not None and t.passed for t in (c.time_history, c.time_history_slc))
        slv = _peaks(c.time_history)
        if slv is None:
            return False
        slc = _peaks(c.time_history_slc) or slv
        d0, r = c.capacity.d0, self.required
        return (
            time_history_deciding_check(slv, d0, c.slv.d_limit, TH_SLV, r[TH_SLV]).passed
            and time_history_deciding_check(slc, d0, c.slc.d_limit, TH_SLC, r[TH_SLC]).passed
        )


def evidence(
    case: CaseResult,
    summary: CaseSummary,
    checks: CaseChecks,
    demand: float,
    target: float,
) -> Evidence:
    """What the decision reads of one case; ``demand`` = FC·a_g·S [g]."""
    return Evidence(
        name=case.name,
        cost=case.option_cost,
        mass=case.option_mass,
        a_dyn=summary.a_dyn_bound,
        censored=tuple(a is None for a in summary.a_dyn),
        demand=demand,
        target=target,
        peaks=_peaks(checks.time_history),
        d0=checks.capacity.d0,
        d_slv=checks.slv.d_limit,
        d_slc=checks.slc.d_limit,
        peaks_slc=_peaks(checks.time_history_slc),
        dropped=not case.is_unreinforced and case.pivot is not None and case.pivot.dropped,
        unreinforced=case.is_unreinforced,
    )


def as_is_evidence(
    ctx: CheckContext, model: RockingModel, results: list[IdaResult], demand: float
) -> Evidence:
    """What the decision reads of the wall as it is (``model``, its IDA ``results``), before
    the cases are summarised: for design mode's requirement; ``demand`` = FC·a_g·S [g]."""
    inputs = ctx.inputs
    s = summarise(results, inputs.ida.max_multiplier, model.a_rm_g)
    c = ctx.checks("unreinforced", model)
    return Evidence(
        name="unreinforced",
        cost=0.0,
        mass=0.0,
        a_dyn=s.a_dyn_bound,
        censored=tuple(a is None for a in s.a_dyn),
        demand=demand,
        target=inputs.target,
        peaks=_peaks(c.time_history),
        d0=c.capacity.d0,
        d_slv=c.slv.d_limit,
        d_slc=c.slc.d_limit,
        peaks_slc=_peaks(c.time_history_slc),
        unreinforced=True,
    )


def _peaks(th: TimeHistoryResult | None) -> tuple[float, ...] | None:
    """The peaks [m] of a time-history check (inf: the wall fell); None: not run."""
    return None if th is None else tuple(math.inf if p is None else p for p in th.peaks)


def falls_inside(ev: Evidence) -> int:
    """Records that topple the wall at the design intensity although their IDA a_dyn (or its
    lower bound) reaches it."""
    if ev.peaks is None:
        return 0
    return sum(
        1
        for a, p in zip(ev.a_dyn, ev.peaks, strict=True)
        if not math.isfinite(p) and a >= ev.demand
    )


def decided_case(case: CaseResult, v: Verdict, rank: int | None, recommended: bool) -> CaseResult:
    """``case`` with its verdict; meets_target is the IDA check's own verdict (false when
    the pivot check drops the option)."""
    ida = next(c for c in v.checks if c.name == IDA_CHECK)
    dropped = any(c.name == PIVOT_CHECK for c in v.checks)
    return replace(
        case,
        deciding_checks=v.checks,
        passes=v.passes,
        governing_check=v.governing_check,
        governing_margin=v.governing_margin,
        governing_lower_bound=v.governing_lower_bound,
        meets_target=ida.passed and not dropped,
        rank=rank,
        recommended=recommended,
    )


@dataclass(frozen=True)
class DecidedRun:
    """Everything the decision adds to a run."""

    inputs: AssessmentInputs  #: with the design-mode answers added as options
    models: list[RockingModel]  #: of every case, in the order of ``cases``
    results: list[list[IdaResult]]  #: IDA of every case under every record
    cases: tuple[CaseResult, ...]
    recommended: str | None
    closest: str | None
    design: list[DesignResult] | None
    design_cases: list[str | None]  #: the case each design answer became (None: none/dup)
    checks: KinematicChecks
    sensitivity: Sensitivity
    robustness: Robustness
    decision_rule: str
    intervention: InterventionResult


def design_options(
    inputs: AssessmentInputs, design: Sequence[DesignResult]
) -> tuple[list[RetrofitOption], list[str | None]]:
    """The design answers as options, named "<material> <position> <ρ>‰ (design)", and the
    case each answer is (an existing option of the same material, position and model ratio
    keeps its own name and is not added again)."""
    added: list[RetrofitOption] = []
    names: list[str | None] = []
    for d in design:
        if d.ratio is None or d.ratio_model is None:
            names.append(None)
            continue
        same = next(
            (
                o
                for o in (*inputs.options, *added)
                if o.material is not None
                and o.tie is None
                and o.material.name == d.material.name
                and o.position == d.position
                and math.isclose(o.ratio, d.ratio_model, rel_tol=1e-9)
            ),
            None,
        )
        if same is not None:
            names.append(same.name)
            continue
        opt = RetrofitOption(
            name=f"{d.material.name} {d.position} {format_ratio(d.ratio)}‰ (design)",
            material=d.material,
            position=d.position,
            ratio=d.ratio_model,
            ratio_asked=d.ratio,
            layout=d.layout,
        )
        added.append(opt)
        names.append(opt.name)
    return added, names


def assess_and_decide(
    inputs: AssessmentInputs,
    runner: IdaRunner,
    sens_runner: IdaRunner,
    records: Sequence[Record],
    models: list[RockingModel],
    all_results: list[list[IdaResult]],
    *,
    fc: float,
    floor_pga: Sequence[float] | None,
    report: Report,
    state_records: Mapping[str, Sequence[Record]] | None = None,
) -> DecidedRun:
    """Design mode, the code checks, the decision and its robustness (module docstring).

    ``runner`` ran ``all_results`` (the cases of ``inputs``); ``sens_runner`` shares its cache
    and counts the sensitivity's IDAs apart; ``fc`` divides the IDA capacity;
    ``state_records`` the records of a limit state with its own set
    (:attr:`~frp_assess.assess.seismic.SeismicInput.state_records`).
    """
    names = [r.name for r in records]
    demand = inputs.spectrum.pga_g
    ctx = CheckContext(inputs, records, state_records)
    design: list[DesignResult] | None = None
    design_cases: list[str | None] = []
    if inputs.design is not None:
        pairs = [(m, p) for m in inputs.design.materials for p in inputs.design.positions]
        design = []
        # the category's requirement, from the wall as it is (the decision takes it again)
        ctx.required = requirements(
            as_is_evidence(ctx, models[0], all_results[0], fc * demand), inputs.intervention
        )
        ida_req = None if ctx.required is None else ctx.required[IDA_CHECK]
        for k, (mat, pos) in enumerate(pairs):
            report("design", k, len(pairs))
            design.append(
                design_search(
                    runner,
                    inputs,
                    mat,
                    pos,
                    fc * demand,
                    ctx.screen,
                    target=None if ida_req is None else ida_req.value,
                    strict=ida_req is not None and ida_req.strict,
                )
            )
        report("design", len(pairs), len(pairs))
        added, design_cases = design_options(inputs, design)
        if added:
            inputs = replace(inputs, options=(*inputs.options, *added))
            new_models = [inputs.model_for(o) for o in added]
            all_results = [*all_results, *runner.run(new_models)]
            models = [*models, *new_models]
            ctx.inputs = inputs
    summaries = [
        summarise(r, inputs.ida.max_multiplier, m.a_rm_g)
        for m, r in zip(models, all_results, strict=True)
    ]
    urm_design = summaries[0].design_a_dyn
    design_names = {n for n in design_cases if n is not None and n.endswith("(design)")}
    raw = [
        case_result(inputs, o, m, s, names, demand, urm_design, fc=fc, floor_pga=floor_pga)
        for o, m, s in zip([None, *inputs.options], models, summaries, strict=True)
    ]
    raw = [replace(c, source="design") if c.name in design_names else c for c in raw]

    report("checks", 0, 1)
    checks = kinematic_checks(
        inputs,
        records=list(records),
        ida={
            c.name: IdaSummary(s.mean_a_dyn, s.min_a_dyn, len(records))
            for c, s in zip(raw, summaries, strict=True)
        },
        building=inputs.building,
        state_records=state_records,
    )
    report("checks", 1, 1)
    ev = [
        evidence(c, s, k, fc * demand, inputs.target)
        for c, s, k in zip(raw, summaries, checks.cases, strict=True)
    ]
    decision = decide(ev, inputs.intervention)
    rank_of = {i: r for r, i in enumerate(decision.order, start=1)}
    cases = tuple(
        replace(
            decided_case(c, v, rank_of.get(i), i == decision.recommended),
            remark=remark(
                c, raw[0], models[i], models[0], inputs.building is not None, falls_inside(ev[i])
            ),
        )
        for i, (c, v) in enumerate(zip(raw, decision.verdicts, strict=True))
    )
    recommended = None if decision.recommended is None else cases[decision.recommended].name
    closest = None if decision.closest is None else cases[decision.closest].name

    focus = next((i for i in (decision.recommended, decision.closest) if i is not None), 0)
    report("sensitivity", 0, 1)
    outcomes, rows = conventions(
        sens_runner, ctx, models, ev, decision, focus, fc * demand, inputs.ida.max_multiplier
    )
    report("sensitivity", 1, 1)
    sens = Sensitivity(case=cases[focus].name, rows=rows)
    at_demand = time_histories_pass(checks.cases[focus])
    near = near_demand(cases[focus].name, models[focus], ctx.inputs, ctx.demands)
    robust = robustness(
        cases, ev, summaries[focus], decision, focus, outcomes, names, fc * demand,
        near=near, at_demand=at_demand,
    )  # fmt: skip
    return DecidedRun(
        inputs=inputs,
        models=models,
        results=all_results,
        cases=cases,
        recommended=recommended,
        closest=closest,
        design=design,
        design_cases=design_cases,
        checks=checks,
        sensitivity=sens,
        robustness=robust,
        decision_rule=decision_rule(inputs.intervention, inputs.target),
        intervention=intervention_result(ev[0], inputs.intervention),
    )


def _variant_verdict(
    runner: IdaRunner,
    ctx: CheckContext,
    base: Evidence,
    model: RockingModel,
    demand: float,
    max_multiplier: float,
    settings: IdaSettings | None = None,
    required: Requirements | None = None,
) -> tuple[Verdict, CaseSummary]:
    """The verdict of ``model`` (a convention variant of ``base``'s case; ``settings``: its
    IDA search when not the run's; ``required``: what the decision asked of the options)."""
    s = summarise(runner.run([model], settings=settings)[0], max_multiplier, model.a_rm_g)
    c = ctx.checks(base.name, model)
    ev = replace(
        base,
        a_dyn=s.a_dyn_bound,
        censored=tuple(a is None for a in s.a_dyn),
        peaks=_peaks(c.time_history),
        d0=c.capacity.d0,
        d_slv=c.slv.d_limit,
        d_slc=c.slc.d_limit,
        peaks_slc=_peaks(c.time_history_slc),
    )
    return verdict(ev, required), s


def conventions(
    runner: IdaRunner,
    ctx: CheckContext,
    models: Sequence[RockingModel],
    ev: Sequence[Evidence],
    decision: Decision,
    focus: int,
    demand: float,
    max_multiplier: float,
) -> tuple[tuple[ConventionOutcome, ...], tuple[SensitivityRowResult, ...]]:
    """The focus case under each model convention (:mod:`frp_assess.assess.convention_sensitivity`):
    its sensitivity rows, and whether it still passes; where the recommendation fails under a
    variant, the next passing options (as assessed, by rank; at most
    :data:`TAKE_OVER_CANDIDATES`) are run under the same variant and the first that passes
    takes over."""
    rows = tuple(
        SensitivityRowResult(**asdict(r))
        for r in sensitivity(runner, models[focus], demand, max_multiplier)
    )
    variants = convention_variants(models[focus], runner.settings)
    candidates = [i for i in decision.order if decision.verdicts[i].passes and i != focus][
        :TAKE_OVER_CANDIDATES
    ]
    out = []
    for j, (label, variant, settings) in enumerate(variants):
        v, _ = _variant_verdict(
            runner, ctx, ev[focus], variant, demand, max_multiplier, settings, decision.required
        )
        takes_over = None
        if decision.recommended == focus and not v.passes:
            for i in candidates:
                their = convention_variants(models[i], runner.settings)
                if j >= len(their):
                    continue
                vi, _ = _variant_verdict(
                    runner,
                    ctx,
                    ev[i],
                    their[j].model,
                    demand,
                    max_multiplier,
                    their[j].settings,
                    decision.required,
                )
                if vi.passes:
                    takes_over = ev[i].name
                    break
        out.append(
            ConventionOutcome(
                variant=label,
                passes=v.passes,
                governing_check=v.governing_check,
                governing_margin=v.governing_margin,
                takes_over=takes_over,
            )
        )
    return tuple(out), rows
