"""The compiled kernel's cache: whether a run will compile it, and compiling it ahead.

Every ``@njit(cache=True)`` function of the package (the rocking kernel, the IDA search, the
response spectra, the floor filter) is compiled by numba the first time a process calls it
with a new argument type, and stored next to its source (``__pycache__/*.nbi|*.nbc``, or
under ``NUMBA_CACHE_DIR``); a later process loads it in milliseconds.  A first run without
that cache spends 15-23 CPU-s compiling (docs/compilation.md).  :func:`warm_up` calls the few
entry points a run calls from Python, once each, with the argument types a run gives them,
so that everything a run needs is compiled and cached.  The wheel's build runs it
(``setup.py``: :func:`warm_up_in_parallel`), so a run after ``pip install .`` finds the
cache warm; so do the tests before their workers start (tests/conftest.py).
:func:`cache_is_cold` tells, without compiling, whether a run would compile.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from frp_assess import libm
from frp_assess.dynamics.ida import IdaSettings, ida
from frp_assess.dynamics.ida_search import sample, search
from frp_assess.dynamics.kernel.fate import tipping_angle
from frp_assess.dynamics.kernel.simulate import simulate
from frp_assess.dynamics.rocking import RockingModel
from frp_assess.dynamics.wall import Wall
from frp_assess.motions.floor import _relative_acceleration, floor_acceleration
from frp_assess.motions.response import _psa, response_spectrum

#: What a cold cache costs a run of the bundled example, in round seconds of one core: 15-23
#: CPU-s measured (docs/compilation.md); the wall time grows with the machine's load (35 s at
#: load 3, 64-80 s at load 12-14 on the shared 2-core machine)
COMPILE_SECONDS = 20
#: The line a run prints before it compiles (CLI, and the TUI's run log).
COLD_NOTICE = (
    f"compiling the numerical kernel once, about {COMPILE_SECONDS} s "
    "(later runs load it from numba's cache)"
)
#: The compiled functions a run calls from Python (every other one is compiled inside them).
ENTRY_POINTS: tuple[Any, ...] = (
    search, sample, simulate, tipping_angle, _psa, _relative_acceleration,
)  # fmt: skip


def _has_machine_code(dispatcher: Any) -> bool:
    """Whether numba's cache of ``dispatcher`` holds a version compiled for this processor,
    this numba, this source and this bytecode: the index file's checks (numba version and
    source hash, :class:`numba.core.caching.IndexDataCacheFile`) and the entry's key (the
    processor and the bytecode's hash, ``Cache._index_key``), all but the argument types."""
    cache = dispatcher._cache
    index = cache._cache_file._load_index()  # {} when missing, stale or of another numba
    codegen = dispatcher.targetctx.codegen()
    expected = cache._index_key(None, codegen)[1:]
    return any(tuple(key[1:]) == expected for key in index)


def cache_is_cold() -> bool:
    """True when a run would compile: an entry point has no machine code for this processor
    in numba's cache.  Reads numba's index files only (a few ms); False when numba's private
    cache API is not the one expected (no claim is made then)."""
    try:
        return not all(_has_machine_code(d) for d in ENTRY_POINTS)
    except (AttributeError, TypeError, ValueError):  # another numba's internals
        return False


def warm_up_motions() -> None:
    """The response spectra and the floor filter compiled (or loaded): frp_assess/motions."""
    dt, acc = _tiny_record()
    response_spectrum(acc, dt, np.array([0.0, 0.1, 0.5]))
    floor_acceleration(acc, dt, height_building=9.0, storeys=3, wall_base=6.0, period=0.3)


def warm_up_rocking() -> None:
    """The IDA's two searches (the effective collapse intensity's sampling, the default, and
    the first collapse's hunt, which the paper's projects pin; each with the driver it
    inlines), the driver with its history and the tipping angle compiled (or loaded):
    frp_assess/dynamics.  The kernel's arguments have the same types with bars or loads or
    without (:class:`~.kernel.params.KernelParams`: numbers)."""
    dt, acc = _tiny_record()
    model = RockingModel(Wall(thickness=0.25, height=4.5, unit_weight=18e3), "one-sided")
    model.run(acc, dt, history=True)
    ida(model, acc, dt, IdaSettings())
    ida(model, acc, dt, IdaSettings(capacity="first-collapse"))


def warm_up() -> None:
    """Compile (or load) every entry point with the argument types a run gives it, by calling
    the Python faces a run calls, on a tiny wall and record (~0.3 s when warm)."""
    warm_up_motions()
    warm_up_rocking()


def warm_up_in_parallel() -> None:
    """:func:`warm_up` on two cores: the motions' kernels in a second process while this one
    compiles the rocking kernel.  The two compile disjoint modules (numba writes one index
    file per function), so neither overwrites the other's cache."""
    root = str(Path(__file__).resolve().parents[2])  # the helper imports this very package
    path = os.pathsep.join(p for p in (root, os.environ.get("PYTHONPATH")) if p)
    helper = subprocess.Popen(
        [sys.executable, "-c", f"from {__name__} import warm_up_motions as w; w()"],
        env={**os.environ, "PYTHONPATH": path},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    try:
        warm_up_rocking()
    finally:
        _, err = helper.communicate()
    if helper.returncode != 0:
        raise RuntimeError(
            f"compiling the motions' kernels failed:\n{err.decode(errors='replace')}"
        )


def _tiny_record() -> tuple[float, NDArray[np.float64]]:
    """(dt [s], acc [m/s²]): 2 s of a 2 Hz sine of 0.41 g, enough to rock and tip the wall."""
    dt = 0.01
    return dt, 4.0 * libm.sin(2.0 * np.pi * 2.0 * np.arange(200) * dt)
