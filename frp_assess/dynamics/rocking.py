"""Time history of one wall under one scaled record: the Python face of the kernel."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from frp_assess.dynamics import kernel as k
from frp_assess.dynamics.rebars import Rebars
from frp_assess.dynamics.restitution import Restitution, velocity_ratio
from frp_assess.dynamics.wall import Mechanism, Wall
from frp_assess.motions.record import G

RuptureRule = Literal["energy-transfer", "velocity-continuous"]
CollapseRule = Literal["end-of-record", "first-exceedance"]

#: Sub-steps are chosen so that h·ω ≤ STEP_FACTOR, ω = p·√(1 + K) the stiffest frequency of
#: the system (the bar-restrained wall near θ = 0).  RK4's phase error per cycle is then
#: ~(h·ω)⁴/120·2π ≈ 1e-4 rad; `tests/validation/test_convergence.py` checks that halving the
#: step changes peak rotations by < 0.1 % and collapse multipliers by < 0.2 %, and
#: `test_reference.py` compares with an independent rtol-1e-11 solution.
STEP_FACTOR = 0.2


@dataclass(frozen=True)
class ModelOptions:
    """Model choices of MODEL.md §3 that the user can change.

    Attributes:
        restitution: ``"energy"`` (|θ'₊| = √r·|θ'₋|, default), ``"velocity"`` (r·|θ'₋|) or a
            velocity ratio in (0, 1].
        rupture: ``"energy-transfer"`` (Eq. 12, default) or ``"velocity-continuous"``.
        collapse: ``"end-of-record"`` (|θ| ≥ α when the input ends, default) or
            ``"first-exceedance"`` (|θ| reaches α at any time).
        free_vibration_tail: zero ground motion appended after the record [s].
        max_step: largest RK4 step [s]; ``None`` chooses it from the system's stiffest
            frequency (and never above the record's dt).
    """

    restitution: Restitution = "energy"
    rupture: RuptureRule = "energy-transfer"
    collapse: CollapseRule = "end-of-record"
    free_vibration_tail: float = 0.0
    max_step: float | None = None

    def __post_init__(self) -> None:
        if self.rupture not in ("energy-transfer", "velocity-continuous"):
            raise ValueError(
                "rupture rule must be 'energy-transfer' or 'velocity-continuous', "
                f"got {self.rupture!r}"
            )
        if self.collapse not in ("end-of-record", "first-exceedance"):
            raise ValueError(
                "collapse rule must be 'end-of-record' or 'first-exceedance', "
                f"got {self.collapse!r}"
            )
        if not (math.isfinite(self.free_vibration_tail) and self.free_vibration_tail >= 0.0):
            raise ValueError(
                f"free-vibration tail must be >= 0 s, got {self.free_vibration_tail!r}"
            )
        if self.max_step is not None and not (math.isfinite(self.max_step) and self.max_step > 0.0):
            raise ValueError(f"max step must be > 0 s, got {self.max_step!r}")


@dataclass(frozen=True)
class History:
    """Time histories at the record's samples (NaN after an early stop at collapse)."""

    time: NDArray[np.float64]  #: [s]
    theta: NDArray[np.float64]  #: rotation θ [rad]
    omega: NDArray[np.float64]  #: angular velocity θ' [rad/s]
    strain: NDArray[np.float64]  #: strain of the acting bar [-] (0 when unreinforced/broken)

    @property
    def computed(self) -> int:
        """Samples computed: all of them, or those up to an early stop at collapse."""
        return int(np.count_nonzero(~np.isnan(self.theta)))


@dataclass(frozen=True)
class Rupture:
    time: float  #: [s]
    side: int  #: +1 or -1: sign of θ when the bar broke


@dataclass(frozen=True)
class RockingResult:
    """What one time history gives."""

    collapsed: bool
    collapse_time: float | None  #: [s]; None without collapse
    max_rotation: float  #: peak |θ| [rad]
    max_rotation_ratio: float  #: peak |θ| / α [-]
    impacts: int
    ruptures: tuple[Rupture, ...]
    final_theta: float  #: [rad]
    final_omega: float  #: [rad/s]
    history: History | None = field(default=None, repr=False)


@dataclass(frozen=True)
class RockingModel:
    """A wall, its mechanism, its rebars (``None``: unreinforced) and the model options.

    Every constant the kernel needs is derived once here, so an IDA can run the same model
    many times at different scales.
    """

    wall: Wall
    mechanism: Mechanism
    rebars: Rebars | None = None
    options: ModelOptions = ModelOptions()

    def __post_init__(self) -> None:
        if self.mechanism not in ("one-sided", "two-sided"):
            raise ValueError(
                f"mechanism must be 'one-sided' or 'two-sided', got {self.mechanism!r}"
            )

    @property
    def impact_velocity_ratio(self) -> float:
        return velocity_ratio(self.options.restitution, self.mechanism, self.wall.alpha)

    @property
    def K(self) -> float:  # noqa: N802 - the paper's symbol
        """K of Eq. 10 [-] (0 when unreinforced)."""
        return 0.0 if self.rebars is None else self.rebars.stiffness_term(self.wall)

    @property
    def theta_max(self) -> float:
        """Rupture rotation θ_max [rad] (``inf``: unreinforced, or a bar that cannot break)."""
        return math.inf if self.rebars is None else self.rebars.rupture_rotation(self.wall)

    def substeps(self, dt: float) -> int:
        """RK4 sub-steps per sample interval of length dt [s]."""
        if self.options.max_step is not None:
            h = self.options.max_step
        else:
            h = STEP_FACTOR / (self.wall.p * math.sqrt(1.0 + self.K))
        return max(1, math.ceil(dt / h - 1e-9))

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
        acc = np.ascontiguousarray(acc, dtype=np.float64)
        if acc.ndim != 1 or acc.size < 2:
            raise ValueError("the record needs at least two samples")
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt must be > 0 s, got {dt!r}")
        n_tail = int(math.ceil(self.options.free_vibration_tail / dt - 1e-9))
        n_total = acc.size + n_tail
        size = n_total if history else 1
        h_theta = np.empty(size)
        h_omega = np.empty(size)
        h_strain = np.empty(size)
        r_time = np.zeros(2)
        r_side = np.zeros(2, dtype=np.int64)
        if self.rebars is None:
            bar_mode, lever_over_h = k.BAR_NONE, 0.0
        else:
            bar_mode = k.BAR_SHARED if self.rebars.position == "centred" else k.BAR_PER_SIDE
            lever_over_h = self.rebars.lever_arm(self.wall) / self.wall.height
        status, collapsed, t_c, peak, impacts, n_rup, th_f, om_f = k.simulate_kernel(
            acc,
            float(dt),
            float(scale),
            n_tail,
            self.substeps(dt),
            G,
            self.wall.p2,
            self.wall.alpha,
            self.mechanism == "one-sided",
            bar_mode,
            self.K,
            self.theta_max,
            lever_over_h,
            self.impact_velocity_ratio,
            k.RUPTURE_ENERGY_TRANSFER
            if self.options.rupture == "energy-transfer"
            else k.RUPTURE_VELOCITY_CONTINUOUS,
            k.COLLAPSE_END_OF_RECORD
            if self.options.collapse == "end-of-record"
            else k.COLLAPSE_FIRST_EXCEEDANCE,
            float(theta0),
            float(omega0),
            history,
            h_theta,
            h_omega,
            h_strain,
            r_time,
            r_side,
        )
        if status != k.STATUS_OK:
            raise RuntimeError("rocking kernel: too many impacts in one sample interval")
        hist = None
        if history:
            hist = History(np.arange(n_total) * dt, h_theta, h_omega, h_strain)
        ruptures = tuple(Rupture(float(r_time[i]), int(r_side[i])) for i in range(min(n_rup, 2)))
        return RockingResult(
            collapsed=bool(collapsed),
            collapse_time=None if math.isnan(t_c) else float(t_c),
            max_rotation=float(peak),
            max_rotation_ratio=float(peak) / self.wall.alpha,
            impacts=int(impacts),
            ruptures=ruptures,
            final_theta=float(th_f),
            final_omega=float(om_f),
            history=hist,
        )
