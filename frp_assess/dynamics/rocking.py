"""Time history of one wall under one scaled record: the Python face of the kernel."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import Literal, get_args

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics.base_reaction import PIVOT_RULES, BaseReaction, PivotRule
from frp_assess.dynamics.kernel import Buffers, Ground, history_length, simulate
from frp_assess.dynamics.kernel import params as kp
from frp_assess.dynamics.kernel.fate import loaded_tipping_angle, tipping_angle
from frp_assess.dynamics.loads import NO_LOADS, Loads, side_terms, tie_levels, tie_params
from frp_assess.dynamics.options import (
    COLLAPSE,
    COLLAPSE_RULES,
    FREE_VIBRATION_TAIL,
    INTEGRATION_TOLERANCE,
    PIVOT,
    RESTITUTION,
    RUPTURE,
    RUPTURE_RULES,
    CollapseRule,
    RuptureRule,
)
from frp_assess.dynamics.rebars import Rebars
from frp_assess.dynamics.restitution import Restitution, velocity_ratio
from frp_assess.dynamics.wall import Mechanism, Wall
from frp_assess.errors import NumericalError
from frp_assess.rules.constants import G
from frp_assess.rules.wall_loads import impact_velocity_ratio

Fate = Literal["fell", "at rest", "exceeded", "standing", "crushed"]
#: How a wall that collapsed failed (docs/model.md §1.1, §12): it fell (or met the α_x limit of
#: the other collapse rules), or its toe crushed under an intact bar, after a bar broke or not,
#: or it fell after its tie's anchorage failed (and a bar broke, or not).
FailureMode = Literal[
    "overturning",
    "rupture then overturning",
    "crushing",
    "rupture then crushing",
    "tie lost then overturning",
    "rupture and tie lost then overturning",
]
#: Every failure mode, in the order of :data:`FailureMode` (derived: one list to keep).
FAILURE_MODES: tuple[FailureMode, ...] = get_args(FailureMode)
#: The fates that are a collapse: the wall fell (or met the α_x limit of the other collapse
#: rules), or its toe crushed.
COLLAPSE_FATES: frozenset[Fate] = frozenset({"fell", "exceeded", "crushed"})


def failure_mode_of(fate: Fate, ruptured: bool, tie_lost: bool = False) -> FailureMode | None:
    """How a wall whose time history ended in ``fate`` failed (``None``: it did not collapse);
    ``ruptured``: a bar broke before; ``tie_lost``: a tie's anchorage failed before (a wall
    that lost both and fell: "rupture and tie lost then overturning"; the toe's crushing is
    named by the bars alone, the tie takes no part in it)."""
    if fate not in COLLAPSE_FATES:
        return None
    if tie_lost and fate != "crushed":
        return "rupture and tie lost then overturning" if ruptured else "tie lost then overturning"
    head = "rupture then " if ruptured else ""
    return f"{head}{'crushing' if fate == 'crushed' else 'overturning'}"  # type: ignore[return-value]


#: Default local error tolerance of the Dormand–Prince pair [-] (the measurement that chose it:
#: :data:`~frp_assess.dynamics.options.INTEGRATION_TOLERANCE`).
DEFAULT_TOLERANCE = INTEGRATION_TOLERANCE.default
#: Bounds of the tolerance a user may ask for [-].
TOLERANCE_RANGE = INTEGRATION_TOLERANCE.bounds

#: The kernel's fate codes by name.
FATE_NAMES: dict[int, Fate] = {
    kp.FATE_FELL: "fell",
    kp.FATE_AT_REST: "at rest",
    kp.FATE_EXCEEDED: "exceeded",
    kp.FATE_STANDING: "standing",
    kp.FATE_CRUSHED: "crushed",
}
_STATUS_MESSAGES = {
    kp.STATUS_EVENT_OVERFLOW: "too many events in one sample interval",
    kp.STATUS_STEP_UNDERFLOW: (
        f"the error control asked for a step below {kp.MIN_STEP_FRACTION:g}·dt"
    ),
    kp.STATUS_FREE_VIBRATION_UNDECIDED: (
        f"the wall's fate was not certain after {kp.MAX_FREE_VIBRATION:g} s of free vibration"
    ),
}


@dataclass(frozen=True)
class ModelOptions:
    """Model choices of docs/model.md §3–4 that the user can change.

    Attributes:
        restitution: ``"energy"`` (|θ'₊| = √r·|θ'₋|, default), ``"velocity"`` (r·|θ'₋|) or a
            velocity ratio in (0, 1].
        rupture: ``"energy-transfer"`` (Eq. 12, default) or ``"velocity-continuous"``.
        collapse: ``"overturning"`` (the wall falls, followed into free vibration after the
            record; default), ``"end-of-record"`` (|θ| ≥ α when the input ends, the paper's
            convention) or ``"first-exceedance"`` (|θ| reaches α at any time).
        free_vibration_tail: zero ground motion appended to the record [s]; it cannot change
            an ``overturning`` verdict.
        tolerance: local error tolerance of the Dormand–Prince 5(4) pair [-].
        fixed_step: if set, classical RK4 at this largest fixed step [s] instead of the
            error-controlled pair (the independent reference of the tests and benchmarks).
        method: the embedded pair, ``"dopri5"`` (Dormand–Prince 5(4), default) or ``"bs3"``
            (Bogacki–Shampine 3(2); kept for the benchmark that chose the default).
        pivot: ``"crushing"`` (default: the base reaction N = W + T(θ) acts at x/2 from the
            corner, x = N/(0.85·f_d), f_d = :attr:`Wall.compressive_strength`, and the toe can
            crush; a wall without a strength is the edge model) or ``"edge"`` (the paper:
            x = 0; docs/model.md §1.1).
    """

    restitution: Restitution = RESTITUTION.default
    rupture: RuptureRule = RUPTURE.default
    collapse: CollapseRule = COLLAPSE.default
    free_vibration_tail: float = FREE_VIBRATION_TAIL.default
    tolerance: float = INTEGRATION_TOLERANCE.default
    fixed_step: float | None = None
    method: Literal["dopri5", "bs3"] = "dopri5"
    pivot: PivotRule = PIVOT.default

    def __post_init__(self) -> None:
        if self.rupture not in RUPTURE_RULES:
            raise ValueError(f"rupture rule must be one of {RUPTURE_RULES}, got {self.rupture!r}")
        if self.collapse not in COLLAPSE_RULES:
            raise ValueError(
                f"collapse rule must be one of {COLLAPSE_RULES}, got {self.collapse!r}"
            )
        if not (math.isfinite(self.free_vibration_tail) and self.free_vibration_tail >= 0.0):
            raise ValueError(
                f"free-vibration tail must be >= 0 s, got {self.free_vibration_tail!r}"
            )
        lo, hi = TOLERANCE_RANGE
        if not (math.isfinite(self.tolerance) and lo <= self.tolerance <= hi):
            raise ValueError(
                f"integration tolerance must be in [{lo:g}, {hi:g}], got {self.tolerance!r}"
            )
        if self.pivot not in PIVOT_RULES:
            raise ValueError(f"pivot must be one of {PIVOT_RULES}, got {self.pivot!r}")
        if self.fixed_step is not None and not (
            math.isfinite(self.fixed_step) and self.fixed_step > 0.0
        ):
            raise ValueError(f"fixed step must be > 0 s, got {self.fixed_step!r}")


@dataclass(frozen=True)
class History:
    """Time histories at the record's samples, the free vibration after it included."""

    time: NDArray[np.float64]  #: [s]
    theta: NDArray[np.float64]  #: rotation θ [rad]
    omega: NDArray[np.float64]  #: angular velocity θ' [rad/s]
    strain: NDArray[np.float64]  #: strain of the acting bar [-] (0 when unreinforced/broken)

    @property
    def computed(self) -> int:
        """Samples computed (up to the fall, or to the instant the fate was decided)."""
        return int(self.theta.size)


@dataclass(frozen=True)
class Rupture:
    time: float  #: [s]
    side: int  #: +1 or -1: sign of θ when the bar broke


@dataclass(frozen=True)
class RockingResult:
    """What one time history gives."""

    #: fell, at rest (overturning); exceeded, standing (the α_x-based rules); crushed (any)
    fate: Fate
    decided_time: float  #: when the fate became certain [s]
    collapse_time: float | None  #: [s]; None without collapse
    max_rotation: float  #: peak |θ| [rad], the free vibration after the record included
    max_rotation_ratio: float  #: peak |θ| / α_x [-]
    peak_strain: float  #: peak strain of an intact acting bar [-] (0 when unreinforced)
    rupture_strain: float | None  #: ε_max = c·ε_u of the bars [-]; None when unreinforced
    impacts: int  #: impacts followed (not the bounces that surely die out: docs/model.md §3.3)
    ruptures: tuple[Rupture, ...]
    final_theta: float  #: [rad]
    final_omega: float  #: [rad/s]
    steps: int  #: accepted integration steps
    rejected_steps: int  #: steps the error control rejected
    history: History | None = field(default=None, repr=False)
    tie_lost: bool = False  #: the tie's anchorage failed (docs/model.md §12)
    #: each tie level's δ_p at the end [m] (:func:`~.loads.tie_levels`; () without a tie)
    tie_plastic_elongations: tuple[float, ...] = ()

    @property
    def collapsed(self) -> bool:
        """The collapse rule's verdict: the wall fell (or met the α_x limit of the other
        rules), or its toe crushed."""
        return self.fate in COLLAPSE_FATES

    @property
    def failure_mode(self) -> FailureMode | None:
        """How the wall failed (``None``: it did not collapse)."""
        return failure_mode_of(self.fate, bool(self.ruptures), self.tie_lost)

    @property
    def tie_plastic_elongation(self) -> float:
        """The largest plastic elongation of a tie level at the end [m] (0 without a tie)."""
        return max(self.tie_plastic_elongations, default=0.0)


@dataclass(frozen=True)
class RockingModel:
    """A wall, its mechanism, its rebars (``None``: unreinforced) and the model options.

    Every constant the kernel needs is derived once here (:attr:`params`), so an IDA can run
    the same model many times at different scales.
    """

    wall: Wall
    mechanism: Mechanism
    rebars: Rebars | None = None
    options: ModelOptions = ModelOptions()
    #: what bears on and pushes the wall (docs/model.md §12); none: the free-standing wall
    loads: Loads = NO_LOADS

    def __post_init__(self) -> None:
        if self.mechanism not in ("one-sided", "two-sided"):
            raise ValueError(
                f"mechanism must be 'one-sided' or 'two-sided', got {self.mechanism!r}"
            )
        _ = self.base_reaction  # x_W ≥ B: the base cannot carry the wall's weight

    @cached_property
    def base_reaction(self) -> BaseReaction:
        """The stress block at the base (``options.pivot``, docs/model.md §1.1)."""
        return BaseReaction(self.wall, self.rebars, self.options.pivot, self.loads.vertical)

    @property
    def alpha(self) -> float:
        """α_x [rad], where the wall tips: atan((B − x_W)/H), the wall's α with the edge
        pivot; with loads, where the static restoring moment of the outward side vanishes
        (docs/model.md §12).  The α of the collapse rules and of θ/α in the outputs."""
        if self.params.loaded:
            return self.params.alpha_x
        return self.base_reaction.alpha_x

    @property
    def a_rm(self) -> float:
        """Ground acceleration that starts rocking, g·tan α_x = g·(B − x_W)/H [m/s²]; with
        loads, a_RM of §12 on the side that rocks first (the smaller of those that can)."""
        if self.params.loaded:
            return G * self.params.tan_ax
        return self.base_reaction.a_rm

    @property
    def a_rm_g(self) -> float:
        """:attr:`a_rm` in g [-]."""
        return self.a_rm / G

    @property
    def impact_velocity_ratio(self) -> float:
        """Eqs. 13–14 by the restitution convention, at the wall's α (its corners)."""
        return velocity_ratio(self.options.restitution, self.mechanism, self.wall.alpha)

    @property
    def K(self) -> float:  # noqa: N802 - the paper's symbol
        """K of Eq. 10 [-] (0 when unreinforced)."""
        return 0.0 if self.rebars is None else self.rebars.stiffness_term(self.wall)

    @property
    def theta_max(self) -> float:
        """Rupture rotation θ_max [rad] (``inf``: unreinforced, or a bar that cannot break)."""
        return math.inf if self.rebars is None else self.rebars.rupture_rotation(self.wall)

    @property
    def crushing_rotation(self) -> float:
        """θ_cr [rad]: the toe crushes there under the intact acting bar (``inf``: never;
        0: at the first uplift)."""
        return self.base_reaction.crushing_rotation

    def with_options(self, **changes: object) -> RockingModel:
        """The same wall and bars with some options changed."""
        return replace(self, options=replace(self.options, **changes))  # type: ignore[arg-type]

    @cached_property
    def tie_params(self) -> kp.TieParams:
        """The kernel's constants of the wall's tie levels (docs/model.md §12)."""
        return tie_params(self.wall, tie_levels(self.loads))

    @cached_property
    def params(self) -> kp.KernelParams:
        """The kernel's constants (docs/model.md §1–4), derived once."""
        wall, bars, o = self.wall, self.rebars, self.options
        theta_max = self.theta_max
        alpha = wall.alpha
        if bars is None:
            bar_mode, rupture_energy = kp.BAR_NONE, 0.0
        else:
            bar_mode = kp.BAR_SHARED if bars.position == "centred" else kp.BAR_PER_SIDE
            rupture_energy = 0.0
            if math.isfinite(theta_max):
                rupture_energy = bars.stored_energy(wall, theta_max) / wall.I0
        base = self.base_reaction
        k_bar = self.K
        sin_a, cos_a = math.sin(alpha), math.cos(alpha)
        loads = self.loads
        ties = tie_levels(loads)
        # a tie that carries nothing is no tie: the wall alone, bit for bit
        loaded = bool(loads.top or loads.thrusts or ties)
        pos = side_terms(wall, loads, 1, sin_a, cos_a)
        neg = side_terms(wall, loads, -1, sin_a, cos_a)
        e_wall = self.impact_velocity_ratio
        e_pos, e_neg = self._impact_ratios(e_wall)
        prm = kp.KernelParams(
            g=G,
            p2=wall.p2,
            p=math.sqrt(wall.p2),
            alpha=alpha,
            sin_a=sin_a,
            cos_a=cos_a,
            one_sided=self.mechanism == "one-sided",
            bar_mode=bar_mode,
            k_bar=k_bar,
            theta_max=theta_max,
            rupture_energy=rupture_energy,
            e_impact=e_wall,
            rupture_mode=kp.RUPTURE_ENERGY_TRANSFER
            if o.rupture == "energy-transfer"
            else kp.RUPTURE_VELOCITY_CONTINUOUS,
            collapse_mode={
                "overturning": kp.COLLAPSE_OVERTURNING,
                "end-of-record": kp.COLLAPSE_END_OF_RECORD,
                "first-exceedance": kp.COLLAPSE_FIRST_EXCEEDANCE,
            }[o.collapse],
            method=kp.METHOD_RK4
            if o.fixed_step is not None
            else (kp.METHOD_DOPRI5 if o.method == "dopri5" else kp.METHOD_BS3),
            tolerance=o.tolerance,
            fixed_step=math.inf if o.fixed_step is None else o.fixed_step,
            xi=base.xi,
            kappa_per_k=base.kappa / k_bar if k_bar > 0.0 else 0.0,
            theta_cr=base.crushing_rotation,
            alpha_x=base.alpha_x,
            tan_ax=base.tan_alpha_x,
            tip_bar=math.nan,
            loaded=loaded,
            p2_pos=pos.p2,
            p2_neg=neg.p2,
            a0_pos=pos.a0,
            a0_neg=neg.a0,
            a1_pos=pos.a1,
            a1_neg=neg.a1,
            b0_pos=pos.b0,
            b0_neg=neg.b0,
            b1_pos=pos.b1,
            b1_neg=neg.b1,
            tan_pos=base.tan_alpha_x,
            tan_neg=base.tan_alpha_x,
            e_to_pos=e_pos,
            e_to_neg=e_neg,
            alpha_x_neg=base.alpha_x,
            tip_bar_neg=math.nan,
            tie_on=bool(ties),
            # the bound on the bounces that surely die out is written for the wall alone
            settle_chatter=not loaded,
        )
        if loaded:
            prm = _with_loads(prm, self.mechanism == "one-sided")
            return prm._replace(
                tip_bar=float(loaded_tipping_angle(1.0, k_bar, prm)),
                tip_bar_neg=float(loaded_tipping_angle(-1.0, k_bar, prm)),
            )
        # θ* with the bar intact: the compiled rule itself, so the kernel and this agree
        tip = float(tipping_angle(k_bar, prm))
        return prm._replace(tip_bar=tip, tip_bar_neg=tip)

    def _impact_ratios(self, e_wall: float) -> tuple[float, float]:
        """The velocity ratios of an impact after which the wall rocks on side + and on side −
        (docs/model.md §12): the wall's, times e_c/e_w of the whole body (two-sided), or times
        the product of the two base impacts' (e_c,−/e_w)·(e_c,+/e_w) (one-sided)."""
        carried = self.loads.carried()
        if not carried:
            return e_wall, e_wall
        wall = self.wall
        masses = [(p.force / G, p.distance) for p in carried]
        e_w = impact_velocity_ratio(wall.mass, wall.thickness, wall.height, (), 1)  # 1 − 1.5 sin²α
        e_c = {
            s: impact_velocity_ratio(wall.mass, wall.thickness, wall.height, masses, s)
            for s in (1, -1)
        }
        if self.mechanism == "one-sided":
            both = e_wall * (e_c[-1] / e_w) * (e_c[1] / e_w)
            return both, both
        return e_wall * e_c[1] / e_w, e_wall * e_c[-1] / e_w

    def tail_samples(self, dt: float) -> int:
        """Zero samples appended to a record sampled every dt [s]: the free-vibration tail."""
        return int(math.ceil(self.options.free_vibration_tail / dt - 1e-9))

    def run(
        self,
        acc: NDArray[np.float64],
        dt: float,
        scale: float = 1.0,
        *,
        history: bool = False,
        theta0: float = 0.0,
        omega0: float = 0.0,
    ) -> RockingResult:
        """Integrate the wall under ``scale``·acc (acc in m/s², sampled every dt seconds)."""
        acc = kp.kernel_record(acc)
        if acc.ndim != 1 or acc.size < 2:
            raise ValueError("the record needs at least two samples")
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt must be > 0 s, got {dt!r}")
        prm = self.params
        n_tail = self.tail_samples(dt)
        size = history_length(acc.size + n_tail, dt, prm.collapse_mode) if history else 1
        buf = Buffers(
            np.empty(size), np.empty(size), np.empty(size), np.zeros(2), np.zeros(2, np.int64)
        )
        ground = Ground(acc, float(dt), float(scale), n_tail)
        out = simulate(ground, prm, self.tie_params, float(theta0), float(omega0), history, buf)
        if out.status != kp.STATUS_OK:
            raise NumericalError(
                f"time history at multiplier C = {scale:.6g}: {_STATUS_MESSAGES[out.status]} "
                f"(wall B = {self.wall.thickness:g} m, H = {self.wall.height:g} m, "
                f"{self.mechanism}{'' if self.rebars is None else ', with bars'}); "
                "try another integration tolerance (--rtol) and report it if it persists"
            )
        hist = None
        if history:
            n = out.samples
            theta = buf.theta[:n].copy()
            strain = np.zeros(n)
            if self.rebars is not None:
                strain = self.rebars.strain(self.wall, theta) * buf.bar[:n]
            time = np.arange(n, dtype=np.float64) * dt
            hist = History(time, theta, buf.omega[:n].copy(), strain)
        ruptures = tuple(
            Rupture(float(buf.rupture_time[i]), int(buf.rupture_side[i]))
            for i in range(min(out.ruptures, 2))
        )
        bars = self.rebars
        return RockingResult(
            fate=FATE_NAMES[out.fate],
            decided_time=float(out.decided_time),
            collapse_time=None if math.isnan(out.collapse_time) else float(out.collapse_time),
            max_rotation=float(out.peak),
            max_rotation_ratio=float(out.peak) / self.alpha,
            peak_strain=0.0 if bars is None else bars.strain(self.wall, float(out.peak_with_bar)),
            rupture_strain=None if bars is None else bars.rupture_strain,
            impacts=int(out.impacts),
            ruptures=ruptures,
            final_theta=float(out.final_theta),
            final_omega=float(out.final_omega),
            steps=int(out.steps),
            rejected_steps=int(out.rejected),
            history=hist,
            tie_lost=bool(out.tie_lost),
            tie_plastic_elongations=tuple(
                float(v) for v in out.tie_plastic[: self.tie_params.levels]
            ),
        )


def _with_loads(prm: kp.KernelParams, one_sided: bool) -> kp.KernelParams:
    """The uplift thresholds and tipping angles of each side with the loads (docs/model.md
    §12), from the bracket at θ = 0 without bar force, (a0_s + u·a1_s − s·ξ): rocking starts on
    side + when u < −(a0_+ − ξ)/a1_+ and on side − when u > (−a0_− − ξ)/a1_−; and the angle
    where the static restoring moment of a side without bar, (s·a0_s − ξ)·cos q + b0_s·sin q,
    vanishes."""
    tan_pos = (prm.a0_pos - prm.xi) / prm.a1_pos
    tan_neg = (-prm.a0_neg - prm.xi) / prm.a1_neg
    alpha_pos = math.atan2(prm.a0_pos - prm.xi, -prm.b0_pos)
    alpha_neg = math.atan2(-prm.a0_neg - prm.xi, -prm.b0_neg)
    return prm._replace(
        tan_pos=tan_pos,
        tan_neg=tan_neg,
        tan_ax=tan_pos if one_sided else min(tan_pos, tan_neg),
        alpha_x=alpha_pos,
        alpha_x_neg=alpha_neg,
    )
