"""The range of a user's table spectrum (T [s], Se [g]): the same for a project's
``seismic.spectrum`` of type table (config.schema), a study's or ``records generate``'s
``table:...`` text (:func:`frp_assess.motions.spectra.table_spectrum`)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from frp_assess.errors import InputError

#: the largest period of a table spectrum [s]
MAX_TABLE_PERIOD = 100.0
#: the largest spectral acceleration of a table spectrum [g]
MAX_TABLE_SE = 20.0


def check_table_range(periods: NDArray[np.float64], accelerations: NDArray[np.float64]) -> None:
    """One InputError line if a table's periods [s] or accelerations [g] (finite, increasing
    periods) leave the range a project file allows."""
    if periods[-1] > MAX_TABLE_PERIOD or accelerations.max() > MAX_TABLE_SE:
        raise InputError(
            f"expected periods of at most {MAX_TABLE_PERIOD:g} s and accelerations of at most "
            f"{MAX_TABLE_SE:g} g, found T up to {periods[-1]:g} s and Se up to "
            f"{accelerations.max():g} g",
            key="spectrum",
        )
