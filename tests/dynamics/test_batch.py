"""run_batch on threads (frp_assess/dynamics/batch.py): the callbacks run on one delivery
thread, never on a worker; everything finished is delivered; a failing callback stops the
batch with its own error."""

from __future__ import annotations

import threading

import pytest

from frp_assess.dynamics import IdaTask, RockingModel, Wall, run_batch
from frp_assess.errors import Cancelled
from tests.conftest import synthetic_record

WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3)


def _tasks(n: int = 6) -> list[IdaTask]:
    return [
        IdaTask(RockingModel(WALL, "two-sided"), synthetic_record(s, duration=4.0), 0.01)
        for s in range(n)
    ]


def test_callbacks_on_one_delivery_thread_and_every_result_delivered():
    tasks = _tasks()
    seen: dict[int, object] = {}
    threads: set[str] = set()
    counts: list[int] = []

    def on_result(i, res):
        threads.add(threading.current_thread().name)
        seen[i] = res

    out = run_batch(tasks, jobs=2, on_result=on_result, progress=lambda d, n: counts.append(d))
    assert threads == {"ida-results"}
    assert sorted(seen) == list(range(len(tasks)))
    assert [seen[i] for i in range(len(tasks))] == out
    assert counts == list(range(1, len(tasks) + 1))
    assert out == run_batch(tasks, jobs=1)  # the same numbers on one thread


def test_a_failing_callback_stops_the_batch_with_its_error():
    calls = []

    def on_result(i, res):
        calls.append(i)
        raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        run_batch(_tasks(), jobs=2, on_result=on_result)
    assert len(calls) == 1  # nothing delivered after the failure


def test_cancel_delivers_what_finished():
    stop = threading.Event()
    delivered = []

    def on_result(i, res):
        delivered.append(res)
        stop.set()

    with pytest.raises(Cancelled):
        run_batch(_tasks(24), jobs=2, on_result=on_result, cancel=stop)
    assert 1 <= len(delivered) < 24
    assert all(r is not None for r in delivered)
