"""The IDA's search compiled: the hunt and the bisection of docs/model.md §5 in one call.

:func:`frp_assess.dynamics.ida` states the rule and builds the result; this runs its time
histories without returning to Python between them (one call per IDA, the GIL released
throughout, so threads use every core), and skips the record's quiet start.

The quiet start: a wall at rest stays at rest, exactly, until the linear ground acceleration
C·ü_g/g passes tan α_x (:func:`~frp_assess.dynamics.kernel.jumps.uplift`).  In a sample
interval whose two samples are both below the threshold the kernel does nothing but find
that (the state stays exactly zero, the step size untouched); :func:`quiet_intervals` finds
how many such intervals open the record, for each multiplier from one running maximum of
|ü_g|, and the kernel starts at the first interval that may uplift, from rest.  Every number
of the time history is then the same, bit for bit; only its clock starts later (the times
of the outcome are not used by the search).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from frp_assess.dynamics.kernel import Buffers, Ground, KernelParams, simulate
from frp_assess.dynamics.kernel import params as kp

#: Relative margin of the quiet-start test [-]: an interval is skipped only when both its
#: samples are below the uplift threshold by more than this, so rounding in the kernel's own
#: test (ü at the interval's end is rebuilt from its slope) can never matter.
QUIET_MARGIN = 1e-9
#: Status of a search that ran out of room for its time histories (a tolerance so small
#: that the bisection cannot end); never a kernel status.
STATUS_TOO_MANY_RUNS = -1


@njit(cache=True, nogil=True)
def running_max_abs(acc: np.ndarray) -> np.ndarray:
    """max(|acc[0]|, …, |acc[k]|) for every k, in the units of ``acc``."""
    out = np.empty(acc.shape[0])
    m = 0.0
    for k in range(acc.shape[0]):
        a = abs(acc[k])
        if a > m:
            m = a
        out[k] = m
    return out


@njit(cache=True, nogil=True)
def quiet_intervals(peak_so_far: np.ndarray, scale: float, prm: KernelParams) -> int:
    """Sample intervals at the start of ``scale``·acc in which a wall at rest cannot uplift
    (``peak_so_far`` = :func:`running_max_abs` of acc [m/s²]); at most all but the last one,
    so that the kernel always gets two samples."""
    bound = prm.tan_ax * (1.0 - QUIET_MARGIN) * prm.g / scale  # [m/s²]
    first = int(np.searchsorted(peak_so_far, bound))  # first sample that may reach the threshold
    last: int = peak_so_far.shape[0] - 2
    return max(0, min(first - 1, last))


@njit(cache=True, nogil=True)
def next_multiplier(
    hunt: np.ndarray, tolerance: float, runs: int, c_lo: float, c_hi: float
) -> float:
    """The search rule of docs/model.md §5: the next multiplier C to run, or NaN when the
    search is over.

    ``hunt`` holds C₀·s^k up to C_max; ``runs`` time histories were run so far; ``c_lo`` is
    the largest C run without collapse since the hunt began (0 before), ``c_hi`` the last C
    that collapsed (NaN before the first collapse).  The hunt runs ``hunt`` in order until
    the first collapse (over, with no collapse, when it is exhausted); then the bisection
    runs the midpoint of (C_lo, C_hi) until (C_hi − C_lo) ≤ tolerance·C_hi.  Every collapse
    lowers C_hi, every survival raises C_lo, so C_hi stays the *first* collapse of the hunt's
    sequence.
    """
    if math.isnan(c_hi):
        return hunt[runs] if runs < hunt.shape[0] else math.nan
    if c_hi - c_lo > tolerance * c_hi:
        return 0.5 * (c_lo + c_hi)
    return math.nan


@njit(cache=True, nogil=True)
def search(
    acc: np.ndarray,
    dt: float,
    n_tail: int,
    prm: KernelParams,
    hunt: np.ndarray,
    tolerance: float,
    multiplier: np.ndarray,
    fate: np.ndarray,
    peak: np.ndarray,
    ruptures: np.ndarray,
    collapse_fate: np.ndarray,
) -> tuple[int, int]:
    """Every time history of the IDA of the wall ``prm`` under ``acc`` [m/s²] every dt [s]
    (``n_tail`` zero samples after it), as :func:`next_multiplier` chooses them.

    Time history j is stored in ``multiplier[j]`` (C), ``fate[j]`` (the kernel's FATE_*),
    ``peak[j]`` (peak |θ| [rad]) and ``ruptures[j]``; ``collapse_fate[f]`` says whether the
    fate code f is a collapse.  Returns (time histories run, status).  A status other than
    STATUS_OK stops the search at the time history that gave it (the last one stored), or
    says that the arrays had no room for the next (:data:`STATUS_TOO_MANY_RUNS`).
    """
    quiet = running_max_abs(acc)
    h = np.empty(1)  # the history arrays of the driver: not written (no history here)
    out = Buffers(h, h, h, np.zeros(2), np.zeros(2, dtype=np.int64))
    n = 0
    c_lo = 0.0
    c_hi = math.nan
    while True:
        c = next_multiplier(hunt, tolerance, n, c_lo, c_hi)
        if math.isnan(c):
            return n, kp.STATUS_OK
        if n >= multiplier.shape[0]:
            return n, STATUS_TOO_MANY_RUNS
        start = quiet_intervals(quiet, c, prm)
        # record_history as the constant False: numba compiles a version of the driver
        # without the history for it (a version of its own, beside the one of
        # RockingModel.run: 8 CPU-s more on a cold cache), 1.3-9 % faster per IDA than with
        # a flag known only at run time (docs/model.md §4.2)
        res = simulate(Ground(acc[start:], dt, c, n_tail), prm, 0.0, 0.0, False, out)
        multiplier[n] = c
        fate[n] = res.fate
        peak[n] = res.peak
        ruptures[n] = res.ruptures
        n += 1
        if res.status != kp.STATUS_OK:
            return n, res.status
        if collapse_fate[res.fate]:
            c_hi = c
        else:
            c_lo = c
