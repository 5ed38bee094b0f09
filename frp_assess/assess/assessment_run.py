"""The engineering of one assessment: from the checked records to the typed results.

:func:`assess` runs the IDA of every case (through the runner's cache), the numerical check,
the floor spectra of a wall above ground, the design search, the code's checks and the one
decision (:func:`frp_assess.assess.verdict_pipeline.assess_and_decide`), the SLV linear
check, the governing time histories and the materials, and returns
:class:`~frp_assess.results.model.AssessmentResult`.  What the service around it does
(:func:`frp_assess.app.assessment.run_assessment`) is orchestration only: where the cache
and the outputs go, progress, the date and the digest of the inputs, writing the files.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace

from frp_assess.assess.floor_input import floor_record, floor_spectra
from frp_assess.assess.independent_checks import independent_checks
from frp_assess.assess.inputs import AssessmentInputs, Material
from frp_assess.assess.kinematic_checks import (
    KinematicCheck,
    floor_ratio,
    ida_confidence_factor,
    linear_check,
)
from frp_assess.assess.limit_states import limit_state_spectrum
from frp_assess.assess.results import below_collapse, build_results, history_run
from frp_assess.assess.runner import IdaRunner
from frp_assess.assess.seismic import SeismicInput
from frp_assess.assess.verdict_pipeline import assess_and_decide
from frp_assess.assess.verification import verify
from frp_assess.dynamics import RockingModel
from frp_assess.dynamics.effective import collapse_and_below
from frp_assess.results.model import AssessmentResult, CaseResult, Governing

#: progress(stage, done, total); stages: "ida", "verify", "sensitivity", "design", "checks"
Progress = Callable[[str, int, int], None]
#: case_progress(case_index, record_index): one (case, record) IDA finished
PairDone = Callable[[int, int], None]


def materials_of(inputs: AssessmentInputs) -> dict[str, Material]:
    """The bar materials of a run by name, each once: the options' in their order, then
    those design mode may choose."""
    materials: dict[str, Material] = {}
    for o in inputs.options:
        if o.material is not None:
            materials.setdefault(o.material.name, o.material)
    if inputs.design is not None:
        for mat in inputs.design.materials:
            materials.setdefault(mat.name, mat)
    return materials


def slv_linear_check(inputs: AssessmentInputs, model: RockingModel) -> KinematicCheck:
    """The linear check a0* ≥ a/q of ``model`` (the unreinforced wall): an SLV check
    (Circolare 2019 §C8.7.1.2.1.7, eq. C8.7.1.9), at the SLV spectrum; its demand is a_g·S at
    ground level, above it a_Z, the floor's peak acceleration at Z [g]."""
    slv = limit_state_spectrum(inputs, "SLV")
    return linear_check(
        model,
        slv.pga_g * floor_ratio(slv, inputs.building),
        inputs.code_check.knowledge_level,
        inputs.code_check.behaviour_factor,
    )


def governing_histories(
    inputs: AssessmentInputs,
    cases: Sequence[CaseResult],
    records: list,
    all_results: list,
    recommended: str | None,
) -> Governing | None:
    """θ/α(t) and bar strain of the recommended option (else the unreinforced wall) under the
    record that fails first, at the collapse multiplier and just below it."""
    idx = next((i for i, c in enumerate(cases) if c.name == recommended), 0)
    res = all_results[idx]
    failing = [(r.collapse_multiplier, k) for k, r in enumerate(res) if r.collapse_multiplier]
    if not failing:
        return None
    c, k = min(failing)
    survivor = res[k].survivor_multiplier
    if res[k].capacity == "effective":
        # the effective capacity is no sample (docs/model.md §11): show the first time history
        # that collapsed at or above it, and the largest one below that stood
        c, survivor = collapse_and_below(res[k].curve, c)
    model = inputs.model_for(None if idx == 0 else inputs.options[idx - 1])
    rec = floor_record(records[k], inputs.building)  # the motion the IDA ran
    below = below_collapse(c, survivor, inputs.ida.tolerance)
    alpha = model.alpha  # θ/α_x: α_x = atan((B − x_W)/H), the edge's α with pivot: edge
    runs = (
        history_run("collapse", c, model.run(rec.acc, rec.dt, c, history=True), alpha),
        history_run("just below", below, model.run(rec.acc, rec.dt, below, history=True), alpha),
    )
    bars = model.rebars
    return Governing(
        case=cases[idx].name,
        record=rec.name,
        runs=runs,
        rupture_strain=None if bars is None else bars.rupture_strain,
    )


def assess(
    inputs: AssessmentInputs,
    seismic: SeismicInput,
    runner: IdaRunner,
    *,
    created: str,
    report: Progress,
    case_progress: PairDone | None = None,
) -> AssessmentResult:
    """Every computation of an assessment of ``inputs`` under ``seismic``'s records.

    ``runner`` runs (and caches) the IDAs of the cases, and counts them (``computed``,
    ``reused``); design mode and the sensitivity run theirs through a runner of their own on
    the same cache, so that those counts are the assessment's.  ``created``: the ISO date
    the results record.
    """
    records = seismic.records
    models = inputs.case_models()
    all_results = runner.run(
        models, progress=lambda d, n: report("ida", d, n), on_pair=case_progress
    )
    numerical_check = None
    if inputs.verify:
        numerical_check = verify(
            runner,
            models,
            all_results,
            inputs.ida.tolerance,
            progress=lambda d, n: report("verify", d, n),
        )
    # FC divides the IDA capacity (code_check.fc_in_ida): capacity/demand = a_dyn/(FC·a_g·S)
    fc = ida_confidence_factor(inputs.code_check)
    # the floor spectra at the wall's base, once (a wall above ground only)
    spectra = (
        None
        if inputs.building is None
        else floor_spectra(records, inputs.spectrum, inputs.building, floors=runner.motions)
    )
    floor_pga = None if spectra is None else spectra.floor_pga
    # design mode, the code checks, the one decision rule and how firm it is
    # (frp_assess.assess.verdict_pipeline); the design answers join the cases
    decided = assess_and_decide(
        inputs,
        runner,
        IdaRunner(
            records,
            inputs,
            runner.cache,
            jobs=runner.jobs,
            cancel=runner.cancel,
            batch=runner.batch,
        ),
        records,
        models,
        all_results,
        fc=fc,
        floor_pga=floor_pga,
        report=report,
        state_records=seismic.state_records,
    )
    inputs, cases, recommended = decided.inputs, decided.cases, decided.recommended
    all_results = decided.results
    governing = governing_histories(inputs, cases, records, all_results, recommended)
    results = build_results(
        inputs=inputs,
        seismic=seismic,
        cases=cases,
        recommended=recommended,
        check=slv_linear_check(inputs, models[0]),
        design=decided.design,
        governing=governing,
        materials=materials_of(inputs),
        created=created,
        numerical_check=numerical_check,
        sensitivity=decided.sensitivity,
        floor_spectra=spectra,
        kinematic_checks=decided.checks,
        design_cases=decided.design_cases,
        decision_rule=decided.decision_rule,
        closest=decided.closest,
        robustness=decided.robustness,
        intervention=decided.intervention,
    )
    # NTC 2018 §10.2: the checks of the run by routes it did not take (assess/independent_checks)
    checks = independent_checks(
        inputs.case_models(),
        inputs.case_names(),
        runner.motions,
        results.cases,
        results.recommended or results.closest,
        scale=fc,
        ida_tolerance=inputs.ida.tolerance,
        numerical=results.numerical_check,
    )
    return replace(results, independent_checks=checks)
