"""Prepare and run an assessment; show the last run again.

:func:`run_assessment` takes validated :class:`~frp_assess.assess.inputs.AssessmentInputs`,
orchestrates a run (the records, the IDA cache in the results folder, progress and
cancellation) around the engineering, which is :func:`frp_assess.assess.assessment_run.assess`
(cached parallel IDAs, ranking, sensitivity, design search, the code's checks), writes the
results directory as one set (:func:`frp_assess.app.report.write_outputs`) and returns the
typed results (:class:`~frp_assess.results.model.AssessmentResult`, docs/results-json.md).
:func:`prepare_run`, :func:`run_prepared` and :func:`load_previous` do the same from a
project being edited (the TUI).  Progress and cancellation are plain callables and
:class:`threading.Event`, never UI objects.
"""

from __future__ import annotations

import datetime as _dt
import threading
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from frp_assess.app.report import write_outputs
from frp_assess.app.rerun import project_digest, referenced_paths, unchanged_run, write_sidecar
from frp_assess.assess.assessment_run import assess
from frp_assess.assess.assessment_run import governing_histories as governing_histories
from frp_assess.assess.cache import IdaCache, cache_file, record_digest, task_key
from frp_assess.assess.from_project import inputs_from_project, load_inputs
from frp_assess.assess.inputs import UNREINFORCED, AssessmentInputs
from frp_assess.assess.runner import BatchRunner, IdaRunner
from frp_assess.assess.seismic import SeismicInput, build_records
from frp_assess.config import Project
from frp_assess.dynamics import run_batch
from frp_assess.errors import Cancelled, InputError
from frp_assess.io_utils import SOURCE_DATE_EPOCH, read_results_text, source_date
from frp_assess.motions import ComplianceReport
from frp_assess.output_set import check_out_dir
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult

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


def run_date() -> str:
    """The ISO date (``YYYY-MM-DD``, UTC) a run records as ``created``: the day of
    ``SOURCE_DATE_EPOCH`` [s since 1970-01-01 UTC] when that variable is set (the
    reproducible-builds convention: same input, same bytes), else today."""
    return source_date() or _dt.date.today().isoformat()


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
    batch: BatchRunner | None = None,
) -> tuple[AssessmentResult, RunStats]:
    """Run the assessment and write ``out_dir``; returns (results, stats).

    ``progress`` reports each stage overall; ``case_progress`` additionally names every
    (case, record) IDA of the "ida" stage as it finishes, for per-case progress bars.
    ``write=False`` returns the results without writing the result files (the cache is
    still read and filled): how the TUI shows the last run again when it opens a project.
    ``inputs_digest`` is written as results.json's ``inputs_digest`` (:mod:`frp_assess.app.
    rerun`).
    ``batch``: where the missing IDAs run (default local threads; a building run on Dask passes
    :func:`~frp_assess.study.run.executor_batch` of its executor).

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
    cache = IdaCache(out_dir / CACHE_DIR)
    runner = IdaRunner(
        seismic.records, inputs, cache, jobs=jobs, cancel=cancel, batch=batch or run_batch
    )
    results = assess(
        inputs, seismic, runner, created=created, report=report, case_progress=case_progress
    )
    if inputs_digest:
        results = replace(results, inputs_digest=inputs_digest)
    if write:
        report("writing", 0, 1)
        write_outputs(results, seismic, out_dir, pdf=pdf)
        report("writing", 1, 1)
    return results, RunStats(runner.computed, runner.reused, out_dir)


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
    check_out_dir(Path(out_dir), key="results folder")  # as `run --out`, before any work
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
        previous = from_json(read_results_text(stored), file=str(stored))
    except InputError:  # none, or not readable as this version
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
