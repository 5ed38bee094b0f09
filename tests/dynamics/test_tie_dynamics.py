"""The tie (tie-rod) of docs/model.md §12 in the time histories.

References: an independent solver of the same mechanics (tests/dynamics/tie_reference.py: the
statics of the turned block with the tie's force at its anchor, scipy's DOP853 at 1e-12, the
tie's yield, unloading, slackening, re-engagement and loss as scipy event functions); the
energy balance of the block written here from its geometry (input work of the ground's
inertial force on the centroid = kinetic + potential + the tie's elastic energy + F_y·δ_p);
the wall without a tie (the same numbers bit for bit where the tie cannot act).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import ModelOptions, RockingModel, Wall
from frp_assess.dynamics.loads import Loads, Tie, tie_levels
from tests.dynamics.loads_reference import G, LoadedWall
from tests.dynamics.tie_reference import RefTie, tied_rocking

B, H, W_UNIT = 0.4, 6.0, 18e3
H_T = 5.0  #: the tie's height [m]
DT = 0.01
PULSE = -0.3 * G  #: an outward ground acceleration [m/s²], 4.5 a_RM
N_PULSE = 20  #: its samples (0.2 s)


def _model(tie: Tie | None, mechanism: str = "two-sided", **options: object) -> RockingModel:
    opts = ModelOptions(pivot="edge", tolerance=1e-10, **options)  # type: ignore[arg-type]
    loads = Loads(ties=() if tie is None else (tie,))
    return RockingModel(Wall(B, H, W_UNIT), mechanism, None, opts, loads)  # type: ignore[arg-type]


def _pulse(n: int = 400) -> np.ndarray:
    acc = np.zeros(n)
    acc[:N_PULSE] = PULSE
    return acc


def _pulse_ground(t: float) -> float:
    """The kernel's input of :func:`_pulse`: linear between the samples."""
    return float(np.interp(t, [0.0, (N_PULSE - 1) * DT, N_PULSE * DT], [PULSE, PULSE, 0.0]))


_PULSE_BREAKS = ((N_PULSE - 1) * DT, N_PULSE * DT)


def _reference(tie: Tie, duration: float, times: np.ndarray, **kw: object):  # type: ignore[no-untyped-def]
    ref_tie = RefTie(tie.height, tie.stiffness, tie.yield_force, tie.anchorage_force)
    return tied_rocking(LoadedWall(B, H, W_UNIT), ref_tie, duration, times, **kw)  # type: ignore[arg-type]


def test_free_rocking_with_an_elastic_tie_matches_an_independent_solver() -> None:
    """θ(t) over 4 s of free rocking from θ0 = 0.02 rad with an elastic tie (F_y never reached)
    against the reference solver: several impacts on both sides, equal to 1e-6 rad."""
    tie = Tie(H_T, 2e4, 1e12, math.inf)
    res = _model(tie, collapse="end-of-record").run(
        np.zeros(400), DT, 1.0, history=True, theta0=0.02
    )
    assert res.history is not None and res.impacts >= 3
    ref = _reference(tie, 4.0, res.history.time, theta0=0.02)
    assert np.nanmax(np.abs(res.history.theta - ref.theta)) < 1e-6
    assert np.min(res.history.theta) < -1e-4  # it rocked inward too


def test_a_yielding_tie_after_a_pulse_matches_an_independent_solver() -> None:
    """An outward pulse of 0.2 s: the tie yields, unloads, goes slack at δ_p on the way back,
    the wall strikes and rocks on both sides, the tie re-engages beyond δ_p on the next
    outward excursions.  θ(t) over 4 s equal to the reference to 1e-6 rad, δ_p to 1e-6."""
    tie = Tie(H_T, 2e5, 6e3, math.inf)
    res = _model(tie, collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    assert res.history is not None
    ref = _reference(tie, 4.0, res.history.time, ground=_pulse_ground, breaks=_PULSE_BREAKS)
    assert ref.plastic > 0.0 and res.impacts >= 2
    assert np.nanmax(np.abs(res.history.theta - ref.theta)) < 1e-6
    assert res.tie_plastic_elongation == pytest.approx(ref.plastic, rel=1e-6)


def test_the_plastic_elongation_is_kept_after_a_yield() -> None:
    """After the yield the tie is slack until the wall turns to asin(δ_p/h_t) on every later
    outward excursion: below that angle the wall's own energy ½·I0·θ'² + W·((B/2)·sin θ +
    (H/2)·cos θ) (no tie energy, no ground: after the pulse) is the same at every sample of an
    excursion, whether the tie is stretched above it or not; a tie engaged from θ = 0 (δ_p
    lost at the impacts) would take energy there."""
    tie = Tie(H_T, 2e5, 6e3, math.inf)
    res = _model(tie, collapse="end-of-record").run(_pulse(), DT, 1.0, history=True)
    assert res.history is not None
    dp = res.tie_plastic_elongation
    slack_angle = math.asin(dp / H_T)
    th, om = res.history.theta, res.history.omega
    wall = Wall(B, H, W_UNIT)
    energy = 0.5 * wall.I0 * om**2 + wall.weight * (B / 2 * np.sin(th) + H / 2 * np.cos(th))
    start = N_PULSE + 1 + int(np.argmax(th[N_PULSE + 1 :] <= 0.0))  # the first return
    checked = engaged = 0
    i = start
    while i < th.size:
        if th[i] <= 0.0:
            i += 1
            continue
        j = i
        while j < th.size and th[j] > 0.0:
            j += 1
        below = np.arange(i, j)[th[i:j] < slack_angle * (1.0 - 1e-3)]
        if below.size >= 4:
            e = energy[below]
            assert np.max(e) - np.min(e) < 1e-7 * np.max(e)
            checked += 1
            engaged += int(np.max(th[i:j]) > slack_angle)
        i = j
    assert dp > 0.0 and checked >= 2 and engaged >= 1


def test_a_brittle_anchorage_loses_the_tie() -> None:
    """F_a < F_y: the tie is lost when its force reaches F_a (it never yields), and the wall
    falls afterwards ('tie lost then overturning'); θ(t) up to the fall equal to the
    reference with its loss event to 1e-6 rad."""
    tie = Tie(H_T, 2e5, 6e3, 3e3)
    model = _model(tie)
    res = model.run(_pulse(), DT, 1.0, history=True)
    assert res.history is not None
    assert res.tie_lost and res.tie_plastic_elongation == 0.0
    assert res.fate == "fell" and res.failure_mode == "tie lost then overturning"
    ref = _reference(tie, 4.0, res.history.time, ground=_pulse_ground, breaks=_PULSE_BREAKS)
    assert ref.lost
    both = ~np.isnan(ref.theta) & (np.abs(res.history.theta) < 1.0)
    assert np.max(np.abs(res.history.theta[both] - ref.theta[both])) < 1e-6
    # the same record without the anchorage's failure holds the wall
    held = _model(Tie(H_T, 2e5, 6e3, math.inf)).run(_pulse(), DT, 1.0)
    assert not held.collapsed and not held.tie_lost


def test_tension_only_the_tie_does_nothing_while_the_wall_turns_inward() -> None:
    """From θ0 < 0 (inward, two-sided) the wall with a stiff tie moves as the wall without one,
    the same numbers bit for bit, until it first comes back to θ = 0."""
    tied = _model(Tie(H_T, 5e7, 1e6, math.inf), collapse="end-of-record")
    bare = _model(None, collapse="end-of-record")
    a = tied.run(np.zeros(300), DT, 1.0, history=True, theta0=-0.01)
    b = bare.run(np.zeros(300), DT, 1.0, history=True, theta0=-0.01)
    assert a.history is not None and b.history is not None
    inward = int(np.argmax(b.history.theta >= 0.0))
    assert inward > 10
    assert np.array_equal(a.history.theta[:inward], b.history.theta[:inward])
    # afterwards the tie holds the wall on the outward side
    assert np.max(a.history.theta) < np.max(b.history.theta)


@pytest.mark.parametrize("mechanism", ["two-sided", "one-sided"])
def test_a_tie_that_carries_nothing_is_no_tie(mechanism: str) -> None:
    """Zero yield force and an infinite anchorage: the IDA's time histories are the wall's
    without a tie, bit for bit (the builder drops it); a yield force of 1e-9 N/m (the kernel's
    yield, unload and slack events at every excursion) moves θ by less than 1e-9 rad."""
    acc = _pulse()
    bare = _model(None, mechanism, collapse="end-of-record").run(acc, DT, 0.3, history=True)
    zero = Tie(H_T, 5e5, 0.0, math.inf)
    assert tie_levels(Loads(ties=(zero,))) == ()
    same = _model(zero, mechanism, collapse="end-of-record").run(acc, DT, 0.3, history=True)
    assert bare.history is not None and same.history is not None
    assert np.array_equal(bare.history.theta, same.history.theta)
    assert (bare.fate, bare.max_rotation, bare.impacts) == (
        same.fate,
        same.max_rotation,
        same.impacts,
    )
    tiny = _model(Tie(H_T, 5e5, 1e-9, math.inf), mechanism, collapse="end-of-record")
    near = tiny.run(acc, DT, 0.3, history=True)
    assert near.history is not None
    assert np.max(np.abs(near.history.theta - bare.history.theta)) < 1e-9


def test_energy_balance_with_a_yielding_tie() -> None:
    """Under a constant outward ground acceleration (no impact: the tie holds the wall), the
    work of the ground's inertial force −m·ü_g on the centroid's outward displacement
    (B/2)(1 − cos θ) + (H/2)·sin θ equals the kinetic energy ½·I0·θ'², the potential
    W·((B/2)·sin θ + (H/2)·cos θ − H/2), the tie's elastic energy ½·k_t·(h_t·sin θ − δ_p)² and
    its plastic dissipation F_y·δ_p, to 1e-6 of the input work, at every sample once δ_p
    stopped growing (the tie elastic: after its first unloading)."""
    k, fy = 2e5, 6e3
    ug = -0.2 * G
    tie = Tie(H_T, k, fy, math.inf)
    res = _model(tie, collapse="end-of-record").run(np.full(300, ug), DT, 1.0, history=True)
    assert res.history is not None and res.impacts == 0 and not res.collapsed
    th, om = res.history.theta[:-2], res.history.omega[:-2]  # the record's last ramp excluded
    dp = res.tie_plastic_elongation
    assert dp > 0.0
    wall = Wall(B, H, W_UNIT)
    m = wall.mass
    work = -m * ug * (B / 2 * (1 - np.cos(th)) + H / 2 * np.sin(th))
    kinetic = 0.5 * wall.I0 * om**2
    potential = wall.weight * (B / 2 * np.sin(th) + H / 2 * np.cos(th) - H / 2)
    stretch = np.clip(H_T * np.sin(th) - dp, 0.0, fy / k)
    stored = 0.5 * k * stretch**2 + fy * dp
    elastic = H_T * np.sin(th) - dp <= fy / k * (1 - 1e-6)  # at δ_p: not yielding
    turned = np.argmax(np.diff(th) < 0.0) + 1  # after the first unloading
    sel = elastic & (np.arange(th.size) > turned)
    assert sel.sum() > 100
    balance = work[sel] - (kinetic[sel] + potential[sel] + stored[sel])
    assert np.max(np.abs(balance)) < 1e-6 * np.max(np.abs(work))


@pytest.mark.parametrize("capacity", ["first-collapse", "effective"])
def test_the_ida_names_the_loss_of_the_tie(capacity: str) -> None:
    """The compiled IDA search reports 'tie lost then overturning' at the collapse of a wall
    whose brittle tie is lost, as the single time history at that multiplier does; a wall
    with a ductile tie of the same stiffness falls by plain overturning, at a higher C."""
    from frp_assess.dynamics import IdaSettings, ida

    settings = IdaSettings(max_multiplier=20.0, capacity=capacity)  # type: ignore[arg-type]
    brittle = _model(Tie(H_T, 2e5, 6e3, 3e3))
    res = ida(brittle, _pulse(), DT, settings)
    assert res.collapse_multiplier is not None
    assert res.failure_mode == "tie lost then overturning"
    c_first = res.first_collapse if capacity == "effective" else res.collapse_multiplier
    assert c_first is not None
    assert brittle.run(_pulse(), DT, c_first).failure_mode == "tie lost then overturning"
    ductile = ida(_model(Tie(H_T, 2e5, 6e3, math.inf)), _pulse(), DT, settings)
    assert ductile.failure_mode in (None, "overturning")
    assert ductile.capacity_multiplier > res.capacity_multiplier


def test_a_wall_that_loses_its_bars_and_its_tie_names_both() -> None:
    """GFRP centred 0.5 ‰ and a brittle tie (F_a = 3 kN/m < F_y), an outward pulse of 0.4 g:
    the tie is lost, a bar breaks and the wall falls — 'rupture and tie lost then overturning'
    (it read 'rupture then overturning', the tie's loss unnamed); the same wall without the
    tie falls by 'rupture then overturning'."""
    from frp_assess.dynamics.rebars import Rebars
    from frp_assess.dynamics.rocking import failure_mode_of

    bars = Rebars(46e9, 0.015, "centred", 0.5)
    opts = ModelOptions(pivot="edge")
    wall = Wall(B, H, W_UNIT)
    acc = np.zeros(400)
    acc[:N_PULSE] = -0.4 * G
    both = RockingModel(wall, "two-sided", bars, opts, Loads(ties=(Tie(H_T, 2e5, 6e3, 3e3),)))
    res = both.run(acc, DT, 1.0)
    assert res.fate == "fell" and res.ruptures and res.tie_lost
    assert res.failure_mode == "rupture and tie lost then overturning"
    alone = RockingModel(wall, "two-sided", bars, opts).run(acc, DT, 1.0)
    assert alone.fate == "fell" and alone.failure_mode == "rupture then overturning"
    # the toe's crushing is named by the bars alone
    assert failure_mode_of("crushed", True, True) == "rupture then crushing"
