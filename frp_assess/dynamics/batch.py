"""Run many IDAs (cases × records) on all cores.

The kernel releases the GIL (``nogil=True``), so plain threads use every core without the
cost of pickling records into processes.  Progress and cancellation are plain callables.
"""

from __future__ import annotations

import os
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

    Raises :class:`~frp_assess.errors.Cancelled` if ``cancel`` is set before all finish
    (results already delivered through ``on_result`` are not lost).
    """
    n = len(tasks)
    results: list[IdaResult | None] = [None] * n
    stop = cancel if cancel is not None else threading.Event()
    lock = threading.Lock()
    done = 0

    def work(i: int) -> None:
        nonlocal done
        if stop.is_set():
            raise Cancelled("batch cancelled")
        t = tasks[i]
        res = ida(t.model, t.acc, t.dt, t.settings, should_stop=stop.is_set)
        results[i] = res
        if on_result is not None:
            on_result(i, res)
        with lock:
            done += 1
            if progress is not None:
                progress(done, n)

    workers = max(1, jobs if jobs is not None else default_jobs())
    if workers == 1:
        for i in range(n):
            work(i)
    else:
        with ThreadPoolExecutor(max_workers=workers, thread_name_prefix="ida") as pool:
            futures = [pool.submit(work, i) for i in range(n)]
            try:
                finished, _ = wait(futures, return_when=FIRST_EXCEPTION)
            except BaseException:  # Ctrl-C in the waiting thread: stop the workers promptly
                stop.set()
                for f in futures:
                    f.cancel()
                raise
            for f in finished:
                exc = f.exception()
                if exc is not None:
                    stop.set()
                    for g in futures:
                        g.cancel()
                    raise exc
    if stop.is_set() and any(r is None for r in results):
        raise Cancelled("batch cancelled")
    return [r for r in results if r is not None]
