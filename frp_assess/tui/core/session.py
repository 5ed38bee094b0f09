"""The long operations of the TUI as plain functions (run, time history, export, save).

They run in Textual worker threads and talk back through an ``emit`` callable, so they can
be tested without a terminal.  Everything goes through the application service
(:mod:`frp_assess.app`): the same inputs, cache and result files as ``frp-assess run``.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from frp_assess.app.assessment import RunOutcome, load_previous, prepare_run, run_prepared
from frp_assess.app.history import HistoryData, case_history
from frp_assess.app.project import Project, save_project, yaml_path_problem
from frp_assess.app.report import export_run
from frp_assess.tui.core.progress import CaseCount, CaseProgress

__all__ = [
    "Emit",
    "HistoryData",
    "RunEvent",
    "RunOutcome",
    "case_history",
    "execute_run",
    "export_outputs",
    "load_previous",
    "save_project",
    "yaml_path_problem",
]


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


def execute_run(
    project: Project,
    base_dir: Path,
    input_file: str,
    out_dir: Path,
    *,
    cancel: threading.Event,
    emit: Emit,
    jobs: int | None = None,
    project_file: Path | None = None,
) -> RunOutcome:
    """Records, then every IDA (cached in ``out_dir/.cache``), ranking and result files,
    report.pdf included, as ``frp-assess run`` writes them
    (:func:`frp_assess.app.assessment.run_prepared`), reported through ``emit``.

    ``project_file``: the saved file the project is (None when edited and not saved): its
    inputs' digest is recorded as ``frp-assess run`` records it (``run_prepared``).

    Raises :class:`~frp_assess.errors.Cancelled` when ``cancel`` is set (finished IDAs stay
    in the cache), :class:`~frp_assess.errors.InputError` for a problem the user can fix.
    """

    def records_started(stage: str, done: int, total: int) -> None:
        if done == 0:
            emit(RunEvent(stage, done, total, message="generating/reading the records"))

    prepared = prepare_run(project, base_dir, input_file, progress=records_started)
    seismic = prepared.seismic
    failed = [c for c in seismic.compliance.checks if not c.passed]
    emit(
        RunEvent(
            "records",
            1,
            1,
            message=f"{len(seismic.records)} records; spectrum compatibility: "
            + ("all checks passed" if not failed else f"{len(failed)} check(s) FAILED"),
        )
    )
    tracker = CaseProgress(prepared.inputs, len(seismic.records))

    def progress(stage: str, done: int, total: int) -> None:
        if stage == "ida":
            emit(RunEvent(stage, done, total, tuple(tracker.counts())))
        else:
            emit(RunEvent(stage, done, total))

    return run_prepared(
        prepared,
        out_dir,
        cancel=cancel,
        progress=progress,
        case_progress=tracker.mark,
        jobs=jobs,
        project_file=project_file,
    )


def export_outputs(outcome: RunOutcome, directory: Path) -> list[Path]:
    """Write report.pdf, results.json/.csv, spectra.csv and records/ into ``directory``
    (:func:`frp_assess.app.report.export_run`)."""
    return export_run(outcome, directory)
