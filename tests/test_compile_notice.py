"""The line that says a run will first compile the numerical kernel (issue 42, goal 3): said
when numba's cache is cold, and only then, by `frp-assess run` and in the TUI's run log."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.dynamics import kernel_cache
from frp_assess.dynamics.kernel_cache import COLD_NOTICE, warm_up
from frp_assess.errors import Cancelled
from frp_assess.tui import jobs
from frp_assess.tui.worker_messages import RunDone, RunProgress
from tests.cli.test_run import SMALL

ROOT = Path(__file__).resolve().parents[1]
ASK = "from frp_assess.app.kernel import compile_notice; print(compile_notice())"


def notice_in_fresh_process(**env: str) -> str:
    """What :func:`frp_assess.app.kernel.compile_notice` says in a new process (this tree)."""
    path = os.pathsep.join(p for p in (str(ROOT), os.environ.get("PYTHONPATH")) if p)
    done = subprocess.run(
        [sys.executable, "-c", ASK],
        env={**os.environ, "PYTHONPATH": path, **env},
        capture_output=True,
        text=True,
        check=True,
    )
    return done.stdout.strip()


def test_an_empty_cache_is_cold_and_a_warmed_one_is_not(tmp_path):
    """numba's cache under NUMBA_CACHE_DIR: an empty folder holds no machine code, so the
    notice is said; the cache this process uses, once :func:`warm_up` has compiled (or
    loaded) every entry point into it, holds it all, so a new process says nothing."""
    assert notice_in_fresh_process(NUMBA_CACHE_DIR=str(tmp_path / "empty")) == COLD_NOTICE
    warm_up()
    assert notice_in_fresh_process() == "None"


def test_a_cache_of_another_source_is_cold(tmp_path, monkeypatch):
    """An index whose source hash is not the module's (an edited kernel) is stale for numba:
    the check reads it the same way, as no machine code."""
    warm_up()
    assert not kernel_cache.cache_is_cold()
    cache = kernel_cache.ENTRY_POINTS[0]._cache
    monkeypatch.setattr(cache._cache_file, "_source_stamp", b"another source")
    assert kernel_cache.cache_is_cold()


@pytest.mark.parametrize("cold", [True, False])
def test_run_prints_the_notice_only_when_cold(cold, tmp_path, capsys, monkeypatch):
    """`frp-assess run` prints the notice as its first line when the cache is cold (the
    check replaced by its answer: a real cold cache would compile for half a minute), and
    not at all when it is warm."""
    monkeypatch.setattr(kernel_cache, "cache_is_cold", lambda: cold)
    project = tmp_path / "small.yaml"
    project.write_text(SMALL, encoding="utf-8")
    assert main(["run", str(project), "--no-pdf", "--jobs", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    if cold:
        assert " ".join(lines[:3]).startswith(COLD_NOTICE.split(" (")[0])
    else:
        assert not any("compiling the numerical kernel" in line for line in lines)


@pytest.mark.parametrize("cold", [True, False])
def test_tui_run_log_has_the_notice_only_when_cold(cold, monkeypatch):
    """The TUI's run job posts the notice to the run log before the run starts, when cold
    (the run itself replaced by a cancelled one: only the order of the messages matters)."""
    monkeypatch.setattr(kernel_cache, "cache_is_cold", lambda: cold)

    def cancelled_run(*args: object, **kwargs: object) -> None:
        raise Cancelled("cancelled")

    monkeypatch.setattr(jobs, "execute_run", cancelled_run)
    posted: list[object] = []
    jobs.run_assessment_job(
        posted.append,
        None,
        Path("."),
        "x.yaml",
        Path("out"),
        threading.Event(),
        1,  # type: ignore[arg-type]
    )
    messages = [m.event.message for m in posted if isinstance(m, RunProgress)]
    assert messages == ([COLD_NOTICE] if cold else [])
    assert isinstance(posted[-1], RunDone) and posted[-1].status == "cancelled"
