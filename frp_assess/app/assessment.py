"""Prepare and run an assessment; show the last run again.

:func:`run_assessment` takes validated :class:`~frp_assess.assess.inputs.AssessmentInputs`,
runs everything (records, cached parallel IDAs, ranking, sensitivity, design search, the
code's checks), writes the results directory as one set (:func:`frp_assess.app.report.
write_outputs`) and returns the typed results (:class:`~frp_assess.results.model.
AssessmentResult`, docs/results-json.md).  :func:`prepare_run`, :func:`run_prepared` and
:func:`load_previous` do the same from a project being edited (the TUI).  Progress and
cancellation are plain callables and :class:`threading.Event`, never UI objects.
"""

from __future__ import annotations

import datetime as _dt
import os
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from frp_assess.app.report import write_outputs
from frp_assess.app.rerun import project_digest, referenced_paths, unchanged_run, write_sidecar
from frp_assess.assess.cache import IdaCache, cache_file, record_digest, task_key
from frp_assess.assess.floor_input import floor_record, floor_spectra
from frp_assess.assess.from_project import inputs_from_project, load_inputs
from frp_assess.assess.inputs import UNREINFORCED, AssessmentInputs, Material
from frp_assess.assess.kinematic_checks import floor_ratio, ida_confidence_factor, linear_check
from frp_assess.assess.limit_states import limit_state_spectrum
from frp_assess.assess.results import (
    below_collapse,
    build_results,
    history_run,
)
from frp_assess.assess.runner import (
    IdaRunner,
)
from frp_assess.assess.seismic import SeismicInput, build_records
from frp_assess.assess.verdict_pipeline import assess_and_decide
from frp_assess.assess.verification import verify
from frp_assess.config import Project
from frp_assess.dynamics.effective import collapse_and_below
from frp_assess.errors import Cancelled, InputError
from frp_assess.motions import ComplianceReport
from frp_assess.results.json_io import from_json
from frp_assess.results.model import (
    AssessmentResult,
    CaseResult,
    Governing,
)

__all__ = [
    "CACHE_DIR",
    "UNREINFORCED",
    "AssessmentInputs",
    "ComplianceReport",
    "PairDone",
    "PreparedRun",
    "Progress",
    "RunOutcome",
    "SOURCE_DATE_EPOCH",
    "RunStats",
    "SeismicInput",
    "default_out_dir",
    "governing_histories",
    "inputs_from_project",
    "load_inputs",
    "load_previous",
    "missing_idas",
    "prepare_records",
    "prepare_run",
    "run_assessment",
    "run_date",
    "run_prepared",
]

#: progress(stage, done, total); stages: "records", "ida", "verify", "sensitivity",
#: "design", "checks", "writing"
Progress = Callable[[str, int, int], None]
#: case_progress(case_index, record_index): one (case, record) IDA of the "ida" stage finished
#: (case 0 is the unreinforced wall); called from the worker threads
PairDone = Callable[[int, int], None]

CACHE_DIR = ".cache"


@dataclass(frozen=True)
class RunStats:
    computed: int  #: (case, record) IDAs computed in this run
    reused: int  #: (case, record) IDAs taken from the cache
    out_dir: Path


def _noop(stage: str, done: int, total: int) -> None:
    return None


#: seconds since 1970-01-01 UTC that fix the date of a run (reproducible-builds.org)
SOURCE_DATE_EPOCH = "SOURCE_DATE_EPOCH"


def run_date() -> str:
    """The ISO date (``YYYY-MM-DD``, UTC) a run records as ``created``: the day of
    ``SOURCE_DATE_EPOCH`` [s since 1970-01-01 UTC] when that variable is set (the
    reproducible-builds convention: same input, same bytes), else today."""
    epoch = os.environ.get(SOURCE_DATE_EPOCH, "")
    if not epoch:
        return _dt.date.today().isoformat()
    try:
        when = _dt.datetime.fromtimestamp(int(epoch), tz=_dt.UTC)
    except (ValueError, OverflowError, OSError):
        raise InputError(
            f"expected whole seconds since 1970-01-01 UTC, found {epoch!r}",
            key=SOURCE_DATE_EPOCH,
        ) from None
    return when.date().isoformat()


def prepare_records(inputs: AssessmentInputs) -> SeismicInput:
    """Generate or read the records and check them (the first stage of a run)."""
    return build_records(inputs)


def run_assessment(
    inputs: AssessmentInputs,
    out_dir: Path,
    *,
    jobs: int | None = None,
    progress: Progress | None = None,
    case_progress: PairDone | None = None,
    cancel: threading.Event | None = None,
    seismic: SeismicInput | None = None,
    created: str | None = None,
    pdf: bool = True,
    write: bool = True,
    inputs_digest: str | None = None,
) -> tuple[AssessmentResult, RunStats]:
    """Run the assessment and write ``out_dir``; returns (results, stats).

    ``progress`` reports each stage overall; ``case_progress`` additionally names every
    (case, record) IDA of the "ida" stage as it finishes, for per-case progress bars.
    ``write=False`` returns the results without writing the result files (the cache is
    still read and filled): how the TUI shows the last run again when it opens a project.
    ``inputs_digest`` is written as results.json's ``inputs_digest`` (:mod:`frp_assess.app.
    rerun`).

    Finished (case, record) IDAs are cached in ``out_dir/.cache`` as they complete, so a
    cancelled run (:class:`~frp_assess.errors.Cancelled`) loses nothing; result files are
    only written once everything is computed, as one set (:func:`write_outputs`, which
    locks the folder; ``frp-assess run`` holds that lock for the whole run).
    """
    report = progress or _noop
    created = created or run_date()  # a bad SOURCE_DATE_EPOCH stops here, before any work
    out_dir = Path(out_dir)
    if seismic is None:
        report("records", 0, 1)
        seismic = build_records(inputs)
        report("records", 1, 1)
    records = seismic.records
    runner = IdaRunner(records, inputs, IdaCache(out_dir / CACHE_DIR), jobs=jobs, cancel=cancel)

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
        # the same cache, its own counts: RunStats reports the assessment's IDAs
        IdaRunner(records, inputs, runner.cache, jobs=jobs, cancel=cancel),
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
    materials: dict[str, Material] = {}
    for o in inputs.options:
        materials.setdefault(o.material.name, o.material)
    if inputs.design is not None:
        for mat in inputs.design.materials:
            materials.setdefault(mat.name, mat)
    slv = limit_state_spectrum(inputs, "SLV")
    results = build_results(
        inputs=inputs,
        seismic=seismic,
        cases=cases,
        recommended=recommended,
        # the linear check is an SLV check (eq. C8.7.1.9), at the SLV spectrum; above ground
        # its demand is a_Z, the floor's peak acceleration at Z
        check=linear_check(
            models[0],
            slv.pga_g * floor_ratio(slv, inputs.building),
            inputs.code_check.knowledge_level,
            inputs.code_check.behaviour_factor,
        ),
        design=decided.design,
        governing=governing,
        materials=materials,
        created=created,
        numerical_check=numerical_check,
        sensitivity=decided.sensitivity,
        floor_spectra=spectra,
        kinematic_checks=decided.checks,
        design_cases=decided.design_cases,
        decision_rule=decided.decision_rule,
        closest=decided.closest,
        robustness=decided.robustness,
    )
    if inputs_digest:
        results = replace(results, inputs_digest=inputs_digest)
    if write:
        report("writing", 0, 1)
        write_outputs(results, seismic, out_dir, pdf=pdf)
        report("writing", 1, 1)
    return results, RunStats(runner.computed, runner.reused, out_dir)


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


def missing_idas(inputs: AssessmentInputs, seismic: SeismicInput, out_dir: Path) -> int:
    """How many (case, record) IDAs of a run are not in ``out_dir``'s cache yet (0: the IDA
    stage of a run computes nothing; design mode may still search new ratios, and a cache
    written before the sensitivity table existed lacks its variants)."""
    directory = Path(out_dir) / CACHE_DIR
    hashes = [record_digest(r.acc, r.dt) for r in seismic.records]
    return sum(
        not cache_file(directory, task_key(m, h, inputs.ida, inputs.building)).is_file()
        for m in inputs.case_models()
        for h in hashes
    )


def default_out_dir(project_file: Path) -> Path:
    """``<stem>-results/`` next to the project file."""
    return project_file.with_name(f"{project_file.stem}-results")


# ----------------------------------------------------------------------------------------------
# A project being edited (the TUI): the same inputs, cache and result files as `run`.


@dataclass(frozen=True)
class PreparedRun:
    """A project turned into assessment inputs, with its records generated or read and
    checked: the first stage of a run, after which the cases and records are known."""

    project: Project
    inputs: AssessmentInputs
    seismic: SeismicInput


@dataclass(frozen=True)
class RunOutcome:
    """A finished run: what the results, the plots and the history viewer need."""

    results: AssessmentResult
    seismic: SeismicInput
    inputs: AssessmentInputs
    out_dir: Path
    stats: RunStats
    project: Project


def prepare_run(
    project: Project, base_dir: Path, input_file: str, *, progress: Progress | None = None
) -> PreparedRun:
    """The inputs of ``project`` (record paths relative to ``base_dir``; ``input_file`` is
    the name results.json records) and its records (:func:`prepare_records`), reported as
    the "records" stage (0 of 1 once the inputs are valid, 1 of 1 when the records are
    ready)."""
    report = progress or _noop
    inputs = inputs_from_project(project, base_dir, input_file)
    report("records", 0, 1)
    seismic = prepare_records(inputs)
    report("records", 1, 1)
    return PreparedRun(project, inputs, seismic)


def run_prepared(
    prepared: PreparedRun,
    out_dir: Path,
    *,
    cancel: threading.Event,
    progress: Progress | None = None,
    case_progress: PairDone | None = None,
    jobs: int | None = None,
    project_file: Path | None = None,
) -> RunOutcome:
    """Every IDA (cached in ``out_dir/.cache``), ranking and result files, report.pdf and
    report.docx included, as ``frp-assess run`` writes them.

    ``project_file``: the file the project was read from, when the project run is that
    file's content (not edited since): its inputs' digest (:func:`frp_assess.app.rerun.
    project_digest`, with ``run``'s default options) goes into results.json and the
    sidecar, as ``frp-assess run`` records it, so a later unchanged ``run`` recomputes
    nothing and the results can be told stale.  None (an edited, unsaved project): no
    digest, since no file holds these inputs.

    Raises :class:`~frp_assess.errors.Cancelled` when ``cancel`` is set (finished IDAs stay
    in the cache), :class:`~frp_assess.errors.InputError` for a problem the user can fix.
    """
    if cancel.is_set():
        raise Cancelled("cancelled")
    digest = None
    if project_file is not None:
        digest = project_digest(project_file, prepared.project)
    results, stats = run_assessment(
        prepared.inputs,
        out_dir,
        jobs=jobs,
        progress=progress,
        case_progress=case_progress,
        cancel=cancel,
        seismic=prepared.seismic,
        pdf=True,
        inputs_digest=digest,
    )
    if digest is not None:
        files = referenced_paths(prepared.project)
        write_sidecar(Path(out_dir), digest, results.created, files, pdf=True)
    return RunOutcome(
        results, prepared.seismic, prepared.inputs, Path(out_dir), stats, prepared.project
    )


def load_previous(
    project: Project,
    base_dir: Path,
    input_file: str,
    out_dir: Path,
    *,
    cancel: threading.Event,
    jobs: int | None = None,
    project_file: Path | None = None,
) -> RunOutcome | None:
    """The last run into ``out_dir`` again, for the project as it is.

    ``project_file``: the file ``project`` was read from, when ``project`` is that file's
    content.  When the stored run is that of the file's inputs as they are now
    (:func:`frp_assess.app.rerun.unchanged_run`, the rule that makes an unchanged
    ``frp-assess run`` recompute nothing: the digest of the inputs, the output set complete,
    results.json the one the run wrote), its results are shown as read.
    Otherwise they are rebuilt from the cache, and no result file is written (a design-mode
    search may add IDAs to the cache).  None when there was no run (no ``results.json``) or
    when some (case, record) IDA of the project is not in the cache (the project changed
    since the run); the date of the results is that of the stored run.
    """
    stored = Path(out_dir) / "results.json"
    try:
        previous = from_json(stored.read_text(encoding="utf-8"), file=str(stored))
    except (OSError, UnicodeDecodeError, InputError):  # none, or not readable as this version
        return None
    inputs = inputs_from_project(project, base_dir, input_file)
    seismic = prepare_records(inputs)
    if project_file is not None and unchanged_run(project_file, out_dir, pdf=False):
        stats = RunStats(0, 0, Path(out_dir))  # no IDA computed, none read from the cache
        return RunOutcome(previous, seismic, inputs, Path(out_dir), stats, project)
    if missing_idas(inputs, seismic, out_dir):
        return None
    results, stats = run_assessment(
        inputs,
        out_dir,
        jobs=jobs,
        cancel=cancel,
        seismic=seismic,
        created=previous.created,
        write=False,
        inputs_digest=previous.inputs_digest,
    )
    return RunOutcome(results, seismic, inputs, Path(out_dir), stats, project)
