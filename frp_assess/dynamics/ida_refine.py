"""The default sampling of the effective collapse intensity (docs/model.md §11.2, design (e)):
a coarse ladder up to the first collapse, the fine ladder from a band below it.

The fine ladder is the ladder of §11, C_j = C₀·r^(j+offset) (r = ``analysis.ida.ladder_ratio``);
the coarse ladder is every ``coarse``-th point of it (r^8 ≈ 1.104 for the default 1.0125).  The
sampling, exactly as benchmarks/effective_sampling_designs.py measured it (its ``adapt_design``
with coarse 8, margin 1.35, settle 3, collapsed runs only walked coarse):

1. walk the coarse ladder from C₀ until a point collapses (the first collapse);
2. walk the fine points from ``below`` fine steps under it (C_first/1.35) up to it;
3. go on along the fine ladder; after :data:`SETTLE` collapsed points in a row the step doubles
   (up to ``coarse``); where the outcome changes across a step longer than one, the step's
   interior is walked at the fine density and the step drops back to one;
4. stop early once the points run have collapsed without a break over ``band_steps`` fine
   steps (the band 1.5 of §11 (ii)), or at C_max;
5. bisect every change of outcome between two neighbouring fine points that follows
   :data:`SETTLE` agreeing pairs (a monotone record's threshold: to the IDA tolerance, as the
   §5 search refines its first collapse); every other change takes the midpoint rule of
   :mod:`~frp_assess.dynamics.effective`.

:func:`next_refined` is a state machine (one time history per call, as ``next_sample``), so
the compiled driver and the Python one of the tests run the same samples.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: Agreeing samples in a row before a collapsed run's step doubles, and agreeing pairs before
#: a change of outcome is bisected (docs/model.md §11.2).
SETTLE = 3
#: Slots of the state of :func:`next_refined`: the phase; the fine index j of the walk and its
#: step; the agreeing samples in a row; the outcome at the last walked point (1 collapsed);
#: the collapses seen on the ladder; the index of an inner walk (or of the pair scan) and its
#: end; the agreeing pairs of the scan; the kind and ladder index of the time history whose
#: outcome the next call receives, and its C (NaN: none); the bisection's bracket and the
#: outcome at its lower end.  The outcome at fine point k follows at slot R_SIZE + k (NaN: not
#: run).
(
    R_PHASE, R_J, R_STEP, R_AGREE, R_PREV, R_FELL, R_I, R_END, R_RUN, R_KIND, R_AT, R_LAST,
    R_LO, R_HI, R_S_LO,
) = range(15)  # fmt: skip
R_SIZE = 15
#: phases: walking the ladder, walking the fine points below a walked point, after a walked
#: point (the early stop, the next step), scanning the pairs, bisecting one, over
WALK, BELOW, AFTER, PAIRS, BISECT, OVER = 0.0, 1.0, 2.0, 3.0, 4.0, 5.0


def refine_steps(ratio: float, margin: float, band: float) -> tuple[int, int]:
    """(below, band_steps) in fine steps of ``ratio``: the first collapse's fine walk starts
    ⌈ln margin / ln r⌉ steps under it; the early stop needs the least n with n·ln r ≥ ln band
    (−1: never, band = ∞)."""
    h = math.log(ratio)
    below = math.ceil(math.log(margin) / h)
    if math.isinf(band):
        return below, -1
    n = 0
    while n * h < math.log(band) - 1e-12:
        n += 1
    return below, n


@njit(cache=True, nogil=True)
def new_refined_state(n: int, coarse: int) -> np.ndarray:
    """The state of :func:`next_refined` for a fine ladder of ``n`` points."""
    st = np.full(R_SIZE + n, math.nan)
    st[R_PHASE] = WALK if n > 0 else OVER
    st[R_J] = 0.0
    st[R_STEP] = float(coarse)
    st[R_AGREE] = 0.0
    st[R_PREV] = 0.0
    st[R_FELL] = 0.0
    return st


@njit(cache=True, nogil=True)
def _walked(st: np.ndarray, f: float, coarse: int, below: int) -> None:
    """The walk's rule at its point j, whose outcome is ``f`` (step 2 and 3 of the module
    docstring)."""
    j = int(st[R_J])
    step = st[R_STEP]
    if f != st[R_PREV] and step > 1.0:
        first = f == 1.0 and st[R_FELL] == 1.0
        n_below = below if first else int(step) - 1
        st[R_I] = float(max(0, j - n_below))
        st[R_END] = float(j)
        st[R_STEP] = 1.0
        st[R_AGREE] = 0.0
        st[R_PHASE] = BELOW
    elif f == st[R_PREV]:
        st[R_AGREE] += 1.0
        if st[R_AGREE] >= SETTLE and step < coarse and f == 1.0:
            st[R_STEP] = 2.0 * step
            st[R_AGREE] = 0.0
        st[R_PHASE] = AFTER
    else:
        st[R_AGREE] = 0.0
        st[R_PHASE] = AFTER
    st[R_PREV] = f


@njit(cache=True, nogil=True)
def _stops_early(st: np.ndarray, band_steps: int) -> bool:
    """Whether the points run have collapsed without a break from band_steps fine steps (or
    more) below the walk's point j up to it."""
    seen = st[R_SIZE:]
    j = int(st[R_J])
    if band_steps < 0 or seen[j] != 1.0:
        return False
    start = j
    for p in range(j - 1, -1, -1):
        if math.isnan(seen[p]):
            continue
        if seen[p] != 1.0:
            break
        start = p
    return j - start >= band_steps


@njit(cache=True, nogil=True)
def next_refined(
    ladder: np.ndarray,
    tolerance: float,
    coarse: int,
    below: int,
    band_steps: int,
    shifted: bool,
    st: np.ndarray,
    collapsed: bool,
) -> float:
    """The next C of the sampling of the module docstring on the fine ``ladder``, or NaN when
    it is over; ``collapsed`` is the outcome of the time history at ``st[R_LAST]`` (ignored
    before the first).  ``shifted``: offset > 0, the wall's standing at C₀ (not run) counts as
    the first agreeing sample of the pair scan."""
    seen = st[R_SIZE:]
    c = st[R_LAST]
    if not math.isnan(c):
        f_new = 1.0 if collapsed else 0.0
        if st[R_KIND] == BISECT:
            if f_new == st[R_S_LO]:
                st[R_LO] = c
            else:
                st[R_HI] = c
        else:
            seen[int(st[R_AT])] = f_new
            st[R_FELL] += f_new
            if st[R_KIND] == WALK:
                _walked(st, f_new, coarse, below)
            else:
                st[R_I] += 1.0
    n = ladder.shape[0]
    while True:
        phase = st[R_PHASE]
        if phase == WALK:
            j = int(st[R_J])
            if j >= n:
                st[R_PHASE] = PAIRS
                st[R_I] = 0.0
                st[R_RUN] = 1.0 if shifted and seen[0] == 0.0 else 0.0
            elif math.isnan(seen[j]):
                st[R_AT] = float(j)
                break
            else:
                _walked(st, seen[j], coarse, below)
        elif phase == BELOW:
            i = int(st[R_I])
            if i >= st[R_END]:
                st[R_PHASE] = AFTER
            elif math.isnan(seen[i]):
                st[R_AT] = float(i)
                break
            else:
                st[R_I] = float(i + 1)
        elif phase == AFTER:
            if _stops_early(st, band_steps):
                st[R_J] = float(n)  # the walk is over
            else:
                st[R_J] += st[R_STEP]
            st[R_PHASE] = WALK
        elif phase == PAIRS:
            a = int(st[R_I])
            b = a + 1
            while b < n and math.isnan(seen[b]):
                b += 1
            if b >= n:
                st[R_PHASE] = OVER
                continue
            st[R_I] = float(b)
            run = st[R_RUN]
            st[R_RUN] = run + 1.0 if seen[a] == seen[b] else 0.0
            if seen[a] != seen[b] and run >= SETTLE and b == a + 1:
                st[R_PHASE] = BISECT
                st[R_LO] = ladder[a]
                st[R_HI] = ladder[b]
                st[R_S_LO] = seen[a]
        elif phase == BISECT:
            if st[R_HI] - st[R_LO] > tolerance * st[R_HI]:
                st[R_KIND] = BISECT
                st[R_LAST] = 0.5 * (st[R_LO] + st[R_HI])
                return float(st[R_LAST])
            st[R_PHASE] = PAIRS
        else:
            st[R_LAST] = math.nan
            return math.nan
    st[R_KIND] = st[R_PHASE]
    st[R_LAST] = ladder[int(st[R_AT])]
    return float(st[R_LAST])
