"""The long operations of the TUI as plain functions (run, time history, export, save).

They run in Textual worker threads and talk back through an ``emit`` callable, so they can
be tested without a terminal.  Everything goes through the application API
(:mod:`frp_assess.api`): the same inputs, cache and result files as ``frp-assess run``.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from frp_assess.api import (
    RunStats,
    missing_idas,
    prepare_records,
    run_assessment,
    time_history,
    write_outputs,
)
from frp_assess.assess.from_project import inputs_from_project
from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.assess.seismic import SeismicInput
from frp_assess.config import Project, dump_project, load_project_text
from frp_assess.config.yaml_update import update_project_text
from frp_assess.errors import Cancelled, InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.tui.core.progress import CaseCount, CaseProgress


@dataclass(frozen=True)
class RunEvent:
    """Progress of a run.

    Attributes:
        stage: ``records`` | ``ida`` | ``design`` | ``writing`` (as the API reports them).
        done, total: progress of the stage (IDAs for ``ida``).
        cases: per-case counts during the ``ida`` stage, else None.
        message: a line for the run log (may be empty).
    """

    stage: str
    done: int
    total: int
    cases: tuple[CaseCount, ...] | None = None
    message: str = ""


Emit = Callable[[RunEvent], None]


@dataclass(frozen=True)
class RunOutcome:
    """A finished run: what the results, the plots and the history viewer need."""

    results: AssessmentResult
    seismic: SeismicInput
    inputs: AssessmentInputs
    out_dir: Path
    stats: RunStats
    project: Project


def execute_run(
    project: Project,
    base_dir: Path,
    input_file: str,
    out_dir: Path,
    *,
    cancel: threading.Event,
    emit: Emit,
    jobs: int | None = None,
) -> RunOutcome:
    """Records, then every IDA (cached in ``out_dir/.cache``), ranking and result files,
    report.pdf included, as ``frp-assess run`` writes them.

    Raises :class:`~frp_assess.errors.Cancelled` when ``cancel`` is set (finished IDAs stay
    in the cache), :class:`~frp_assess.errors.InputError` for a problem the user can fix.
    """
    inputs = inputs_from_project(project, base_dir, input_file)
    emit(RunEvent("records", 0, 1, message="generating/reading the records"))
    seismic = prepare_records(inputs)
    rep = seismic.compliance
    failed = [c for c in rep.checks if not c.passed]
    emit(
        RunEvent(
            "records",
            1,
            1,
            message=f"{len(seismic.records)} records; spectrum compatibility: "
            + ("all checks passed" if not failed else f"{len(failed)} check(s) FAILED"),
        )
    )
    if cancel.is_set():
        raise Cancelled("cancelled")
    tracker = CaseProgress(inputs, len(seismic.records))

    def progress(stage: str, done: int, total: int) -> None:
        if stage == "ida":
            emit(RunEvent(stage, done, total, tuple(tracker.counts())))
        else:
            emit(RunEvent(stage, done, total))

    results, stats = run_assessment(
        inputs,
        out_dir,
        jobs=jobs,
        progress=progress,
        case_progress=tracker.mark,
        cancel=cancel,
        seismic=seismic,
        pdf=True,
    )
    return RunOutcome(results, seismic, inputs, Path(out_dir), stats, project)


def load_previous(
    project: Project,
    base_dir: Path,
    input_file: str,
    out_dir: Path,
    *,
    cancel: threading.Event,
    jobs: int | None = None,
) -> RunOutcome | None:
    """The last run into ``out_dir`` again, rebuilt from its cache for the project as it is.

    No result file is written (a design-mode search may add IDAs to the cache).  None when
    there was no run (no ``results.json``) or when some (case, record) IDA of the project is
    not in the cache (the project changed since the run: ``ctrl+r`` runs it); the date of
    the results is that of the stored run.
    """
    stored = Path(out_dir) / "results.json"
    try:
        created = from_json(stored.read_text(encoding="utf-8"), file=str(stored)).created
    except (OSError, UnicodeDecodeError, InputError):  # none, or not readable as this version
        return None
    inputs = inputs_from_project(project, base_dir, input_file)
    seismic = prepare_records(inputs)
    if missing_idas(inputs, seismic, out_dir):
        return None
    results, stats = run_assessment(
        inputs, out_dir, jobs=jobs, cancel=cancel, seismic=seismic, created=created, write=False
    )
    return RunOutcome(results, seismic, inputs, Path(out_dir), stats, project)


def export_outputs(outcome: RunOutcome, directory: Path) -> list[Path]:
    """Write report.pdf, results.json/.csv, spectra.csv and records/ into ``directory``."""
    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise InputError(f"{directory} is a file, not a directory")
    try:
        write_outputs(outcome.results, outcome.seismic, directory, pdf=True)
    except OSError as exc:
        raise InputError(f"cannot write into {directory}: {exc.strerror or exc}") from None
    names = ["report.pdf", "results.json", "results.csv", "spectra.csv", "records"]
    return [directory / n for n in names if (directory / n).exists()]


def yaml_path_problem(path: Path) -> str | None:
    """Why a project cannot be saved as ``path`` (None: it can)."""
    if path.suffix.lower() not in (".yaml", ".yml"):
        return f"expected a .yaml file name, found {path.name!r}"
    if path.is_dir():
        return f"{path} is a directory"
    if not path.parent.is_dir():
        return f"no such directory: {path.parent}"
    return None


def save_project(project: Project, path: Path, *, opened_from: Path | None = None) -> bool:
    """Write the project as YAML (atomically); loading it gives an equal :class:`Project`.

    When ``opened_from`` is a valid project file (the one being edited), its text is kept,
    comments and layout included, and only what changed is rewritten; otherwise (or if that
    fails) the whole project is dumped.  Returns whether the comments were kept.
    """
    path = Path(path)
    problem = yaml_path_problem(path)
    if problem is not None:
        raise InputError(problem)
    text = _updated_text(opened_from, project, str(path))
    kept = text is not None
    if text is None:
        text = (
            "# frp-assess project file, saved by `frp-assess tui` (units: see `frp-assess new`)\n"
            + dump_project(project)
        )
    try:
        atomic_write_text(path, text)
    except OSError as exc:
        raise InputError(f"cannot write {path}: {exc.strerror or exc}") from None
    return kept


def _updated_text(opened_from: Path | None, project: Project, name: str) -> str | None:
    """The text of ``opened_from`` changed to hold ``project``, or None (see save_project)."""
    if opened_from is None:
        return None
    try:
        original_text = Path(opened_from).read_text(encoding="utf-8")
        original = load_project_text(original_text, name, check_files=False).project
    except (OSError, UnicodeDecodeError, InputError):
        return None
    return update_project_text(original_text, original, project, name)


@dataclass(frozen=True)
class HistoryData:
    """θ/α(t) and bar strain(t) of one case under one record at one multiplier."""

    case: str
    record: str
    multiplier: float
    time: np.ndarray  #: [s]
    theta_over_alpha: np.ndarray  #: [-]
    strain: np.ndarray  #: acting bar [-]
    collapsed: bool
    collapse_time: float | None  #: [s]
    peak_ratio: float  #: max |θ|/α [-]
    impacts: int
    ruptures: tuple[float, ...]  #: times of bar ruptures [s]
    rupture_strain: float | None  #: ε_max = c·ε_u, None when unreinforced
    reinforced: bool


def case_history(
    outcome: RunOutcome, case_index: int, record_index: int, multiplier: float
) -> HistoryData:
    """The time history of case ``case_index`` (0 = unreinforced) under record
    ``record_index`` of the run, scaled by ``multiplier`` (as the IDA does)."""
    run = time_history(
        outcome.inputs, outcome.seismic.records, case_index, record_index, multiplier
    )
    model, rec, res = run.model, run.record, run.result
    h = res.history
    assert h is not None
    n = h.computed
    bars = model.rebars
    return HistoryData(
        case=outcome.results.cases[case_index].name,
        record=rec.name,
        multiplier=float(multiplier),
        time=h.time[:n],
        theta_over_alpha=h.theta[:n] / model.alpha,  # α_x, as peak_ratio (docs/model.md §1.1)
        strain=h.strain[:n],
        collapsed=res.collapsed,
        collapse_time=res.collapse_time,
        peak_ratio=res.max_rotation_ratio,
        impacts=res.impacts,
        ruptures=tuple(r.time for r in res.ruptures),
        rupture_strain=None if bars is None else bars.rupture_strain,
        reinforced=bars is not None,
    )
