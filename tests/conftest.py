"""Shared fixtures: seeded synthetic ground motions (no files, no network); the ``tui`` marker
of tests/tui/; the numba cache warmed once before pytest-xdist's workers start; Textual without
animations."""

from __future__ import annotations

import gc
import os

# pytest-xdist's workers are long-lived processes whose heaps hold 300-650 thousand objects
# (numba's typing registries, the widget trees of the TUI tests' Pilot sessions), and
# CPython by default collects that whole heap after every 10 collections of the middle
# generation.  Measured with gc.callbacks over one full run: 57 full collections and 16 s in
# the worker that ran the TUI tests, 22 s over both workers; collecting the oldest
# generation ten times less often (threshold 100 instead of 10): 15 collections, 6.6 s.
# The product's own processes are unaffected (a `run` of the bundled example spends 0.3 s
# in the collector), and no test depends on when cyclic garbage is freed.
gc.set_threshold(700, 10, 100)

# The TUI tests drive the app with Pilot: Textual's animations (tab underline, scrolling,
# progress bars) only repaint frames no test looks at.  Textual reads the variable when it is
# first imported, so it is set here, before any test module imports it.  Measured on five
# Pilot tests of tests/tui/test_app.py: 22.3 -> 20.4 CPU-s.
os.environ.setdefault("TEXTUAL_ANIMATIONS", "none")

import contextlib  # noqa: E402
import io  # noqa: E402
import tempfile  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402

G = 9.80665


def synthetic_record(
    seed: int, duration: float = 8.0, dt: float = 0.01, pga_g: float = 0.2, corner: int = 6
) -> np.ndarray:
    """Band-limited noise under a trapezoidal envelope, scaled to ``pga_g`` [returns m/s²].

    A stand-in for an earthquake record: broadband, non-stationary, reproducible from its seed.
    """
    rng = np.random.default_rng(seed)
    n = int(round(duration / dt)) + 1
    t = np.arange(n) * dt
    env = np.clip(t / 1.5, 0, 1) * np.clip((duration - t) / 2.0, 0, 1)
    noise = np.convolve(rng.standard_normal(n), np.ones(corner) / corner, mode="same")
    acc = noise * env
    return acc / np.max(np.abs(acc)) * pga_g * G


@pytest.fixture
def record_factory():
    return synthetic_record


TUI_TESTS = Path(__file__).parent / "tui"


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Every test under tests/tui/ carries the ``tui`` marker (``-m "not tui"`` skips them)."""
    for item in items:
        if item.path.is_relative_to(TUI_TESTS):
            item.add_marker(pytest.mark.tui)


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session: pytest.Session) -> None:
    """Collect the garbage once, then freeze what survives: pytest's clean-up after the
    session collects five more times (to surface exceptions raised in finalizers), and each
    full collection of a worker's heap (600 thousand objects after the TUI tests) costs
    about 0.3 s at the end of the run.  The collection here runs every finalizer of the
    session's garbage; what those finalizers leave is young, so the five later
    collections still find it, and they skip the frozen survivors."""
    gc.collect()
    gc.freeze()


def pytest_configure(config: pytest.Config) -> None:
    """With pytest-xdist (``-n``), compile the numba kernels once in the controller, before
    the workers start: each worker then loads them from the on-disk cache instead of all of
    them compiling the same functions at once (wasted CPU, and racing writes of the cache
    index).  Workers (they have ``workerinput``) and serial runs do nothing here."""
    if hasattr(config, "workerinput") or not config.pluginmanager.hasplugin("xdist"):
        return
    if not config.getoption("numprocesses", None) or config.getoption("collectonly"):
        return
    if not numba_cache_is_warm():
        warm_numba_cache()


PACKAGE = Path(__file__).resolve().parents[1] / "frp_assess"


def numba_cache_is_warm(package: Path = PACKAGE) -> bool:
    """Whether every module with cached kernels (``cache=True``) has a numba index in its
    ``__pycache__`` written after the module's last change: then the workers load the kernels
    from the cache and warming it (:func:`warm_numba_cache`, before any worker starts: 26–34 s
    of wall time from a cold cache, all of it added to the run's) is skipped.  An edited
    module, a new one or a fresh checkout has no such index: the cache is warmed.  (Numba
    itself decides whether an index is stale by the same module's stamp: a kernel inlined
    from another file is not tracked either way; delete the ``*.nbi``/``*.nbc`` files after
    such an edit.)"""
    for source in sorted(package.rglob("*.py")):
        if "cache=True" not in source.read_text(encoding="utf-8"):
            continue
        indexes = list((source.parent / "__pycache__").glob(f"{source.stem}.*.nbi"))
        if not indexes or min(i.stat().st_mtime for i in indexes) < source.stat().st_mtime:
            return False
    return True


def warm_numba_cache() -> None:
    """Compile every cached kernel once, on both cores
    (:func:`frp_assess.dynamics.kernel_cache.warm_up_in_parallel`, what the wheel's build
    runs: the motions' kernels in a second process while this one compiles the rocking
    kernel), then run the golden gable (tests/golden/projects/building-crushing.yaml) through
    the CLI, quietly, for whatever else it calls; by then it all comes from the cache.
    Measured cold on this machine: 26–34 s wall (4 runs), against 40–47 s (3 runs) for the
    gable alone on one core.  (Compiling the driver with its history in the second process
    too was tried: both then compiled the driver's helpers, 31 s and 54 CPU-s.)"""
    from frp_assess.dynamics.kernel_cache import warm_up_in_parallel
    from tests.golden.golden import run_project

    warm_up_in_parallel()
    with (
        tempfile.TemporaryDirectory(prefix="frp-numba-warm-") as tmp,
        contextlib.redirect_stdout(io.StringIO()),
        contextlib.redirect_stderr(io.StringIO()),
    ):
        run_project("building-crushing", Path(tmp) / "out", jobs=1)
