"""The long operations of the app, run in worker threads; each posts its result as a
message (:mod:`frp_assess.tui.worker_messages`) through ``post`` (thread-safe)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from pathlib import Path

from textual.message import Message

from frp_assess.app.kernel import compile_notice
from frp_assess.config.schema import Project
from frp_assess.errors import Cancelled, InputError
from frp_assess.tui.core.session import (
    RunEvent,
    RunOutcome,
    execute_run,
    export_outputs,
    load_previous,
)
from frp_assess.tui.worker_messages import ExportDone, PreviousLoaded, RunDone, RunProgress

Post = Callable[[Message], object]

#: the least time between two progress messages of one stage [s] (the UI thread shares the
#: GIL with the run: at most ~10 updates a second)
PROGRESS_INTERVAL = 0.1


def run_assessment_job(
    post: Post,
    project: Project,
    base_dir: Path,
    input_file: str,
    out_dir: Path,
    cancel: threading.Event,
    jobs: int | None,
    project_file: Path | None = None,
) -> None:
    """Run the assessment (as ``frp-assess run``); posts RunProgress, then RunDone.
    ``project_file``: the saved file the project is, None when edited (``execute_run``)."""
    last: dict[str, float] = {}

    def emit(ev: RunEvent) -> None:
        now = time.monotonic()
        if (
            ev.message
            or ev.done in (0, ev.total)
            or now - last.get(ev.stage, 0.0) >= PROGRESS_INTERVAL
        ):
            last[ev.stage] = now
            post(RunProgress(ev))

    try:
        if (notice := compile_notice()) is not None:  # a cold numba cache: said in the log
            post(RunProgress(RunEvent("records", 0, 0, message=notice)))
        outcome = execute_run(
            project,
            base_dir,
            input_file,
            out_dir,
            cancel=cancel,
            emit=emit,
            jobs=jobs,
            project_file=project_file,
        )
    except Cancelled:
        post(RunDone("cancelled", None, "finished analyses are kept in the cache"))
    except InputError as exc:
        post(RunDone("error", None, str(exc)))
    except Exception as exc:  # noqa: BLE001 - shown in the run panel, never a crash
        post(RunDone("error", None, f"{type(exc).__name__}: {exc}"))
    else:
        post(RunDone("done", outcome, ""))


def previous_results_job(
    post: Post,
    project: Project,
    base_dir: Path,
    project_file: Path,
    out_dir: Path,
    cancel: threading.Event,
    jobs: int | None,
) -> None:
    """The last run's results of ``project``, read from ``project_file`` and not edited
    since: as stored when the file gives the inputs they carry, else rebuilt from the cache
    (:func:`frp_assess.app.assessment.load_previous`); posts PreviousLoaded (not if
    cancelled)."""
    try:
        outcome = load_previous(
            project,
            base_dir,
            project_file.name,
            out_dir,
            cancel=cancel,
            jobs=jobs,
            project_file=project_file,
        )
    except Cancelled:
        return
    except Exception as exc:  # noqa: BLE001 - a note in the run log, never a crash
        post(PreviousLoaded(None, f"{type(exc).__name__}: {exc}"))
    else:
        post(PreviousLoaded(outcome))


def export_job(post: Post, outcome: RunOutcome, directory: Path) -> None:
    """Write the report and results of ``outcome`` into ``directory``; posts ExportDone."""
    try:
        files = export_outputs(outcome, directory)
    except InputError as exc:
        post(ExportDone([], str(exc)))
    except Exception as exc:  # noqa: BLE001 - reported, never a crash
        post(ExportDone([], f"{type(exc).__name__}: {exc}"))
    else:
        post(ExportDone(files))
