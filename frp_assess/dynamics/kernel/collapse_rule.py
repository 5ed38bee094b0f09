"""The collapse rule's verdict (docs/model.md §3.5): when the wall's
fate is decided, and which.

The driver (:mod:`.simulate`) asks :func:`collapse_verdict` after every event it located,
after every step of the free vibration and when the input ends; the answer is a FATE_* code, or
:data:`UNDECIDED` to go on.  Every rule of collapse is here:

* the toe crushing (|θ| reaches θ_cr with the acting bar intact) is a collapse under every rule;
* the collapse level, :func:`collapse_level`: π/2 (the wall fell), or α_x under
  ``first-exceedance``: the instant the wall reaches it decides;
* ``overturning``: after the input the wall moves freely until it falls or can no longer fall
  (:func:`.fate.cannot_fall`, :func:`.tie_fate.tied_cannot_fall` with a tie; its peaks still
  to come: :func:`peaks_at_rest`);
* ``end-of-record`` and ``first-exceedance``: when the input ends, |θ| ≥ α_x is a collapse
  under ``end-of-record`` (at the last upward crossing of α_x, :func:`alpha_x_crossing`),
  anything else leaves the wall standing.
"""

from __future__ import annotations

import math

from numba import njit

from frp_assess.dynamics.kernel.fate import cannot_fall, remaining_peak
from frp_assess.dynamics.kernel.params import (
    COLLAPSE_END_OF_RECORD,
    COLLAPSE_FIRST_EXCEEDANCE,
    COLLAPSE_OVERTURNING,
    FATE_AT_REST,
    FATE_CRUSHED,
    FATE_EXCEEDED,
    FATE_FELL,
    FATE_STANDING,
    KernelParams,
    TieParams,
)
from frp_assess.dynamics.kernel.state import Regime
from frp_assess.dynamics.kernel.step_scan import CRUSH, LIMIT
from frp_assess.dynamics.kernel.tie_fate import tied_cannot_fall, tied_remaining_peak

#: The verdict while the fate is still open.
UNDECIDED = -1


@njit(cache=True, nogil=True, inline="always")
def collapse_level(prm: KernelParams) -> float:
    """|θ| whose crossing is the rule's collapse event [rad]: α_x under ``first-exceedance``,
    else π/2 (the wall fell)."""
    return prm.alpha_x if prm.collapse_mode == COLLAPSE_FIRST_EXCEEDANCE else 0.5 * math.pi


@njit(cache=True, nogil=True, inline="always")
def alpha_x_crossing(
    y0: float, y1: float, t0: float, span: float, level: float, last: float
) -> float:
    """The time [s] at which s·θ rose through ``level`` on a piece from (t0, y0) to
    (t0 + span, y1), by linear interpolation, if it did; else ``last``, the previous one
    (``end-of-record`` dates its collapse at the last upward crossing of α_x)."""
    if y0 < level <= y1:
        return t0 + span * (level - y0) / (y1 - y0)
    return last


@njit(cache=True, nogil=True, inline="always")
def collapse_verdict(
    theta: float,
    omega: float,
    r: Regime,
    free: bool,
    event: int,
    level: float,
    now: float,
    last_alpha_up: float,
    prm: KernelParams,
    ties: TieParams,
) -> tuple[int, float]:
    """(fate or :data:`UNDECIDED`, collapse time [s] or NaN) of the wall at (θ, θ') in regime r
    at the instant ``now`` [s], just after ``event`` (a step_scan code; NO_EVENT after a step
    or at a sample) located at ``level``; ``free``: the input is over."""
    if event == CRUSH:
        return FATE_CRUSHED, now
    if event == LIMIT:
        return (FATE_FELL if level >= 0.5 * math.pi else FATE_EXCEEDED), now
    if not free:
        return UNDECIDED, math.nan
    if prm.collapse_mode != COLLAPSE_OVERTURNING:  # the rules of α_x judge when the input ends
        if prm.collapse_mode == COLLAPSE_END_OF_RECORD and abs(theta) >= prm.alpha_x:
            return FATE_EXCEEDED, last_alpha_up
        return FATE_STANDING, math.nan
    if r.resting:
        return FATE_AT_REST, math.nan
    if prm.tie_on:
        if tied_cannot_fall(theta, omega, r, prm, ties):
            return FATE_AT_REST, math.nan
    elif cannot_fall(theta, omega, r.s, r.intact_pos, r.intact_neg, prm):
        return FATE_AT_REST, math.nan
    return UNDECIDED, math.nan


@njit(cache=True, nogil=True)
def peaks_at_rest(
    theta: float,
    omega: float,
    r: Regime,
    peak: float,
    peak_bar: float,
    prm: KernelParams,
    ties: TieParams,
) -> tuple[float, float]:
    """(peak, peak with an intact bar) once the wall can no longer fall: the rotation of the
    rocking still to come is the turning angle its energy reaches (:func:`.fate.remaining_peak`)."""
    if r.resting:
        return peak, peak_bar
    if prm.tie_on:
        extra, with_bar = tied_remaining_peak(theta, omega, r, prm, ties)
    else:
        extra, with_bar = remaining_peak(theta, omega, r.s, r.intact_pos, r.intact_neg, prm)
    return max(peak, extra), (max(peak_bar, extra) if with_bar else peak_bar)
