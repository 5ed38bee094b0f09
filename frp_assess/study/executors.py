"""Where a study's IDAs run: local threads, or a Dask cluster (optional extra ``dask``).

Both run the same :func:`frp_assess.dynamics.ida` on the same inputs, so they give identical
numbers; only the scheduling differs.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from frp_assess.dynamics import IdaResult, IdaSettings, IdaTask, RockingModel, ida
from frp_assess.errors import Cancelled, InputError
from frp_assess.study.run import LocalExecutor, OnResult

#: tasks per Dask future (amortises the scheduler's per-task overhead, ~1 ms)
DASK_BATCH = 8


def batch_size(n_tasks: int, n_workers: int) -> int:
    """Tasks per future: :data:`DASK_BATCH`, or fewer when a call has too few tasks to give
    every worker two futures (a building's wall: 9 IDAs in batches of 8 kept one of two
    workers idle)."""
    return max(1, min(DASK_BATCH, math.ceil(n_tasks / (2 * max(1, n_workers)))))


def _run_tasks(
    items: list[tuple[RockingModel, str, IdaSettings]], accs: dict[str, tuple[np.ndarray, float]]
) -> list[IdaResult]:
    """Worker side: IDA of each (model, record key, settings); records come scattered."""
    out = []
    for model, rkey, settings in items:
        acc, dt = accs[rkey]
        out.append(ida(model, acc, dt, settings))
    return out


class DaskExecutor:
    """IDA tasks on a Dask cluster: a new ``LocalCluster`` or the scheduler at ``address``.

    Records are scattered once per distinct array (broadcast to every worker; an array first
    seen in a later :meth:`run` is scattered then, the others stay); tasks travel in batches
    of :func:`batch_size`.
    """

    def __init__(self, address: str | None = None, n_workers: int | None = None) -> None:
        try:
            from dask.distributed import Client, LocalCluster
        except ImportError:  # pragma: no cover - depends on the environment
            raise InputError(
                "the Dask executor needs dask[distributed]: pip install 'frp-assess[dask]'",
                key="--executor",
            ) from None
        self.address = address
        self._cluster: Any = None
        if address is None:
            self._cluster = LocalCluster(
                n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address=None
            )
            self.client = Client(self._cluster)
        else:
            try:
                self.client = Client(address, timeout=30)
            except OSError as exc:
                raise InputError(
                    f"cannot reach the Dask scheduler at {address}: {exc}", key="--scheduler"
                ) from None
        self._scattered: dict[str, Any] = {}
        self._arrays: dict[str, tuple[np.ndarray, float]] = {}

    def describe(self) -> str:
        n = len(self.client.scheduler_info().get("workers", {}))
        where = self.address or "LocalCluster"
        return f"Dask {where}, {n} workers"

    def run(
        self,
        tasks: Sequence[IdaTask],
        on_result: OnResult,
        progress: Callable[[int], None],
        cancel: threading.Event,
    ) -> None:
        from dask.distributed import as_completed

        keys: list[str] = []
        for t in tasks:
            k = f"{id(t.acc)}:{t.acc.size}:{t.dt!r}"
            if k not in self._arrays:
                self._arrays[k] = (np.asarray(t.acc), float(t.dt))
            keys.append(k)
        # only the new arrays: scattering a dict names the data by its keys, so scattering the
        # ones already there again (and dropping their futures) released them under the
        # running tasks ("lost dependencies": a building's second floor, its new motions)
        missing = {k: v for k, v in self._arrays.items() if k not in self._scattered}
        if missing:
            fut = self.client.scatter(missing, broadcast=True, hash=False)
            self._scattered.update({k: fut[k] for k in missing})
        size = batch_size(len(tasks), len(self.client.scheduler_info().get("workers", {})))
        batches = [list(range(i, min(i + size, len(tasks)))) for i in range(0, len(tasks), size)]
        futures = {}
        for b in batches:
            used = {keys[i] for i in b}
            items = [(tasks[i].model, keys[i], tasks[i].settings) for i in b]
            f = self.client.submit(
                _run_tasks, items, {k: self._scattered[k] for k in used}, pure=False
            )
            futures[f] = b
        done = 0
        try:
            for f in as_completed(list(futures)):
                if cancel.is_set():
                    raise Cancelled("study cancelled")
                for i, res in zip(futures[f], f.result(), strict=True):
                    on_result(i, res)
                    done += 1
                progress(done)
        except BaseException:
            self.client.cancel(list(futures))
            raise

    def close(self) -> None:
        self.client.close()
        if self._cluster is not None:
            self._cluster.close()


def make_executor(
    kind: str, scheduler: str | None = None, jobs: int | None = None
) -> LocalExecutor | DaskExecutor:
    """``local`` threads, or Dask (``kind == 'dask'`` or a ``scheduler`` address)."""
    if scheduler is not None or kind == "dask":
        return DaskExecutor(scheduler, n_workers=jobs)
    if kind != "local":
        raise InputError(f"unknown executor {kind!r}; expected local or dask", key="--executor")
    return LocalExecutor(jobs)
