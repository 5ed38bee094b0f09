"""What the tests of a loaded or tied wall's capacity under a tighter integration tolerance
share (docs/model.md §4.2, §12): a number of the wall and the record, not of a numerical
setting."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from frp_assess.dynamics import IdaSettings, RockingModel, ida
from frp_assess.dynamics.loads import Tie
from tests.conftest import synthetic_record

#: the tolerances compared: the default and 100× tighter [-]
TOLERANCES = (1e-6, 1e-8)


def steel_tie(height: float, diameter: float, anchorage: float) -> Tie:
    """Round S235 ties of ``diameter`` [mm] every 3 m, 8 m long, per metre of wall:
    k_t = E_s·A_s/(L_t·i_t) with E_s = 210 GPa, F_y = A_s·f_y/i_t with f_y = 235 MPa (written
    here, not taken from rules/tie_rods.py); ``anchorage`` F_a/i_t [N/m] (inf: never lost)."""
    area = math.pi * (diameter / 2e3) ** 2
    return Tie(height, 210e9 * area / (8.0 * 3.0), 235e6 * area / 3.0, anchorage)


def assert_capacity_holds(
    model_at: Callable[[float], RockingModel], capacity: str, seeds: int
) -> None:
    """The IDA capacity of ``model_at(tolerance)`` under ``seeds`` synthetic records (8 s)
    moves by no more than the IDA's bisection tolerance (0.5 %, the resolution the capacity is
    stated at) between the :data:`TOLERANCES`, with the capacity rule ``capacity``."""
    settings = IdaSettings(capacity=capacity)  # type: ignore[arg-type]
    for seed in range(seeds):
        acc = synthetic_record(seed, duration=8.0)
        c = [ida(model_at(tol), acc, 0.01, settings).capacity_multiplier for tol in TOLERANCES]
        assert c[0] is not None and c[1] == pytest.approx(c[0], rel=0.005), (seed, c)
