"""Running a study: chunked, cached, resumable, on all local cores or on a Dask cluster.

Layout of the output directory::

    .cache/                   one JSON per (case, record) IDA, shared with `frp-assess run`
    parts-<digest>/           long-NNNNNN.csv and summary-NNNNNN.csv per finished chunk
    long.csv                  one row per case × record
    summary.csv               one row per case: mean a_dyn [g], mean q, improvement
    study.json                what was run, counts and timing

A chunk of ``chunk_size`` consecutive cases is computed, then written as two part files
(atomically); the results of a chunk are dropped from memory once written.  A rerun skips the
chunks whose part files exist and takes every finished IDA of an interrupted chunk from the
cache, so nothing is computed twice.  ``long.csv`` and ``summary.csv`` are assembled by
streaming the part files at the end (the improvement needs only the unreinforced means, one
per wall group).
"""

from __future__ import annotations

import csv
import datetime as _dt
import io
import json
import math
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from frp_assess import __version__
from frp_assess.assess.cache import IdaCache
from frp_assess.assess.inputs import BuildingSettings
from frp_assess.assess.runner import BatchRunner, IdaRunner, summarise
from frp_assess.dynamics import IdaResult, IdaTask, default_jobs, run_batch
from frp_assess.errors import Cancelled
from frp_assess.io_utils import atomic_open, atomic_write_text
from frp_assess.motions import G, Record, generate_artificial, parse_spectrum
from frp_assess.study.plan import Case, StudyPlan
from frp_assess.study.rows import read_summary as read_summary  # (old imports)
from frp_assess.study.schema import StudyFile

CACHE_DIR = ".cache"

#: progress(done, total) in (case, record) IDAs, including those reused
StudyProgress = Callable[[int, int], None]
#: on_result(task index, result), called as soon as a task finishes
OnResult = Callable[[int, IdaResult], None]

LONG_COLUMNS = (
    "case",
    "label",
    "spectrum",
    "mechanism",
    "height_m",
    "thickness_m",
    "alpha_deg",
    "material",
    "position",
    "ratio_permille",
    "record",
    "pga_g",
    "c0",
    "collapse_multiplier",
    "a_dyn_g",
    "q",
    "collapsed",
    "runs",
)
_CASE_COLUMNS = LONG_COLUMNS[:10]
SUMMARY_COLUMNS = (
    *_CASE_COLUMNS,
    "records",
    "a_rm_g",
    "mean_a_dyn_g",
    "min_a_dyn_g",
    "mean_q",
    "lower_bound",
    "unreinforced_case",
    "unreinforced_mean_a_dyn_g",
    "improvement",
)


class Executor(Protocol):
    """Runs IDA tasks; must give the same numbers as :func:`run_batch`."""

    def run(
        self,
        tasks: Sequence[IdaTask],
        on_result: OnResult,
        progress: Callable[[int], None],
        cancel: threading.Event,
    ) -> None:
        """Compute every task, calling ``on_result`` for each and ``progress(done)``."""
        ...  # pragma: no cover

    def describe(self) -> str:
        """Where the IDAs run, in a few words (the study's manifest)."""
        ...  # pragma: no cover

    def close(self) -> None:
        """Release what it holds (a Dask client and its LocalCluster); the caller's to call."""
        ...  # pragma: no cover


@dataclass
class LocalExecutor:
    """Threads on the local cores (the kernel releases the GIL)."""

    jobs: int | None = None

    def run(
        self,
        tasks: Sequence[IdaTask],
        on_result: OnResult,
        progress: Callable[[int], None],
        cancel: threading.Event,
    ) -> None:
        run_batch(
            tasks,
            jobs=self.jobs if self.jobs is not None else default_jobs(),
            on_result=on_result,
            progress=lambda d, n: progress(d),
            cancel=cancel,
        )

    def close(self) -> None:
        return None

    def describe(self) -> str:
        return f"local, {self.jobs if self.jobs is not None else default_jobs()} threads"


@dataclass(frozen=True)
class StudyStats:
    """What a study run did."""

    cases: int
    records_per_case: int
    computed: int  #: (case, record) IDAs computed in this run
    reused: int  #: (case, record) IDAs taken from the cache or from finished chunks
    chunks: int
    chunks_skipped: int  #: chunks already on disk
    seconds: float  #: wall-clock time of this run [s]
    out_dir: Path
    executor: str


def study_records(plan: StudyPlan) -> dict[str, list[Record]]:
    """The artificial record set of every spectrum (deterministic from the seed)."""
    r = plan.study.records
    out: dict[str, list[Record]] = {}
    for label in plan.spectra:
        spec = parse_spectrum(plan.spectrum_texts[label])
        out[label] = generate_artificial(
            spec,
            count=r.count,
            seed=r.seed,
            duration=r.duration,
            dt=r.dt,
            stationary=r.stationary,
            t1=r.t1,
        )
    return out


def _num(x: float | None) -> str:
    return "" if x is None else repr(float(x))


def _case_cells(case: Case) -> list[str]:
    return [
        str(case.index),
        case.label,
        case.spectrum,
        case.mechanism,
        _num(case.height),
        _num(case.thickness),
        _num(case.alpha_deg),
        case.material or "",
        case.position or "",
        _num(case.ratio),
    ]


def _csv_text(rows: Iterable[Sequence[str]], header: Sequence[str] | None = None) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    if header is not None:
        w.writerow(header)
    w.writerows(rows)
    return buf.getvalue()


def _chunk_paths(parts: Path, k: int) -> tuple[Path, Path]:
    return parts / f"long-{k:06d}.csv", parts / f"summary-{k:06d}.csv"


def run_study(
    study: StudyFile,
    out_dir: Path,
    *,
    jobs: int | None = None,
    executor: Executor | None = None,
    progress: StudyProgress | None = None,
    cancel: threading.Event | None = None,
    records: dict[str, list[Record]] | None = None,
    cache_dir: Path | None = None,
) -> StudyStats:
    """Run every case of ``study`` over its records and write the outputs into ``out_dir``.

    Args:
        study: the validated study file.
        out_dir: results directory (created).
        jobs: local worker threads (default: all cores); ignored with ``executor``.
        executor: where the IDAs run (default :class:`LocalExecutor`).
        progress: ``progress(done, total)`` in (case, record) IDAs.
        cancel: when set, the run stops after the IDAs in flight and raises
            :class:`~frp_assess.errors.Cancelled`; finished IDAs stay in the cache.
        records: the record set per spectrum label (default: generated from the study).
        cache_dir: IDA cache (default ``out_dir/.cache``).
    """
    t_start = time.perf_counter()
    plan = StudyPlan(study)
    stop = cancel if cancel is not None else threading.Event()
    ex = executor if executor is not None else LocalExecutor(jobs)
    recs = records if records is not None else study_records(plan)
    n_rec = {label: len(recs[label]) for label in plan.spectra}
    per_case = max(n_rec.values())
    if len(set(n_rec.values())) != 1:
        raise ValueError("every spectrum needs the same number of records")
    cache = IdaCache(cache_dir if cache_dir is not None else out_dir / CACHE_DIR)
    # the cached runner of `frp-assess run`, one per record set and floor of the building
    # (the floor motions are computed once per runner), on the study's executor
    runners: dict[tuple[str, BuildingSettings | None], IdaRunner] = {}

    def runner(label: str, building: BuildingSettings | None) -> IdaRunner:
        key = (label, building)
        if key not in runners:
            runners[key] = IdaRunner(
                recs[label],
                None,
                cache,
                cancel=stop,
                settings=plan.ida_settings,
                building=building,
                batch=executor_batch(ex),
            )
        return runners[key]

    parts = out_dir / f"parts-{plan.digest()}"
    parts.mkdir(parents=True, exist_ok=True)
    n_cases = len(plan)
    total = n_cases * per_case
    size = study.chunk_size
    n_chunks = math.ceil(n_cases / size)
    done = 0
    skipped = 0
    on_disk = 0  #: (case, record) IDAs of the chunks already written

    def report() -> None:
        if progress is not None:
            progress(done, total)

    report()
    for k in range(n_chunks):
        if stop.is_set():
            raise Cancelled("study cancelled")
        lo, hi = k * size, min(n_cases, (k + 1) * size)
        long_path, summary_path = _chunk_paths(parts, k)
        if long_path.exists() and summary_path.exists():
            skipped += 1
            on_disk += (hi - lo) * per_case
            done += (hi - lo) * per_case
            report()
            continue
        cases = list(plan.cases(lo, hi))
        results: list[Sequence[IdaResult]] = [()] * len(cases)
        groups: dict[tuple[str, BuildingSettings | None], list[int]] = {}
        for i, case in enumerate(cases):  # the cases of a chunk by record set and floor
            groups.setdefault((case.spectrum, plan.building(case)), []).append(i)
        for (label, building), slots in groups.items():
            base = done

            def on_progress(d: int, n: int, base: int = base) -> None:
                nonlocal done
                done = base + d
                report()

            found = runner(label, building).run([plan.model(cases[i]) for i in slots], on_progress)
            for i, res in zip(slots, found, strict=True):
                results[i] = res
            done = base + len(slots) * per_case
        report()
        _write_chunk(plan, cases, results, recs, long_path, summary_path)
    _assemble(plan, parts, n_chunks, out_dir)
    seconds = time.perf_counter() - t_start
    computed = sum(r.computed for r in runners.values())
    reused = on_disk + sum(r.reused for r in runners.values())
    stats = StudyStats(
        n_cases, per_case, computed, reused, n_chunks, skipped, seconds, out_dir, ex.describe()
    )
    _write_manifest(plan, recs, stats, out_dir)
    return stats


def executor_batch(ex: Executor) -> BatchRunner:
    """The executor as the batch runner of :class:`~frp_assess.assess.runner.IdaRunner`
    (the signature of :func:`~frp_assess.dynamics.run_batch`; ``jobs`` is the executor's)."""

    def batch(
        tasks: Sequence[IdaTask],
        *,
        jobs: int | None = None,
        progress: Callable[[int, int], None] | None = None,
        on_result: OnResult | None = None,
        cancel: threading.Event | None = None,
    ) -> list[IdaResult]:
        if not tasks:  # everything came from the cache: no call to a remote cluster
            return []
        out: list[IdaResult | None] = [None] * len(tasks)

        def got(i: int, res: IdaResult) -> None:
            out[i] = res
            if on_result is not None:
                on_result(i, res)

        n = len(tasks)
        ex.run(
            tasks,
            got,
            (lambda d: None) if progress is None else (lambda d: progress(d, n)),
            cancel if cancel is not None else threading.Event(),
        )
        if any(r is None for r in out):  # pragma: no cover - defensive
            raise Cancelled("study cancelled")
        return [r for r in out if r is not None]

    return batch


def _write_chunk(
    plan: StudyPlan,
    cases: Sequence[Case],
    results: Sequence[Sequence[IdaResult]],
    recs: dict[str, list[Record]],
    long_path: Path,
    summary_path: Path,
) -> None:
    long_rows: list[list[str]] = []
    summary_rows: list[list[str]] = []
    c_max = plan.ida_settings.max_multiplier
    for case, res in zip(cases, results, strict=True):
        cells = _case_cells(case)
        for rec, r in zip(recs[case.spectrum], res, strict=True):
            long_rows.append(
                [
                    *cells,
                    rec.name,
                    _num(r.pga / G),
                    _num(r.c0),
                    _num(r.collapse_multiplier),
                    _num(None if r.a_dyn is None else r.a_dyn / G),
                    _num(r.q),
                    "yes" if r.a_dyn is not None else "no",
                    str(r.runs),
                ]
            )
        a_rm_g = plan.model(case).a_rm_g  # about the model's pivot, as the run's summary
        s = summarise(res, c_max, a_rm_g)
        summary_rows.append(
            [
                *cells,
                str(len(res)),
                _num(a_rm_g),
                _num(s.mean_a_dyn),
                _num(s.min_a_dyn),
                _num(s.mean_q),
                "yes" if s.lower_bound else "no",
            ]
        )
    atomic_write_text(long_path, _csv_text(long_rows))
    atomic_write_text(summary_path, _csv_text(summary_rows))


def _assemble(plan: StudyPlan, parts: Path, n_chunks: int, out_dir: Path) -> None:
    """Stream the part files into long.csv and summary.csv (with the improvement)."""
    with atomic_open(out_dir / "long.csv", newline="") as fh:
        fh.write(_csv_text([], LONG_COLUMNS))
        for k in range(n_chunks):
            fh.write(_chunk_paths(parts, k)[0].read_text(encoding="utf-8"))
    urm_mean: dict[int, float] = {}
    with atomic_open(out_dir / "summary.csv", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(SUMMARY_COLUMNS)
        for k in range(n_chunks):
            with _chunk_paths(parts, k)[1].open(encoding="utf-8", newline="") as part:
                for row in csv.reader(part):
                    index = int(row[0])
                    group, within = divmod(index, plan.group_size)
                    mean = float(row[12])
                    if within == 0:
                        urm_mean[group] = mean
                    base = urm_mean[group]
                    w.writerow([*row, str(group * plan.group_size), _num(base), _num(mean / base)])


def _write_manifest(
    plan: StudyPlan, recs: dict[str, list[Record]], stats: StudyStats, out_dir: Path
) -> None:
    data = {
        "frp_assess": __version__,
        "written": _dt.datetime.now().isoformat(timespec="seconds"),
        "study": plan.study.model_dump(mode="json"),
        "digest": plan.digest(),
        "cases": stats.cases,
        "unreinforced_cases": plan.n_unreinforced,
        "reinforced_cases": plan.n_reinforced,
        "records_per_case": stats.records_per_case,
        "materials": {k: vars(v) for k, v in plan.materials.items()},
        "records": {
            label: [{"name": r.name, "pga_g": r.pga_g, "dt": r.dt, "npts": r.npts} for r in rs]
            for label, rs in recs.items()
        },
        "run": {
            "computed": stats.computed,
            "reused": stats.reused,
            "chunks": stats.chunks,
            "chunks_skipped": stats.chunks_skipped,
            "seconds": round(stats.seconds, 2),
            "executor": stats.executor,
        },
    }
    atomic_write_text(out_dir / "study.json", json.dumps(data, indent=2) + "\n")
