"""How the Dask executor cuts a call's IDAs into futures (frp_assess.study.executors):
batches of DASK_BATCH for a study's long lists, smaller ones when a call is short, so that
no worker idles while another runs one long batch (a building runs each wall's few IDAs in
one call).  Pure arithmetic: no dask needed."""

from __future__ import annotations

import math

import pytest

from frp_assess.study.executors import DASK_BATCH, batch_size


@pytest.mark.parametrize(
    ("n_tasks", "n_workers", "expected"),
    [
        (9, 2, 3),  # a wall of 3 cases x 3 records on 2 workers: 3 futures of 3 (was 8 + 1)
        (4, 2, 1),  # four IDAs: one each, two futures per worker
        (1, 2, 1),
        (1000, 2, DASK_BATCH),  # a study's chunk: the full batch
        (33, 2, DASK_BATCH),  # ceil(33 / 4) = 9 > 8
        (30, 0, DASK_BATCH),  # no worker known yet (a remote scheduler): as one worker
    ],
)
def test_batch_size(n_tasks: int, n_workers: int, expected: int) -> None:
    assert batch_size(n_tasks, n_workers) == expected


@pytest.mark.parametrize("n_workers", [1, 2, 3, 8])
@pytest.mark.parametrize("n_tasks", [1, 2, 5, 9, 17, 64, 500])
def test_no_worker_idles_while_there_are_tasks(n_tasks: int, n_workers: int) -> None:
    """Futures = ceil(n / size) is at least min(n, workers) unless the batch is full: with
    n >= 2w, size = ceil(n / 2w) <= n / w (ceil(x) <= 2x for x >= 1); with n < 2w, size 1."""
    size = batch_size(n_tasks, n_workers)
    futures = math.ceil(n_tasks / size)
    assert 1 <= size <= DASK_BATCH
    assert size == DASK_BATCH or futures >= min(n_tasks, n_workers)
