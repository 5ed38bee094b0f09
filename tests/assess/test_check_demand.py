"""The code displacement spectra of the checks give Sd at many periods in one call
(frp_assess.assess.check_demand): the same values, bit for bit, as one period at a time, at
ground level and on a floor, for the NTC, EC8 and table spectra; and the displacement demand
of Circolare 2019 §C8.7.1.2.1.8 is the same either way.

Reference: the scalar path (one period per call), the way every check computed it before."""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.assess.check_demand import FloorPosition, displacement_spectrum
from frp_assess.assess.kinematic_nonlinear import SampledSpectrum, displacement_demand
from frp_assess.motions import ElasticSpectrum
from frp_assess.motions.spectra import table_spectrum

SPECTRA = [
    ElasticSpectrum("ec8", "ec8", 0.3, 0.15, 0.5, 2.0),
    ElasticSpectrum("ntc", "ec8", 0.35, 0.2, 0.6, 2.4, plateau_factor=2.45),
    table_spectrum([0.0, 0.2, 0.6, 2.0, 4.0], [0.3, 0.75, 0.75, 0.2, 0.05], name="table"),
]
FLOORS = [None, FloorPosition(height=12.0, storeys=4, wall_base=6.0)]


@pytest.mark.parametrize("floor", FLOORS, ids=["ground", "floor"])
@pytest.mark.parametrize("spectrum", SPECTRA, ids=lambda s: s.name)
def test_many_periods_equal_one_at_a_time(spectrum: ElasticSpectrum, floor: FloorPosition | None):
    sd = displacement_spectrum(spectrum, floor)
    assert isinstance(sd, SampledSpectrum)
    periods = np.concatenate([np.linspace(0.0, 4.0, 401), [0.15, 0.2, 0.5, 0.6, 2.0, 2.4]])
    for damping in (0.05, 0.08, 0.10):
        many = sd.at(periods, damping)
        one = [sd(float(T), damping) for T in periods]
        assert many.tolist() == one  # exact


@pytest.mark.parametrize("floor", FLOORS, ids=["ground", "floor"])
def test_the_demand_is_the_same_sampled_or_one_at_a_time(floor: FloorPosition | None):
    sd = displacement_spectrum(SPECTRA[1], floor)

    def scalar_only(period: float, damping: float) -> float:
        return sd(period, damping)

    for period in (0.3, 1.1, 2.9):
        assert displacement_demand(sd, period, 0.08) == displacement_demand(
            scalar_only, period, 0.08
        )
