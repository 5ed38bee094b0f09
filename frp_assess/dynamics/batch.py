"""Run many IDAs (cases × records) on all cores.

The kernel releases the GIL (``nogil=True``) for a whole IDA (one compiled call,
:mod:`frp_assess.dynamics.ida_search`), so plain threads use every core without the cost of
pickling records into processes.  Progress and cancellation are plain callables; with more
than one thread the results are handed to the callbacks on a thread of their own.
"""

from __future__ import annotations

import os
import queue
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_EXCEPTION, ThreadPoolExecutor, wait
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.ida import IdaResult, IdaSettings, ida
from frp_assess.dynamics.rocking import RockingModel
from frp_assess.errors import Cancelled


@dataclass(frozen=True, eq=False)
class IdaTask:
    """One (case, record) pair."""

    model: RockingModel
    acc: NDArray[np.float64]  #: [m/s²]
    dt: float  #: [s]
    settings: IdaSettings = IdaSettings()


#: progress(done, total) after each finished task
ProgressCallback = Callable[[int, int], None]
#: on_result(index, result), called from the worker thread as soon as a task finishes
ResultCallback = Callable[[int, IdaResult], None]


def default_jobs() -> int:
    """Number of worker threads: the CPUs this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def run_batch(
    tasks: Sequence[IdaTask],
    *,
    jobs: int | None = None,
    progress: ProgressCallback | None = None,
    on_result: ResultCallback | None = None,
    cancel: threading.Event | None = None,
) -> list[IdaResult]:
    """IDA of every task, in the order given; the same numbers whatever ``jobs`` is.

    With more than one job, ``on_result`` and ``progress`` are called from one delivery
    thread, in the order the tasks finish: a callback that writes a file (the IDA cache)
    never holds up a worker, which goes straight on to its next IDA.  Every result
    finished is delivered before this returns or raises.

    Raises :class:`~frp_assess.errors.Cancelled` if ``cancel`` is set before all finish
    (results already delivered through ``on_result`` are not lost); an exception raised by
    a callback stops the batch and is raised here.
    """
    n = len(tasks)
    results: list[IdaResult | None] = [None] * n
    stop = cancel if cancel is not None else threading.Event()

    def compute(i: int) -> IdaResult:
        if stop.is_set():
            raise Cancelled("batch cancelled")
        t = tasks[i]
        res = ida(t.model, t.acc, t.dt, t.settings, should_stop=stop.is_set)
        results[i] = res
        return res

    workers = max(1, jobs if jobs is not None else default_jobs())
    if workers == 1:
        for i in range(n):
            res = compute(i)
            if on_result is not None:
                on_result(i, res)
            if progress is not None:
                progress(i + 1, n)
    else:
        _run_threads(n, workers, compute, stop, progress, on_result)
    if stop.is_set() and any(r is None for r in results):
        raise Cancelled("batch cancelled")
    return [r for r in results if r is not None]


def _run_threads(
    n: int,
    workers: int,
    compute: Callable[[int], IdaResult],
    stop: threading.Event,
    progress: ProgressCallback | None,
    on_result: ResultCallback | None,
) -> None:
    """``compute(i)`` for i < n on ``workers`` threads; the callbacks on one more thread."""
    finished: queue.SimpleQueue[tuple[int, IdaResult] | None] = queue.SimpleQueue()
    failure: list[BaseException] = []

    def deliver() -> None:
        done = 0
        while (item := finished.get()) is not None:
            if failure:  # a callback failed: drain the queue, call nothing more
                continue
            try:
                if on_result is not None:
                    on_result(*item)
                done += 1
                if progress is not None:
                    progress(done, n)
            except BaseException as exc:  # noqa: BLE001 - raised again by the caller
                failure.append(exc)
                stop.set()

    def work(i: int) -> None:
        finished.put((i, compute(i)))

    courier = threading.Thread(target=deliver, name="ida-results", daemon=True)
    courier.start()
    try:
        with ThreadPoolExecutor(max_workers=workers, thread_name_prefix="ida") as pool:
            futures = [pool.submit(work, i) for i in range(n)]
            try:
                finished_futures, _ = wait(futures, return_when=FIRST_EXCEPTION)
            except BaseException:  # Ctrl-C in the waiting thread: stop the workers promptly
                stop.set()
                for f in futures:
                    f.cancel()
                raise
            for f in finished_futures:
                exc = f.exception()
                if exc is not None:
                    stop.set()
                    for g in futures:
                        g.cancel()
                    raise exc
    finally:
        finished.put(None)  # after the workers: every finished result is delivered first
        courier.join()
        if failure:
            raise failure[0]
