"""The seismic action at the wall that the code checks are made against (docs/model.md §5.5).

A limit state's action is its a_g·S, its elastic displacement spectrum and its base motions;
at ground level they are the ground's (NTC 2018 §3.2.3.2.1, eq. 3.2.12), above ground the
floor's (Circolare 2019 §C7.2.3, eq. C8.7.1.12; :mod:`frp_assess.motions.floor`).  The
building is any object with the attributes of :class:`Building` (the project's ``building``
block, :class:`~frp_assess.assess.inputs.BuildingSettings`, or a :class:`FloorPosition`).

Units: ground accelerations in g (a_g·S); records in m/s²; displacements in m; periods in s.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from frp_assess.assess.kinematic_nonlinear import DisplacementSpectrum
from frp_assess.motions import ElasticSpectrum, G, Record
from frp_assess.motions.floor import (
    default_period,
    floor_acceleration,
    floor_displacement_spectrum,
    floor_peak_acceleration,
    ground_displacement_spectrum,
    ground_spectrum_function,
)

# --- the wall's place in the building --------------------------------------------------------


class Building(Protocol):
    """The building around a wall above ground (the project's ``building`` block)."""

    @property
    def height(self) -> float: ...  # H_b [m]
    @property
    def storeys(self) -> int: ...  # n [-]
    @property
    def wall_base(self) -> float: ...  # Z [m]
    @property
    def period(self) -> float | None: ...  # T1 [s]; None: C1·H_b^(3/4)
    @property
    def damping(self) -> float: ...  # ξ1 [-]


@dataclass(frozen=True)
class FloorPosition:
    """A wall whose rocking base is at Z in a building (Circolare 2019 §C7.2.3, first mode).

    For a caller without a project (T1 may be left to C1·H_b^(3/4)); any object with these
    attributes, ``AssessmentInputs.building`` among them, is accepted by
    :func:`kinematic_checks`.
    """

    height: float  #: H_b [m]
    storeys: int  #: n [-]
    wall_base: float  #: Z [m], 0 ≤ Z < H_b
    period: float | None = None  #: T1 [s]; None: C1·H_b^(3/4) (motions.floor.default_period)
    damping: float = 0.05  #: ξ1 [-]


def building_period(building: Building) -> float:
    """T1 [s]: the given one, or C1·H_b^(3/4) (Circolare 2019 eq. C7.3.2)."""
    return default_period(building.height) if building.period is None else building.period


def floor_ratio(spectrum: ElasticSpectrum, building: Building | None) -> float:
    """a_Z,1 / (a_g·S) [-]: the floor's peak acceleration per unit ground intensity
    (Circolare 2019 eq. C7.2.7, first mode); 1 at ground level."""
    if building is None or building.wall_base == 0.0:
        return 1.0
    ground = ground_spectrum_function(spectrum)
    t1 = building_period(building)
    se_t1 = float(ground(np.asarray([t1]), building.damping)[0])
    a_z = floor_peak_acceleration(
        se_t1,
        storeys=building.storeys,
        z_over_h=building.wall_base / building.height,
        building_damping=building.damping,
    )
    return a_z / spectrum.pga_g


@dataclass(frozen=True)
class _CodeDisplacementSpectrum:
    """Sd(T, ξ) [m] of a vectorised spectrum function, one period or many
    (:class:`~frp_assess.assess.kinematic_nonlinear.SampledSpectrum`)."""

    values_at: Callable[[NDArray[np.float64], float], NDArray[np.float64]]

    def __call__(self, period: float, damping: float) -> float:
        return float(self.values_at(np.array([period], dtype=float), damping)[0])

    def at(self, periods: NDArray[np.float64], damping: float) -> NDArray[np.float64]:
        return self.values_at(np.asarray(periods, dtype=float), damping)


def displacement_spectrum(
    spectrum: ElasticSpectrum, building: Building | None
) -> DisplacementSpectrum:
    """Sd(T [s], ξ [-]) [m] at the design intensity: the ground's S_De (NTC 2018 eq. 3.2.12)
    or, above ground, the floor's (Circolare 2019 eq. C8.7.1.12); elementwise, so one period
    or many give the same values."""
    ground = ground_spectrum_function(spectrum)
    if building is None or building.wall_base == 0.0:

        def at_ground(periods: NDArray[np.float64], damping: float) -> NDArray[np.float64]:
            return ground_displacement_spectrum(periods, ground, damping)

        return _CodeDisplacementSpectrum(at_ground)
    t1 = building_period(building)
    z_over_h = building.wall_base / building.height

    def at_floor(periods: NDArray[np.float64], damping: float) -> NDArray[np.float64]:
        return floor_displacement_spectrum(
            periods,
            ground,
            period=t1,
            storeys=building.storeys,
            z_over_h=z_over_h,
            building_damping=building.damping,
            damping=damping,
        )

    return _CodeDisplacementSpectrum(at_floor)


def base_motions(
    records: Sequence[Record], building: Building | None, a_g: float
) -> list[tuple[NDArray[np.float64], float]]:
    """(acceleration [m/s²], dt [s]) at the wall's base under each record at the design
    intensity: the ground record scaled to PGA = a_g·S (the IDA's measure, a_dyn = C·PGA of
    the ground record, docs/model.md §5), then, above ground, filtered into the floor's
    absolute acceleration (motions.floor; the filter is linear, so the order does not matter).

    Args:
        records: the ground records.
        building: the building around a wall above ground (None: ground level).
        a_g: the design intensity a_g·S [g].
    """
    if any(r.pga <= 0.0 for r in records):
        raise ValueError("a record with zero PGA cannot be scaled to the design intensity")
    scaled = [(r.acc * (a_g * G / r.pga), r.dt) for r in records]
    if building is None or building.wall_base == 0.0:
        return scaled
    t1 = building_period(building)
    return [
        (
            floor_acceleration(
                acc,
                dt,
                height_building=building.height,
                storeys=building.storeys,
                wall_base=building.wall_base,
                period=t1,
                damping=building.damping,
            ),
            dt,
        )
        for acc, dt in scaled
    ]


@dataclass(frozen=True)
class LimitStateDemand:
    """One limit state's seismic action at the wall: what its checks are made against."""

    a_g: float  #: a_g·S of the limit state [g]
    sd: DisplacementSpectrum  #: its elastic displacement spectrum (:func:`displacement_spectrum`)
    floor_ratio: float = 1.0  #: a_Z,1/(a_g·S) (:func:`floor_ratio`; 1 at ground level)
    #: the base motions at a_g (:func:`base_motions`); None: no time-history check
    motions: Sequence[tuple[NDArray[np.float64], float]] | None = None


def limit_state_demand(
    spectrum: ElasticSpectrum, building: Building | None, records: Sequence[Record] | None
) -> LimitStateDemand:
    """The action of the limit state whose spectrum is ``spectrum`` (records scaled to its
    a_g·S; None: no time-history check)."""
    a_g = spectrum.pga_g
    return LimitStateDemand(
        a_g,
        displacement_spectrum(spectrum, building),
        floor_ratio(spectrum, building),
        None if records is None else base_motions(records, building, a_g),
    )
