"""Several tie levels in the time histories (docs/model.md §12): ties at different heights, or
yielding and losing their anchorage at different elongations, each with its own state and
plastic elongation.

References: the independent solver of tests/dynamics/tie_reference.py (scipy's DOP853 at 1e-12,
each tie's yield, unloading, slackening, re-engagement and loss its own event function); the
energy balance of the block written here from its geometry; the one-level kernel (a second
level that acts as one with the first is summed into it).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import ModelOptions, RockingModel, Wall
from frp_assess.dynamics.loads import Loads, Tie, tie_levels
from tests.dynamics.loads_reference import G, LoadedWall
from tests.dynamics.test_tie_dynamics import DT, N_PULSE, _pulse, _pulse_ground
from tests.dynamics.tie_reference import RefTie, tied_rocking
from tests.dynamics.tolerance_check import assert_capacity_holds, steel_tie

B, H, W_UNIT = 0.4, 6.0, 18e3
#: a yielding tie at the first floor and a stiffer one at the eaves that stays elastic
LOW = Tie(3.0, 2e5, 4e3, math.inf)
HIGH = Tie(5.8, 1.5e5, 2e5, math.inf)


def _model(ties: tuple[Tie, ...], mechanism: str = "two-sided", **options: object) -> RockingModel:
    opts = ModelOptions(**{"pivot": "edge", "tolerance": 1e-10, **options})  # type: ignore[arg-type]
    return RockingModel(Wall(B, H, W_UNIT), mechanism, None, opts, Loads(ties=ties))  # type: ignore[arg-type]


def _reference(ties: tuple[Tie, ...], times: np.ndarray):  # type: ignore[no-untyped-def]
    refs = [RefTie(t.height, t.stiffness, t.yield_force, t.anchorage_force) for t in ties]
    return tied_rocking(
        LoadedWall(B, H, W_UNIT), refs, 4.0, times, ground=_pulse_ground,
        breaks=((N_PULSE - 1) * DT, N_PULSE * DT),
    )  # fmt: skip


def test_two_levels_one_yielding_match_an_independent_solver() -> None:
    """A tie at 3.0 m that yields and one at 5.8 m that stays elastic, an outward pulse of
    0.2 s: the low tie yields, both hold, the low one unloads and goes slack at its δ_p on
    the way back, the wall strikes and rocks on both sides.  θ(t) over 4 s equal to the
    reference to 1e-6 rad, each level's δ_p to 1e-6."""
    res = _model((LOW, HIGH), collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    assert res.history is not None
    ref = _reference((LOW, HIGH), res.history.time)
    assert ref.plastic_by_tie[0] > 0.0 and ref.plastic_by_tie[1] == 0.0 and res.impacts >= 2
    assert np.nanmax(np.abs(res.history.theta - ref.theta)) < 1e-6
    assert res.tie_plastic_elongations == pytest.approx(ref.plastic_by_tie, rel=1e-6, abs=1e-12)


def test_a_brittle_level_is_lost_and_the_other_holds() -> None:
    """The tie at 5.8 m with a brittle anchorage (F_a = 2 kN/m, below its F_y): it is lost on
    the first excursion and the low tie alone holds the wall afterwards; θ(t) equal to the
    reference with its loss event to 1e-6 rad; the wall stands (no 'tie lost then
    overturning')."""
    high = Tie(5.8, 1.5e5, 2e5, 2e3)
    res = _model((LOW, high), collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    assert res.history is not None
    ref = _reference((LOW, high), res.history.time)
    assert ref.lost and res.tie_lost and not res.collapsed
    assert np.nanmax(np.abs(res.history.theta - ref.theta)) < 1e-6


def test_levels_that_act_as_one_are_summed() -> None:
    """Two ties at the same height with the same yield and loss elongations are one level (their
    k_t, F_y, F_a/i_t added), the same numbers bit for bit as the summed tie; a third tie at
    another height is a second level."""
    a = Tie(4.0, 1e5, 2e3, math.inf)
    b = Tie(4.0, 3e5, 6e3, math.inf)  # the same F_y/k_t
    summed = Tie(4.0, 4e5, 8e3, math.inf)
    assert tie_levels(Loads(ties=(a, b))) == (summed,)
    assert tie_levels(Loads(ties=(a, HIGH, b))) == (summed, HIGH)
    one = _model((a, b), collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    ref = _model((summed,), collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    assert one.history is not None and ref.history is not None
    assert np.array_equal(one.history.theta, ref.history.theta)


def test_more_levels_than_the_kernel_holds_are_refused() -> None:
    """Ties at three heights are three levels: refused with one line naming the rule."""
    ties = tuple(Tie(h, 1e5, 2e3, math.inf) for h in (2.0, 3.0, 4.0))
    with pytest.raises(ValueError, match="at most 2 tie levels; .*found 3 levels"):
        tie_levels(Loads(ties=ties))


def test_energy_balance_with_two_yielding_levels() -> None:
    """Under a constant outward ground acceleration (no impact: the ties hold the wall), the
    work of −m·ü_g on the centroid's outward displacement (B/2)(1 − cos θ) + (H/2)·sin θ equals
    the kinetic energy ½·I0·θ'², the potential W·((B/2)·sin θ + (H/2)·cos θ − H/2), and for
    each tie its elastic energy ½·k_t·(h_t·sin θ − δ_p)² and plastic dissipation F_y·δ_p, to
    1e-6 of the input work, at every sample once both δ_p stopped growing (after the first
    unloading)."""
    low, high = Tie(3.0, 2e5, 4e3, math.inf), Tie(5.0, 1e5, 3e3, math.inf)
    ug = -0.2 * G
    res = _model((low, high), collapse="end-of-record").run(np.full(300, ug), DT, 1.0, history=True)
    assert res.history is not None and res.impacts == 0 and not res.collapsed
    th, om = res.history.theta[:-2], res.history.omega[:-2]  # the record's last ramp excluded
    dps = res.tie_plastic_elongations
    assert min(dps) > 0.0  # both yielded
    wall = Wall(B, H, W_UNIT)
    work = -wall.mass * ug * (B / 2 * (1 - np.cos(th)) + H / 2 * np.sin(th))
    kinetic = 0.5 * wall.I0 * om**2
    potential = wall.weight * (B / 2 * np.sin(th) + H / 2 * np.cos(th) - H / 2)
    stored = np.zeros_like(th)
    elastic = np.ones(th.shape, dtype=bool)
    for tie, dp in zip((low, high), dps, strict=True):
        ey = tie.yield_force / tie.stiffness
        stretch = np.clip(tie.height * np.sin(th) - dp, 0.0, ey)
        stored += 0.5 * tie.stiffness * stretch**2 + tie.yield_force * dp
        elastic &= tie.height * np.sin(th) - dp <= ey * (1 - 1e-6)
    turned = np.argmax(np.diff(th) < 0.0) + 1
    sel = elastic & (np.arange(th.size) > turned)
    assert sel.sum() > 100
    balance = work[sel] - (kinetic[sel] + potential[sel] + stored[sel])
    assert np.max(np.abs(balance)) < 1e-6 * np.max(np.abs(work))


@pytest.mark.parametrize("capacity", ["first-collapse", "effective"])
def test_two_levels_capacity_does_not_move_with_the_integration_tolerance(capacity: str) -> None:
    """A façade with a floor tie (Ø20 S235 every 3 m at 3.0 m, yielding) and an eaves tie (Ø16
    every 3 m at 5.8 m, its anchorage lost at 8 kN/m): a 100× tighter integration tolerance
    (1e-6 → 1e-8) moves no record's capacity by more than the IDA's bisection tolerance
    (0.5 %), with either capacity rule."""
    ties = (steel_tie(3.0, 20.0, math.inf), steel_tie(5.8, 16.0, 8e3))
    assert_capacity_holds(lambda tol: _model(ties, "one-sided", tolerance=tol), capacity, seeds=2)
