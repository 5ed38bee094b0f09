"""The ground-motion record as the numerics see it."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from frp_assess.rules.constants import G as G  # re-export: the records' g [m/s²]


@dataclass(frozen=True, eq=False)
class Record:
    """A uniformly sampled ground acceleration history.

    Attributes:
        name: short label (file stem, or ``"art-01"`` for generated records).
        dt: sampling interval [s].
        acc: ground acceleration [m/s²], one value per sample, first sample at t = 0.
        source: where it came from (file path, or generator and seed), for reports.
    """

    name: str
    dt: float
    acc: NDArray[np.float64]
    source: str = ""
    meta: dict[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        acc = np.ascontiguousarray(self.acc, dtype=np.float64)
        acc.setflags(write=False)
        object.__setattr__(self, "acc", acc)

    @property
    def npts(self) -> int:
        return int(self.acc.size)

    @property
    def duration(self) -> float:
        """Duration [s] from the first to the last sample."""
        return (self.npts - 1) * self.dt

    @property
    def time(self) -> NDArray[np.float64]:
        return np.arange(self.npts, dtype=np.float64) * self.dt

    @property
    def pga(self) -> float:
        """Peak ground acceleration [m/s²]."""
        return float(np.max(np.abs(self.acc))) if self.npts else 0.0

    @property
    def pga_g(self) -> float:
        """Peak ground acceleration [g]."""
        return self.pga / G


def kernel_record(acc: ArrayLike) -> NDArray[np.float64]:
    """Samples as every compiled kernel takes them (the rocking driver and the IDA search,
    the response spectra, the floor filter): float64, C-contiguous and read-only.

    numba compiles one machine-code version per argument type, and a writable and a
    read-only array are two types: the search (9 CPU-s to compile), the driver (3 CPU-s) and
    the spectra (2 CPU-s) were compiled twice, once for the records of a project (read-only)
    and once for arrays made in memory.  Every caller goes through here, so there is one
    version of each.  The array passed in is not changed (a read-only view of it, or of a
    converted copy)."""
    view = np.ascontiguousarray(acc, dtype=np.float64).view()
    view.flags.writeable = False
    return view
