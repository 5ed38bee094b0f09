"""The motion at the wall's base for a wall above the ground floor (docs/model.md §9).

A wall whose rocking base stands at the height Z of a building is shaken by the absolute
acceleration of that floor (first mode only: :func:`frp_assess.motions.floor.floor_acceleration`,
Circolare 2019 §C7.2.3).  The IDA runs the rocking model on the floor motion of each unscaled
ground record; the floor filter is linear, so scaling the ground record by C scales the floor
motion by C, and the IDA's multiplier stays a multiplier of the *ground* record.  What the IDA
reports is therefore put back in ground terms (:func:`in_ground_terms`): a_dyn = C·PGA_ground
and q = a_dyn / a_RM, to be compared with the ground demand a_g·S as for a wall at ground level.

Also here, for the report: the mean 5 % spectrum of the floor motions beside the code's floor
spectrum (Circolare 2019 eqs. C7.2.5-C7.2.9) on one period grid (:func:`floor_spectra`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike

from frp_assess import libm
from frp_assess.assess.inputs import BuildingSettings
from frp_assess.dynamics import IdaResult
from frp_assess.motions import ElasticSpectrum, Record
from frp_assess.motions.compliance import record_spectra
from frp_assess.motions.floor import floor_acceleration, floor_spectrum, ground_spectrum_function

#: the damping ratio of the spectra compared in :func:`floor_spectra` [-]
SPECTRUM_DAMPING = 0.05


def floor_record(record: Record, building: BuildingSettings | None) -> Record:
    """The motion at the wall's base under ``record``: the record itself when the wall stands
    at ground level (``building`` None), else the floor's absolute acceleration at Z [m/s²]
    (same name, dt and length; :func:`~frp_assess.motions.floor.floor_acceleration`)."""
    if building is None:
        return record
    acc = floor_acceleration(
        record.acc,
        record.dt,
        height_building=building.height,
        storeys=building.storeys,
        wall_base=building.wall_base,
        period=building.period,
        damping=building.damping,
    )
    source = f"{record.source}; floor motion at Z = {building.wall_base:g} m".lstrip("; ")
    return Record(record.name, record.dt, acc, source, dict(record.meta))


def in_ground_terms(result: IdaResult, ground_pga: float) -> IdaResult:
    """An IDA run on a floor motion, restated in terms of its ground record.

    The multipliers (C₀ = a_RM / PGA_floor, the collapse and survivor multipliers, the
    curve) multiply the ground record as well as the floor motion (the floor filter is
    linear), so they stay; ``pga`` becomes the ground record's PGA [m/s²], a_dyn = C·PGA_ground
    [m/s²] and q = a_dyn / a_RM [-], with a_RM = C₀·PGA_floor (:func:`frp_assess.dynamics.ida`).
    """
    if not (math.isfinite(ground_pga) and ground_pga > 0.0):
        raise ValueError(f"ground PGA must be > 0, got {ground_pga!r}")
    a_rm = result.c0 * result.pga
    c = result.collapse_multiplier
    a_dyn = None if c is None else c * ground_pga
    q = None if a_dyn is None else a_dyn / a_rm
    return replace(result, pga=ground_pga, a_dyn=a_dyn, q=q)


@dataclass(frozen=True)
class FloorSpectra:
    """The floor spectra of a run, accelerations in g, on one period grid.

    Attributes:
        periods: T [s].
        records: 5 % pseudo-acceleration spectrum of each record's floor motion [g],
            one tuple per record (unscaled, as the IDA receives them).
        mean: their mean [g].
        code: the code's floor spectrum S_eZ(T, 5 %) at Z of the target ground spectrum
            (Circolare 2019 §C7.2.3, eqs. C7.2.5-C7.2.9, first mode) [g].
        ground: the target ground spectrum Se(T, 5 %) [g], for comparison.
        floor_pga: PGA of each record's floor motion [g].
        ground_pga: PGA of each ground record [g].
    """

    periods: tuple[float, ...]
    records: tuple[tuple[float, ...], ...]
    mean: tuple[float, ...]
    code: tuple[float, ...]
    ground: tuple[float, ...]
    floor_pga: tuple[float, ...]
    ground_pga: tuple[float, ...]


def default_periods(building: BuildingSettings) -> np.ndarray:
    """A log grid over 0.02-4 s (at least 2.5·T1) with T1 and the plateau ends 0.8·T1, 1.1·T1
    of the code's floor spectrum [s]."""
    t1 = building.period
    grid = libm.geomspace(0.02, max(4.0, 2.5 * t1), 60)
    return np.unique(np.round(np.concatenate([grid, [0.8 * t1, t1, 1.1 * t1]]), 12))


def floor_spectra(
    records: Sequence[Record],
    spectrum: ElasticSpectrum,
    building: BuildingSettings,
    periods: ArrayLike | None = None,
    floors: Sequence[Record] | None = None,
) -> FloorSpectra:
    """The 5 % spectra of the floor motions of ``records`` and the code's floor spectrum.

    Args:
        records: the ground records of the run (as scaled for the run) [m/s²].
        spectrum: the target ground spectrum of the site.
        building: where the wall stands.
        periods: T [s] (default :func:`default_periods`).
        floors: the floor motions of ``records`` when already computed (the run's
            :attr:`~frp_assess.assess.runner.IdaRunner.motions`), else filtered here.
    """
    if not records:
        raise ValueError("no records")
    T = default_periods(building) if periods is None else np.asarray(periods, dtype=float)
    if floors is None:
        floors = [floor_record(r, building) for r in records]
    elif len(floors) != len(records):
        raise ValueError("one floor motion per record")
    each = record_spectra(floors, T, SPECTRUM_DAMPING)
    ground = ground_spectrum_function(spectrum)
    code = floor_spectrum(
        T,
        ground,
        period=building.period,
        storeys=building.storeys,
        z_over_h=building.z_over_h,
        building_damping=building.damping,
        damping=SPECTRUM_DAMPING,
    )
    return FloorSpectra(
        periods=tuple(float(t) for t in T),
        records=tuple(tuple(float(v) for v in row) for row in each),
        mean=tuple(float(v) for v in each.mean(axis=0)),
        code=tuple(float(v) for v in code),
        ground=tuple(float(v) for v in ground(T, SPECTRUM_DAMPING)),
        floor_pga=tuple(f.pga_g for f in floors),
        ground_pga=tuple(r.pga_g for r in records),
    )
