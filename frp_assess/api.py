"""The one application API that the CLI, the TUI and the report call.

``run_assessment`` takes validated :class:`~frp_assess.assess.inputs.AssessmentInputs`, runs
everything, writes the results directory as one set (locked, staged, swapped in:
:mod:`frp_assess.output_set`) and returns the typed results
(:class:`~frp_assess.results.model.AssessmentResult`, docs/results-json.md).  Progress and
cancellation are plain callables/events.
"""

from __future__ import annotations

import datetime as _dt
import json
import math
import os
import re
import threading
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from importlib import resources
from pathlib import Path

from frp_assess.assess.cache import IdaCache, cache_file, record_digest, task_key
from frp_assess.assess.code_check import simple_overturning_check
from frp_assess.assess.floor_input import floor_record, floor_spectra
from frp_assess.assess.inputs import AssessmentInputs, Material
from frp_assess.assess.kinematic_checks import (
    IdaSummary,
    floor_ratio,
    ida_confidence_factor,
    kinematic_checks,
)
from frp_assess.assess.results import (
    below_collapse,
    build_results,
    case_result,
    history_run,
    rank_cases,
)
from frp_assess.assess.runner import (
    CaseSummary,
    DesignResult,
    IdaRunner,
    design_search,
    design_value_rule,
    summarise,
)
from frp_assess.assess.seismic import SeismicInput, build_records
from frp_assess.assess.sensitivity import sensitivity
from frp_assess.assess.verification import verify
from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel, RockingResult
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.motions import Record, write_at2
from frp_assess.output_set import FolderLock, staged_set
from frp_assess.results.csv_files import results_csv, spectra_csv
from frp_assess.results.json_io import to_json
from frp_assess.results.model import (
    AssessmentResult,
    CaseResult,
    Governing,
    Sensitivity,
    SensitivityRow,
)
from frp_assess.study import run as study_run
from frp_assess.study.run import Executor, StudyStats
from frp_assess.study.schema import StudyFile
from frp_assess.text_safety import plain

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
) -> tuple[AssessmentResult, RunStats]:
    """Run the assessment and write ``out_dir``; returns (results, stats).

    ``progress`` reports each stage overall; ``case_progress`` additionally names every
    (case, record) IDA of the "ida" stage as it finishes, for per-case progress bars.
    ``write=False`` returns the results without writing the result files (the cache is
    still read and filled): how the TUI shows the last run again when it opens a project.

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
    names = [r.name for r in records]
    demand = inputs.spectrum.pga_g
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
    # q = a_dyn / a_RM of each case's own model (about its pivot: docs/model.md §1.1)
    summaries = [
        summarise(r, inputs.ida.max_multiplier, m.a_rm_g)
        for m, r in zip(models, all_results, strict=True)
    ]
    urm_design = summaries[0].design_a_dyn
    options = [None, *inputs.options]
    # FC divides the IDA capacity (code_check.fc_in_ida): capacity/demand = a_dyn/(FC·a_g·S)
    fc = ida_confidence_factor(inputs.code_check)
    # the floor spectra at the wall's base, once (a wall above ground only)
    spectra = (
        None
        if inputs.building is None
        else floor_spectra(records, inputs.spectrum, inputs.building, floors=runner.motions)
    )
    floor_pga = None if spectra is None else spectra.floor_pga
    cases, recommended = rank_cases(
        [
            case_result(inputs, o, m, s, names, demand, urm_design, fc=fc, floor_pga=floor_pga)
            for o, m, s in zip(options, models, summaries, strict=True)
        ],
        inputs.target,
    )
    report("sensitivity", 0, 1)
    focus = next((i for i, c in enumerate(cases) if c.rank == 1), 0)
    # the same cache, its own counts: RunStats reports the assessment's IDAs
    sens_runner = IdaRunner(records, inputs, runner.cache, jobs=jobs, cancel=cancel)
    conventions = Sensitivity(
        case=cases[focus].name,
        rows=tuple(
            SensitivityRow(**asdict(row))
            for row in sensitivity(
                sens_runner, models[focus], fc * demand, inputs.ida.max_multiplier
            )
        ),
    )
    report("sensitivity", 1, 1)

    design: list[DesignResult] | None = None
    if inputs.design is not None:
        pairs = [(m, p) for m in inputs.design.materials for p in inputs.design.positions]
        design = []
        for k, (mat, pos) in enumerate(pairs):
            report("design", k, len(pairs))
            design.append(design_search(runner, inputs, mat, pos, fc * demand))
        report("design", len(pairs), len(pairs))

    report("checks", 0, 1)
    # the code's checks; the IDA's a_dyn passed in, only the time-history check runs the model
    checks = kinematic_checks(
        inputs,
        records=records,
        ida={
            c.name: IdaSummary(s.mean_a_dyn, s.min_a_dyn, len(records))
            for c, s in zip(cases, summaries, strict=True)
        },
        building=inputs.building,
    )
    report("checks", 1, 1)
    governing = governing_histories(inputs, cases, records, all_results, recommended)
    materials: dict[str, Material] = {}
    for o in inputs.options:
        materials.setdefault(o.material.name, o.material)
    if inputs.design is not None:
        for mat in inputs.design.materials:
            materials.setdefault(mat.name, mat)
    results = build_results(
        inputs=inputs,
        seismic=seismic,
        cases=cases,
        recommended=recommended,
        # above ground the linear check's demand is a_Z, the floor's peak acceleration at Z
        check=simple_overturning_check(
            inputs.thickness,
            inputs.height,
            demand * floor_ratio(inputs.spectrum, inputs.building),
            inputs.code_check.knowledge_level,
            inputs.code_check.behaviour_factor,
        ),
        design=design,
        governing=governing,
        materials=materials,
        created=created,
        numerical_check=numerical_check,
        sensitivity=conventions,
        floor_spectra=spectra,
        kinematic_checks=checks,
    )
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
    model = inputs.model_for(None if idx == 0 else inputs.options[idx - 1])
    rec = floor_record(records[k], inputs.building)  # the motion the IDA ran
    below = below_collapse(c, res[k].survivor_multiplier, inputs.ida.tolerance)
    alpha = model.alpha  # θ/α about the model's pivot (the edge's α, or α' with crushing)
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


def write_outputs(
    results: AssessmentResult, seismic: SeismicInput, out_dir: Path, *, pdf: bool
) -> None:
    """Write the output set — results.json, results.csv, spectra.csv, records/*.AT2 and (if
    ``pdf`` and available) report.pdf — as one set (:mod:`frp_assess.output_set`).

    The folder is locked for the duration, the set is written into a fresh staging folder
    inside ``out_dir`` and swapped in only once complete: any failure (disk full, an error in
    the PDF, an interrupt) leaves the previous set as it was.  A record name that is not a
    plain file name is refused (:class:`~frp_assess.errors.InputError`) before anything is
    written.
    """
    for rec in seismic.records:
        if not _is_plain_file_name(rec.name):
            raise InputError(
                f"record name {rec.name!r} cannot be a file name (no '/', '\\', '..', "
                "leading dot or control characters)",
                key="records",
            )
    with FolderLock(out_dir), staged_set(out_dir) as staging:
        for rec in seismic.records:
            write_at2(rec, staging / "records" / f"{rec.name}.AT2", f"{rec.name}: {rec.source}")
        atomic_write_text(staging / "spectra.csv", spectra_csv(results))
        atomic_write_text(staging / "results.csv", results_csv(results))
        atomic_write_text(staging / "results.json", to_json(results))
        if pdf:
            build_pdf(results, staging / "report.pdf")


def _is_plain_file_name(name: str) -> bool:
    return (
        bool(name)
        and not name.startswith(".")
        and "/" not in name
        and "\\" not in name
        and "\x00" not in name
        and name == plain(name)
        and len(name.encode("utf-8")) <= 200
    )


def build_pdf(results: AssessmentResult, path: Path) -> bool:
    """Build the PDF report if the report package is installed; returns whether it did."""
    try:
        from frp_assess.report.document import build_report
    except ImportError:
        return False
    build_report(results, path)
    return True


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
# The other commands: one time history, one IDA, a run's time history, a new project, a study.
# The CLI and the TUI call these; they build no models and run no IDA loops of their own.


def simulate(
    model: RockingModel, record: Record, scale: float = 1.0, *, history: bool = False
) -> RockingResult:
    """One time history of ``model`` under ``record`` scaled by ``scale`` [-] (``history``:
    keep θ(t), θ'(t) and the bar strain at the record's samples)."""
    if not (math.isfinite(scale) and scale > 0.0):
        raise ValueError(f"the record multiplier must be > 0, got {scale!r}")
    return model.run(record.acc, record.dt, scale, history=history)


@dataclass(frozen=True)
class IdaOutcome:
    """The IDA of one wall under a set of records, summarised as `run` summarises a case."""

    records: tuple[Record, ...]
    results: tuple[IdaResult, ...]  #: one per record, in order
    summary: CaseSummary  #: mean/least favourable/design a_dyn [g], the lower-bound rule
    design_value: str  #: how the design a_dyn is taken from the records (results.json wording)
    computed: int  #: IDAs computed (the others came from the cache)


def run_ida(
    model: RockingModel,
    records: Sequence[Record],
    settings: IdaSettings,
    *,
    jobs: int | None = None,
    cache_dir: Path | None = None,
    progress: Callable[[int, int], None] | None = None,
    cancel: threading.Event | None = None,
) -> IdaOutcome:
    """IDA of ``model`` under every record, through the cached runner of `run`
    (:class:`~frp_assess.assess.runner.IdaRunner`; ``cache_dir`` None: no cache), summarised
    by the one definition of the mean (a record without collapse up to C_max counts at
    C_max·PGA, a lower bound: :func:`~frp_assess.assess.runner.summarise`)."""
    runner = IdaRunner(
        records, None, IdaCache(cache_dir), jobs=jobs, cancel=cancel, settings=settings
    )
    results = runner.run([model], progress)[0]
    return IdaOutcome(
        tuple(records),
        tuple(results),
        summarise(results, settings.max_multiplier, model.a_rm_g),
        design_value_rule(len(results)),
        runner.computed,
    )


@dataclass(frozen=True)
class TimeHistory:
    """One case of a run under one of its records at one multiplier."""

    model: RockingModel  #: the case's wall, bars and options
    record: Record
    multiplier: float  #: C [-]
    result: RockingResult  #: with its history


def time_history(
    inputs: AssessmentInputs,
    records: Sequence[Record],
    case_index: int,
    record_index: int,
    multiplier: float,
) -> TimeHistory:
    """The time history of case ``case_index`` of a run (0: the unreinforced wall, then each
    option) under its record ``record_index`` scaled by ``multiplier``, as the IDA ran it (on
    the floor motion at Z for a wall above the ground floor)."""
    model = inputs.case_models()[case_index]
    rec = floor_record(records[record_index], inputs.building)
    res = simulate(model, rec, float(multiplier), history=True)
    return TimeHistory(model, rec, float(multiplier), res)


#: the project name in the packaged template, replaced by one taken from the file name
TEMPLATE_NAME = "Example wall"


def template_text() -> str:
    """The text of the packaged, commented template ``frp_assess/templates/wall.yaml``."""
    return resources.files("frp_assess").joinpath("templates/wall.yaml").read_text("utf-8")


def project_name_from_path(path: Path) -> str:
    """A project name from a file name, as a YAML scalar: ``north_wall.yaml`` ->
    ``north wall`` (none left: the template's); a name YAML would read otherwise is quoted
    (as a JSON string)."""
    name = path.stem.replace("_", " ").replace("-", " ").strip() or TEMPLATE_NAME
    if not re.fullmatch(r"[A-Za-z0-9][\w .()-]*", name):
        name = json.dumps(name, ensure_ascii=False)  # a JSON string is a quoted YAML scalar
    return name


def new_project_text(path: Path | None, template: str | None = None) -> str:
    """The text of a new project (`frp-assess new`, the TUI's new project): ``template``
    (default: the packaged one) with the project named after ``path`` (None: unchanged)."""
    text = template or template_text()
    if path is None:
        return text
    return text.replace(f"name: {TEMPLATE_NAME}", f"name: {project_name_from_path(path)}", 1)


def run_study(
    study: StudyFile,
    out_dir: Path,
    *,
    executor: Executor | None = None,
    jobs: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    cancel: threading.Event | None = None,
    records: dict[str, list[Record]] | None = None,
    figures: bool = True,
) -> tuple[StudyStats, list[Path]]:
    """Run a parametric study into ``out_dir`` (chunked, cached, resumable:
    :func:`frp_assess.study.run.run_study`, on the cached runner of `run`) and, if
    ``figures``, write its PDF; returns the run's counts and the figure files written."""
    stats = study_run.run_study(
        study,
        out_dir,
        jobs=jobs,
        executor=executor,
        progress=progress,
        cancel=cancel,
        records=records,
    )
    written: list[Path] = []
    if figures:
        from frp_assess.study.figures import write_study_pdf

        written = list(write_study_pdf(out_dir))
    return stats, written
