"""Constants of one time history, packed once for the compiled kernel (docs/model.md §3–4).

:class:`KernelParams` is a plain named tuple of numbers: numba passes it to every compiled
piece as one typed record, so a constant is named where it is used and two floats can never
be swapped silently.  The codes below are shared by the kernel and its Python face
(:mod:`frp_assess.dynamics.rocking`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

# the records' form for every compiled kernel, the spectra's too (re-exported here)
from frp_assess.motions.record import kernel_record as kernel_record

BAR_NONE = 0  #: unreinforced
BAR_SHARED = 1  #: centred bar: acts for both signs of θ, one rupture removes it for both
BAR_PER_SIDE = 2  #: external bars: the bar opposite the pivot acts; each side breaks on its own

RUPTURE_ENERGY_TRANSFER = 0  #: Eq. 12: ½I0θ'₊² = ½I0θ'₋² + U_r(θ_max)
RUPTURE_VELOCITY_CONTINUOUS = 1  #: θ' unchanged at rupture (the bar's energy is lost)

COLLAPSE_OVERTURNING = 0  #: the wall falls (|θ| = π/2), followed into free vibration
COLLAPSE_END_OF_RECORD = 1  #: |θ| ≥ α_x when the input ends (or |θ| reaches π/2 earlier)
COLLAPSE_FIRST_EXCEEDANCE = 2  #: |θ| reaches α_x at any time

METHOD_DOPRI5 = 0  #: Dormand–Prince 5(4) with local error control (the default)
METHOD_RK4 = 1  #: classical RK4 at a fixed step (the independent reference)
METHOD_BS3 = 2  #: Bogacki–Shampine 3(2) with local error control

FATE_FELL = 0  #: |θ| reached π/2
FATE_AT_REST = 1  #: `overturning`: the wall can no longer fall
FATE_EXCEEDED = 2  #: `end-of-record`/`first-exceedance`: the rule's limit |θ| ≥ α_x was met
FATE_STANDING = 3  #: `end-of-record`/`first-exceedance`: the input ended below the limit
FATE_CRUSHED = 4  #: the compressed zone reached the intact acting bar: the toe crushed

# the state of a tie level (docs/model.md §12), up to MAX_TIE_LEVELS (of rules.tie_rods: the
# Regime's and TieParams' tuples hold 2) per wall; a tie acts on side + only
TIE_OFF = 0  #: no tie
TIE_SLACK = 1  #: δ ≤ δ_p: the tie carries nothing (or the wall rocks on side −)
TIE_ELASTIC = 2  #: F_t = k_t·(δ − δ_p) between 0 and F_y (F_a of a brittle tie)
TIE_YIELD = 3  #: F_t = F_y while the wall moves outward; δ_p grows with δ
TIE_LOST = 4  #: the anchorage failed: it carries nothing for the rest of the time history

STATUS_OK = 0
STATUS_EVENT_OVERFLOW = 1  #: too many events in one sample interval (Zeno chatter guard)
STATUS_STEP_UNDERFLOW = 2  #: the error control asked for a step below MIN_STEP_FRACTION·dt
STATUS_FREE_VIBRATION_UNDECIDED = 3  #: the fate was not certain after MAX_FREE_VIBRATION

#: After an impact, |θ'| below REST_VELOCITY·p [rad/s] means the wall is at rest.
REST_VELOCITY = 1e-7
#: Most events tolerated in one sample interval before giving up (never seen in practice).
MAX_EVENTS_PER_INTERVAL = 100_000
#: An event is located when the Newton correction of its instant, |s·θ − level|/|θ'|, is at
#: most EVENT_TIME_TOLERANCE times the step [-].  A bound on the instant, not on θ: an absolute
#: 1e-13 rad let the instant of an impact at |θ'| ~ 1e-6 rad/s be off by 1e-7 s and the
#: velocity after it by θ''·1e-7, an error no tolerance of the pair removed, which hundreds of
#: small-amplitude impacts amplified to 2e-3 of a later peak (docs/model.md §4.3).
EVENT_TIME_TOLERANCE = 1e-12
#: Newton iterations allowed to locate one event on the integrator.
EVENT_ITERATIONS = 30
#: The error control gives up below this fraction of the sample interval.
MIN_STEP_FRACTION = 1e-12
#: Longest free vibration after the input before the fate must be certain [s].
MAX_FREE_VIBRATION = 300.0
#: Step-size controller of the embedded pair: safety factor and the bounds of one change.
STEP_SAFETY = 0.9
STEP_GROWTH_MAX = 5.0
STEP_SHRINK_MIN = 0.2


class KernelParams(NamedTuple):
    """Everything the kernel needs besides the record and the state (SI units)."""

    g: float  #: gravity [m/s²]
    p2: float  #: p² [1/s²]
    p: float  #: frequency parameter p [1/s]
    alpha: float  #: slenderness α [rad] (the corners: impacts and the error scale)
    sin_a: float  #: sin α
    cos_a: float  #: cos α
    one_sided: bool  #: only θ ≥ 0, rebound at θ = 0
    bar_mode: int  #: BAR_NONE, BAR_SHARED or BAR_PER_SIDE
    k_bar: float  #: K of Eq. 10 while the acting bar is intact [-]
    theta_max: float  #: rupture rotation θ_max [rad] (inf: never)
    rupture_energy: float  #: U_r(θ_max)/I0 [rad²/s²], the energy Eq. 12 hands to the wall
    e_impact: float  #: velocity ratio |θ'₊/θ'₋| at an impact [-]
    rupture_mode: int  #: RUPTURE_ENERGY_TRANSFER or RUPTURE_VELOCITY_CONTINUOUS
    collapse_mode: int  #: COLLAPSE_OVERTURNING, COLLAPSE_END_OF_RECORD or COLLAPSE_FIRST_EXCEEDANCE
    method: int  #: METHOD_DOPRI5 or METHOD_RK4
    tolerance: float  #: local error tolerance of the embedded pair [-]
    fixed_step: float  #: largest RK4 step [s] (METHOD_RK4 only)
    # --- the base reaction (docs/model.md §1.1); 0, α, ∞ with the edge pivot -------------
    xi: float  #: ξ = x_W/(2R) [-]; 0: the edge pivot, the reaction term is skipped
    kappa_per_k: float  #: κ/K [-]: κ_s = K_s·κ/K, κ = 2·b_r·E·A/(H·W) (0 without ξ)
    theta_cr: float  #: |θ| at which the toe crushes under an intact acting bar [rad] (inf: never)
    alpha_x: float  #: α_x = atan((B − x_W)/H) [rad]: the tipping limit of the rules and outputs
    tan_ax: float  #: tan α_x [-]: the uplift threshold in g
    tip_bar: float  #: θ*: where V stops rising with the acting bar intact [rad] (≤ π/2)
    # --- each side's equation of motion with the loads of docs/model.md §12 ----------------
    # The bracket of Eq. 10 on side s is (a0_s + u·a1_s)·cos θ + (K_s + b0_s + u·b1_s)·sin θ
    # (:mod:`frp_assess.dynamics.loads`); without loads a0 = s·sin α, a1 = cos α, b0 = −cos α,
    # b1 = s·sin α and p²_s = p²: the paper's Eq. 10, the same numbers bit for bit.
    loaded: bool  #: the wall carries loads: the rules below that depend on them take them
    p2_pos: float  #: p²_+ = W·R/I_+ [1/s²]
    p2_neg: float  #: p²_− = W·R/I_− [1/s²]
    a0_pos: float  #: [-]
    a0_neg: float  #: [-]
    a1_pos: float  #: [-]
    a1_neg: float  #: [-]
    b0_pos: float  #: [-]
    b0_neg: float  #: [-]
    b1_pos: float  #: [-]
    b1_neg: float  #: [-]
    tan_pos: float  #: the uplift threshold on side + in g: rocking starts when u < −tan_pos [-]
    tan_neg: float  #: on side −: when u > tan_neg (two-sided only) [-]
    e_to_pos: float  #: velocity ratio at an impact after which the wall rocks on side + [-]
    e_to_neg: float  #: and on side − [-]
    alpha_x_neg: float  #: where the wall without bar tips on side − [rad] (α_x: side +)
    tip_bar_neg: float  #: θ* of side − with the acting bar intact [rad] (tip_bar: side +)
    # --- the ties of docs/model.md §12: their constants are a TieParams of their own
    tie_on: bool  #: the wall has a tie
    #: the bounces after an impact are ended at once when they surely die out where the input
    #: cannot uplift the wall (:func:`.jumps.chatter_ends`; the same results, fewer impacts to
    #: follow); False only to show that
    settle_chatter: bool = True


class TieParams(NamedTuple):
    """The tie levels of docs/model.md §12 (:func:`frp_assess.dynamics.loads.tie_levels`): the
    first ``levels`` entries of each tuple, the others never read.  On side + the moment of
    level j over W·R is kn[j]·(h_t·sin θ − δ_p)·cos θ while elastic and
    kn[j]·yield_elongation[j]·cos θ while yielding (F_t·h_t·cos θ/(W·R), F_t = k_t·(δ − δ_p)
    or F_y).

    Kept out of :class:`KernelParams`: numba passes that record field by field to every
    kernel function it does not inline, and ten more numbers in it made the bare wall's IDAs
    1.5 % slower (benchmarks/bench_kernel_against.py, 2026-11-28); these go only where a tie
    acts (the driver, the jumps, the fate with ties).
    """

    levels: int  #: tie levels (0 to MAX_TIE_LEVELS)
    height: tuple[float, float]  #: h_t [m]
    kn: tuple[float, float]  #: k_t·h_t/(W·R) [1/m]
    yield_elongation: tuple[float, float]  #: F_y/k_t [m]: the elastic elongation at yield
    #: θ where a brittle tie (F_a ≤ F_y) is lost, asin(F_a/(k_t·h_t)) [rad] (inf: never)
    theta_loss: tuple[float, float]


#: A wall without a tie: no level (the entries are never read).
NO_TIES = TieParams(0, (1.0, 1.0), (0.0, 0.0), (math.inf, math.inf), (math.inf, math.inf))
