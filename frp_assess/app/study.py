"""Parametric studies: load, check and run one (chunked, cached, resumable).

:func:`run_study` runs a study file into a folder through the cached runner of `run`
(:func:`frp_assess.study.run.run_study`) and writes its figures; :func:`plan_and_records`
expands the axes and generates the records first, so that a command can say what it is about
to run; :func:`study_problems` are the problems of a schema-valid study that need the
libraries (materials, spectra), reported as `validate` reports a project's.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from frp_assess import study as _study
from frp_assess.config.messages import Loc, format_path, line_of
from frp_assess.errors import InputError
from frp_assess.motions import Record
from frp_assess.motions.spectra import parse_spectrum
from frp_assess.study import run as study_run
from frp_assess.study.plan import StudyPlan
from frp_assess.study.rows import SummaryRow, read_summary
from frp_assess.study.run import Executor, StudyStats
from frp_assess.study.schema import StudyFile, load_study, spectrum_text

if TYPE_CHECKING:
    from frp_assess.study.executors import DaskExecutor, LocalExecutor

__all__ = [
    "Executor",
    "StudyFile",
    "StudyPlan",
    "StudyOutcome",
    "StudyStats",
    "SummaryRow",
    "load_study",
    "make_executor",
    "plan_and_records",
    "read_summary",
    "run_study",
    "study_problems",
]


@dataclass(frozen=True)
class StudyOutcome:
    """A finished study."""

    stats: StudyStats  #: IDAs computed and reused, chunks, seconds
    figures: tuple[Path, ...]  #: the figure files written (study.pdf, figures/...)
    out_dir: Path  #: where long.csv, summary.csv and study.json are

    def rows(self) -> list[SummaryRow]:
        """The study's result per case, typed (its summary.csv, read on each call: a large
        study's rows are not held in memory by the run)."""
        return read_summary(self.out_dir / "summary.csv")


def make_executor(
    kind: str, scheduler: str | None, jobs: int | None
) -> LocalExecutor | DaskExecutor:
    """Local threads (``"local"``) or a Dask cluster (``"dask"``, at ``scheduler`` if given):
    :func:`frp_assess.study.executors.make_executor` (Dask is imported only for it)."""
    from frp_assess.study.executors import make_executor as make

    return make(kind, scheduler, jobs)


def plan_and_records(study: StudyFile) -> tuple[StudyPlan, dict[str, list[Record]]]:
    """The cases of ``study`` (the cross product of its axes) and its records per spectrum
    (generated: :func:`frp_assess.study.study_records`)."""
    plan = StudyPlan(study)
    return plan, _study.study_records(plan)


def study_problems(study: StudyFile, file: str, lines: Mapping[Loc, int]) -> list[InputError]:
    """Problems of a schema-valid study that need the libraries: materials and spectra."""
    out: list[InputError] = []
    try:
        StudyPlan(study)
    except InputError as exc:
        path: Loc = tuple(int(p) if p.isdigit() else p for p in str(exc.key or "").split("."))
        out.append(
            InputError(exc.message, file=file, line=line_of(lines, path), key=format_path(path))
        )
    for i, spectrum in enumerate(study.spectrum):
        try:
            parse_spectrum(spectrum_text(spectrum))
        except InputError as exc:
            where: Loc = ("spectrum", i)
            out.append(
                InputError(
                    f"{exc.key}: {exc.message}"
                    if exc.key and exc.key != "spectrum"
                    else exc.message,
                    file=file,
                    line=line_of(lines, where),
                    key=format_path(where),
                )
            )
    return sorted(out, key=lambda p: p.line or 0)


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
) -> StudyOutcome:
    """Run a parametric study into ``out_dir`` (chunked, cached, resumable:
    :func:`frp_assess.study.run.run_study`, on the cached runner of `run`) and, if
    ``figures``, write its PDF; returns the run's counts, the figure files written and its
    typed rows (:meth:`StudyOutcome.rows`)."""
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
    return StudyOutcome(stats, tuple(written), Path(out_dir))
