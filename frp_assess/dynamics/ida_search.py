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

from frp_assess.dynamics.ida_refine import new_refined_state, next_refined
from frp_assess.dynamics.kernel import Buffers, Ground, KernelParams, Outcome, simulate
from frp_assess.dynamics.kernel import params as kp
from frp_assess.dynamics.kernel.params import TieParams

#: Relative margin of the quiet-start test [-]: an interval is skipped only when both its
#: samples are below the uplift threshold by more than this, so rounding in the kernel's own
#: test (ü at the interval's end is rebuilt from its slope) can never matter.
QUIET_MARGIN = 1e-9
#: Status of a search that ran out of room for its time histories (a tolerance so small
#: that the bisection cannot end); never a kernel status.
STATUS_TOO_MANY_RUNS = -1
#: Flags of the ``losses`` array of the searches: what the wall lost before its fate.
LOST_BARS = 1  #: a bar broke
LOST_TIE = 2  #: the tie's anchorage failed (docs/model.md §12)


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


@njit(cache=True, nogil=True, inline="always")
def _run_and_store(
    acc: np.ndarray,
    quiet: np.ndarray,
    dt: float,
    c: float,
    n_tail: int,
    prm: KernelParams,
    ties: TieParams,
    out: Buffers,
    n: int,
    multiplier: np.ndarray,
    fate: np.ndarray,
    peak: np.ndarray,
    losses: np.ndarray,
) -> Outcome:
    """Time history n of a search at the multiplier c, from the record's first sample that
    may uplift the wall (:func:`quiet_intervals`), stored at index n; the kernel's outcome.

    record_history is the constant False: numba compiles a version of the driver without the
    history for it (a version of its own, beside the one of RockingModel.run: 8 CPU-s more
    on a cold cache), 1.3-9 % faster per IDA than with a flag known only at run time
    (docs/model.md §4.2)."""
    start = quiet_intervals(quiet, c, prm)
    res = simulate(Ground(acc[start:], dt, c, n_tail), prm, ties, 0.0, 0.0, False, out)
    multiplier[n] = c
    fate[n] = res.fate
    peak[n] = res.peak
    losses[n] = (LOST_BARS if res.ruptures > 0 else 0) + (LOST_TIE if res.tie_lost else 0)
    return res


@njit(cache=True, nogil=True)
def search(
    acc: np.ndarray,
    dt: float,
    n_tail: int,
    prm: KernelParams,
    ties: TieParams,
    hunt: np.ndarray,
    tolerance: float,
    multiplier: np.ndarray,
    fate: np.ndarray,
    peak: np.ndarray,
    losses: np.ndarray,
    collapse_fate: np.ndarray,
) -> tuple[int, int]:
    """Every time history of the IDA of the wall ``prm`` (its ties ``ties``) under ``acc``
    [m/s²] every dt [s] (``n_tail`` zero samples after it), as :func:`next_multiplier`
    chooses them.

    Time history j is stored in ``multiplier[j]`` (C), ``fate[j]`` (the kernel's FATE_*),
    ``peak[j]`` (peak |θ| [rad]) and ``losses[j]`` (LOST_* flags); ``collapse_fate[f]`` says
    whether the fate code f is a collapse.  Returns (time histories run, status).  A status
    other than STATUS_OK stops the search at the time history that gave it (the last one stored), or
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
        res = _run_and_store(acc, quiet, dt, c, n_tail, prm, ties, out, n, multiplier, fate,
                             peak, losses)  # fmt: skip
        n += 1
        if res.status != kp.STATUS_OK:
            return n, res.status
        if collapse_fate[res.fate]:
            c_hi = c
        else:
            c_lo = c


#: Slots of the state array of :func:`next_sample` (docs/model.md §11): the index of the last
#: ladder point run; the phase (:data:`ON_LADDER`, :data:`ON_CELL`, :data:`BISECTING`) and
#: the one a bisection returns to; the bisection's bracket (C_lo, C_hi) and the outcome at
#: C_lo (1 standing, 0 collapsed); the outcome of the last ladder point; the C at which the
#: current run of collapsed ladder points began (NaN: the last one stood); the C and kind of
#: the time history whose outcome the next call receives (NaN before the first); the cell
#: being subdivided (its ends and the outcome at the upper one), the index of its last
#: interior point run, and the C and outcome of the point before.
(
    ST_K, ST_PHASE, ST_RETURN, ST_LO, ST_HI, ST_S_LO, ST_S_PREV, ST_BAND, ST_LAST,
    ST_KIND, ST_CELL_A, ST_CELL_B, ST_S_B, ST_J, ST_PREV_C, ST_PREV_S,
) = range(16)  # fmt: skip
STATE_SIZE = 16
#: phases of the sampling: walking the ladder, walking the interior points of a cell whose
#: ends disagree, bisecting a change of outcome
ON_LADDER, ON_CELL, BISECTING = 0.0, 1.0, 2.0


@njit(cache=True, nogil=True)
def new_state() -> np.ndarray:
    """The state of :func:`next_sample` before the first time history: below the ladder the
    wall stands (below C₀ nothing moves)."""
    st = np.full(STATE_SIZE, math.nan)
    st[ST_K] = -1.0
    st[ST_PHASE] = ON_LADDER
    st[ST_S_PREV] = 1.0
    return st


@njit(cache=True, nogil=True)
def _bisect(st: np.ndarray, lo: float, hi: float, s_lo: float, back: float) -> None:
    """Start bisecting the change of outcome in (lo, hi), then go back to phase ``back``."""
    st[ST_PHASE] = BISECTING
    st[ST_RETURN] = back
    st[ST_LO] = lo
    st[ST_HI] = hi
    st[ST_S_LO] = s_lo


@njit(cache=True, nogil=True)
def next_sample(
    ladder: np.ndarray,
    c0: float,
    tolerance: float,
    band: float,
    subdivide: int,
    st: np.ndarray,
    collapsed: bool,
) -> float:
    """The sampling of the effective collapse intensity (docs/model.md §11): the next C to
    run, or NaN when the sampling is over; ``collapsed`` is the outcome of the time history
    at ``st[ST_LAST]`` (ignored before the first).

    The ladder (C₀·r^(k+offset) up to C_max) is run in order.  Where a ladder point's outcome
    differs from the previous one's (C₀ itself, standing, before the first), the cell between
    them is walked at ``subdivide`` times the density (its interior points C_a·(C_b/C_a)^(j/m),
    j = 1 … m − 1), and every change of outcome between two neighbours of that walk is
    bisected until (C_hi − C_lo) ≤ tolerance·C_hi, as the §5 search refines its first
    collapse; then the ladder goes on.  It stops early once the ladder points have collapsed
    without a break over a band C_k/C_first ≥ ``band`` (∞: never; S = 0 is then assumed up to
    C_max, the shortcut of §11 (ii)).
    """
    c = st[ST_LAST]
    if not math.isnan(c):
        s = 0.0 if collapsed else 1.0
        kind = st[ST_KIND]
        if kind == BISECTING:
            if s == st[ST_S_LO]:
                st[ST_LO] = c
            else:
                st[ST_HI] = c
        elif kind == ON_CELL:
            if s != st[ST_PREV_S]:
                _bisect(st, st[ST_PREV_C], c, st[ST_PREV_S], ON_CELL)
            st[ST_PREV_C] = c
            st[ST_PREV_S] = s
        else:
            k = int(st[ST_K])
            before = ladder[k - 1] if k > 0 else c0
            if s != st[ST_S_PREV]:
                if subdivide > 1:
                    st[ST_PHASE] = ON_CELL
                    st[ST_CELL_A] = before
                    st[ST_CELL_B] = c
                    st[ST_S_B] = s
                    st[ST_J] = 0.0
                    st[ST_PREV_C] = before
                    st[ST_PREV_S] = st[ST_S_PREV]
                else:
                    _bisect(st, before, c, st[ST_S_PREV], ON_LADDER)
            st[ST_S_PREV] = s
            if s == 1.0:
                st[ST_BAND] = math.nan
            elif math.isnan(st[ST_BAND]):
                st[ST_BAND] = c
    m = 0.0
    while True:
        phase = st[ST_PHASE]
        if phase == BISECTING:
            if st[ST_HI] - st[ST_LO] > tolerance * st[ST_HI]:
                m = float(0.5 * (st[ST_LO] + st[ST_HI]))
                break
            st[ST_PHASE] = st[ST_RETURN]
        elif phase == ON_CELL:
            j = int(st[ST_J]) + 1
            st[ST_J] = float(j)
            if j < subdivide:
                a = st[ST_CELL_A]
                m = float(a * (st[ST_CELL_B] / a) ** (j / subdivide))
                break
            # the last interior point against the cell's upper end
            st[ST_PHASE] = ON_LADDER
            if st[ST_PREV_S] != st[ST_S_B]:
                _bisect(st, st[ST_PREV_C], st[ST_CELL_B], st[ST_PREV_S], ON_LADDER)
        else:
            k = int(st[ST_K])
            if k >= 0 and not math.isnan(st[ST_BAND]) and ladder[k] >= band * st[ST_BAND]:
                return math.nan
            k += 1
            if k >= ladder.shape[0]:
                return math.nan
            st[ST_K] = float(k)
            m = float(ladder[k])
            break
    st[ST_KIND] = st[ST_PHASE]
    st[ST_LAST] = m
    return m


@njit(cache=True, nogil=True)
def sample(
    acc: np.ndarray,
    dt: float,
    n_tail: int,
    prm: KernelParams,
    ties: TieParams,
    ladder: np.ndarray,
    c0: float,
    tolerance: float,
    band: float,
    subdivide: int,
    coarse: int,
    below: int,
    band_steps: int,
    shifted: bool,
    multiplier: np.ndarray,
    fate: np.ndarray,
    peak: np.ndarray,
    losses: np.ndarray,
    collapse_fate: np.ndarray,
) -> tuple[int, int]:
    """Every time history of the effective collapse intensity's sampling, stored and returned
    as :func:`search` does: with ``coarse`` > 1 the default one of
    :func:`~frp_assess.dynamics.ida_refine.next_refined` (``below``, ``band_steps``,
    ``shifted``), else the plain ladder of :func:`next_sample` (``band``, ``subdivide``)."""
    quiet = running_max_abs(acc)
    h = np.empty(1)  # the history arrays of the driver: not written (no history here)
    buffers = Buffers(h, h, h, np.zeros(2), np.zeros(2, dtype=np.int64))
    st = new_refined_state(ladder.shape[0], coarse) if coarse > 1 else new_state()
    n = 0
    collapsed = False
    while True:
        if coarse > 1:
            c = next_refined(ladder, tolerance, coarse, below, band_steps, shifted, st, collapsed)
        else:
            c = next_sample(ladder, c0, tolerance, band, subdivide, st, collapsed)
        if math.isnan(c):
            return n, kp.STATUS_OK
        if n >= multiplier.shape[0]:
            return n, STATUS_TOO_MANY_RUNS
        out = _run_and_store(acc, quiet, dt, c, n_tail, prm, ties, buffers, n, multiplier,
                             fate, peak, losses)  # fmt: skip
        n += 1
        if out.status != kp.STATUS_OK:
            return n, out.status
        collapsed = collapse_fate[out.fate]
