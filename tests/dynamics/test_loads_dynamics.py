"""The rocking wall with the loads it carries in the kernel (docs/model.md §12).

References: an independent solution of the same equation (tests/dynamics/loads_reference.py:
the statics of the turned block and scipy's DOP853 at 1e-12, its own impact rule from the
angular momentum of the body); the Circolare's α₀ of simple overturning with the loads
(rules/wall_loads.py, checked by hand in tests/rules/test_wall_loads.py); Housner's impact
ratio 1 − 1.5·sin²α without loads; conservation of the mechanical energy between impacts.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import ModelOptions, RockingModel, Wall
from frp_assess.dynamics.kernel.fate import loaded_energy
from frp_assess.dynamics.loads import Loads
from frp_assess.rules.wall_loads import Thrust, TopLoad, uplift_multiplier
from tests.dynamics.loads_reference import G, LoadedWall, free_rocking
from tests.dynamics.tolerance_check import assert_capacity_holds, steel_tie

B, H, W_UNIT = 0.4, 6.0, 18e3
TOP = ((10e3, 0.3, True), (4e3, 0.2, False))
THRUSTS = ((1e3, 5.5),)
DT = 0.002


def _model(
    mechanism: str = "two-sided", top=TOP, thrusts=THRUSTS, **options: object
) -> RockingModel:
    loads = Loads(
        top=tuple(TopLoad(p, d, c) for p, d, c in top),
        thrusts=tuple(Thrust(f, h) for f, h in thrusts),
    )
    opts = ModelOptions(pivot="edge", collapse="end-of-record", tolerance=1e-10, **options)  # type: ignore[arg-type]
    return RockingModel(Wall(B, H, W_UNIT), mechanism, None, opts, loads)  # type: ignore[arg-type]


def test_uplift_on_each_side_is_the_circolare_alpha0_with_the_loads() -> None:
    """a_RM,± of the kernel = g·α of rules.wall_loads (the Circolare's eq. C8.7.1.1 without a
    tie, outward; the same moments about the inner corner, inward)."""
    prm = _model().params
    weight = W_UNIT * B * H
    top = [TopLoad(p, d, c) for p, d, c in TOP]
    thrusts = [Thrust(f, h) for f, h in THRUSTS]
    assert prm.tan_pos == pytest.approx(uplift_multiplier(weight, B, H, top, thrusts, 1), rel=1e-12)
    assert prm.tan_neg == pytest.approx(
        uplift_multiplier(weight, B, H, top, thrusts, -1), rel=1e-12
    )
    assert _model().a_rm == pytest.approx(G * min(prm.tan_pos, prm.tan_neg), rel=1e-12)
    assert _model("one-sided").a_rm == pytest.approx(G * prm.tan_pos, rel=1e-12)


@pytest.mark.parametrize("theta0", [0.02, -0.006])
def test_free_rocking_with_a_carried_floor_and_a_thrust_matches_an_independent_solver(
    theta0: float,
) -> None:
    """θ(t) over 4 s of free rocking (several impacts, both sides) against the reference solver:
    equal to 1e-6 rad (the kernel at a tolerance of 1e-10)."""
    model = _model()
    n = int(4.0 / DT)
    res = model.run(np.zeros(n), DT, 1.0, history=True, theta0=theta0)
    assert res.history is not None and res.impacts >= 3
    ref = free_rocking(
        LoadedWall(B, H, W_UNIT, top=TOP, thrusts=THRUSTS), theta0, 4.0, res.history.time
    )
    assert np.nanmax(np.abs(res.history.theta - ref)) < 1e-6


def test_energy_is_conserved_between_impacts() -> None:
    """ε = ½·θ'²/p²_s + v_s(|θ|) stays constant while the wall rocks on one side (no impact,
    no ground motion): to 1e-9 of the energy."""
    model = _model()
    prm = model.params
    n = int(0.5 / DT)
    res = model.run(np.zeros(n), DT, 1.0, history=True, theta0=0.03)
    assert res.history is not None
    th, om = res.history.theta, res.history.omega
    first = int(np.argmax(th <= 0.0)) if np.any(th <= 0.0) else th.size
    assert first > 10
    e = [
        loaded_energy(float(t), float(w), 1.0, 0.0, prm)
        for t, w in zip(th[:first], om[:first], strict=True)
    ]
    assert max(e) - min(e) < 1e-9 * abs(e[0])


def test_impact_ratio_without_a_carried_mass_is_housners() -> None:
    """A restrained load moves no mass: the impacts keep the wall's 1 − 1.5·sin²α."""
    model = _model(top=((10e3, 0.3, False),), thrusts=())
    alpha = math.atan(B / H)
    assert model.params.e_to_pos == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2, rel=1e-12)
    assert model.params.e_to_neg == model.params.e_to_pos


def test_uplift_with_the_stress_block_under_the_weight_and_the_loads() -> None:
    """§12 with `pivot: crushing`: a_RM,+ = g·(W·B/2 + Σ P·d − N₀·x₀/2 − Σ F·h)/(W·H/2 + Σ P_c·H),
    N₀ = W + Σ P, x₀ = N₀/(0.85·f_d) (NTC 2018 §7.8.2.2.1), f_d = 2 MPa: x₀ =
    (43.2 + 14) kN/m / (0.85 × 2000 kPa) = 0.033647 m."""
    loads = Loads(
        top=tuple(TopLoad(p, d, c) for p, d, c in TOP),
        thrusts=tuple(Thrust(f, h) for f, h in THRUSTS),
    )
    wall = Wall(B, H, W_UNIT, 2e6)
    model = RockingModel(wall, "two-sided", None, ModelOptions(), loads)
    weight = W_UNIT * B * H
    n0 = weight + 14e3
    x0 = n0 / (0.85 * 2e6)
    assert x0 == pytest.approx(0.0336471, rel=1e-5)
    top = [TopLoad(p, d, c) for p, d, c in TOP]
    thrusts = [Thrust(f, h) for f, h in THRUSTS]
    for side, tan in ((1, model.params.tan_pos), (-1, model.params.tan_neg)):
        expected = uplift_multiplier(weight, B, H, top, thrusts, side, n0 * x0 / 2)
        assert tan == pytest.approx(expected, rel=1e-12)


def test_a_rupture_hands_the_bar_energy_to_the_whole_body() -> None:
    """Eq. 12 with a carried floor: ½·I_s·θ'₊² = ½·I_s·θ'₋² + U_r(θ_max), I_s the inertia of the
    wall and the carried mass about the pivot (docs/model.md §12), not I₀ alone."""
    from frp_assess.dynamics.kernel.jumps import rupture
    from frp_assess.dynamics.loads import inertia
    from frp_assess.dynamics.rebars import Rebars

    loads = Loads(top=(TopLoad(10e3, 0.3, True),))
    wall = Wall(B, H, W_UNIT)
    bars = Rebars(50e9, 0.02, "centred", 1.0)
    model = RockingModel(wall, "one-sided", bars, ModelOptions(pivot="edge"), loads)
    prm = model.params
    u_r = bars.stored_energy(wall, model.theta_max)  # [J/m]
    omega, _, _ = rupture(0.3, 1.0, True, True, prm)
    i_s = inertia(wall, loads, 1)
    assert 0.5 * i_s * omega**2 == pytest.approx(0.5 * i_s * 0.3**2 + u_r, rel=1e-12)


def _facade(loads: Loads, tolerance: float) -> RockingModel:
    """The façade of the tolerance tests (f_d = 2 MPa: the crushing pivot), one-sided."""
    return RockingModel(
        Wall(B, H, W_UNIT, 2e6), "one-sided", None, ModelOptions(tolerance=tolerance), loads
    )


@pytest.mark.parametrize("capacity", ["first-collapse", "effective"])
def test_a_loaded_walls_capacity_does_not_move_with_the_integration_tolerance(
    capacity: str,
) -> None:
    """The capacity of a façade with a carried floor, a restrained load and a thrust (crushing
    pivot, one-sided) under four synthetic records: a 100× tighter integration tolerance
    (1e-6 → 1e-8) moves no record's capacity by more than the IDA's bisection tolerance
    (0.5 %, the resolution the capacity is stated at) — a number of the wall and the record,
    not of a numerical setting."""
    loads = Loads(
        top=tuple(TopLoad(p, d, c) for p, d, c in TOP),
        thrusts=tuple(Thrust(f, h) for f, h in THRUSTS),
    )
    assert_capacity_holds(lambda tol: _facade(loads, tol), capacity, seeds=4)


@pytest.mark.parametrize(
    "anchorage", [pytest.param(13.3e3, id="brittle"), pytest.param(math.inf, id="yielding")]
)
@pytest.mark.parametrize("capacity", ["first-collapse", "effective"])
def test_a_tied_walls_capacity_does_not_move_with_the_integration_tolerance(
    capacity: str, anchorage: float
) -> None:
    """The same façade held by a steel tie at 5.5 m (Ø20 S235 every 3 m, 8 m long: k_t =
    E_s·A_s/(L_t·i_t) = 2.75 MN/m per m, F_y = 24.6 kN/m; its anchorage lost at 13.3 kN/m, or
    never): its yield, unloading, slack and loss are events located inside the step, so a
    100× tighter integration tolerance (1e-6 → 1e-8) moves no record's capacity by more than
    the IDA's bisection tolerance (0.5 %), with either capacity rule."""
    tie = steel_tie(5.5, 20.0, anchorage)
    loads = Loads(top=tuple(TopLoad(p, d, c) for p, d, c in TOP), ties=(tie,))
    assert_capacity_holds(lambda tol: _facade(loads, tol), capacity, seeds=3)


def test_a_yielding_tie_is_not_stopped_at_a_sample_by_round_off() -> None:
    """The time history where a yielding tie's wall was stopped at a record sample: after a
    step stretched to the sample, x + (dt − x) fell an ulp short of dt and the driver took a
    1.7e-18 s step on the sliver; its dense output was round-off, showed a spurious maximum,
    and the tie "unloaded" there with θ' set to 0 (seed 0 at C = 17.25: peak 0.2147 rad at
    tolerance 1e-6 against 0.2864 rad from 1e-7 on).  The reference is the same equation at
    a 1000× tighter tolerance (convergence): the peak and the tie's plastic elongation agree
    to 1e-5."""
    from tests.conftest import synthetic_record

    loads = Loads(
        top=tuple(TopLoad(p, d, c) for p, d, c in TOP), ties=(steel_tie(5.5, 20.0, math.inf),)
    )
    acc = synthetic_record(0, duration=8.0)
    default, tight = (_facade(loads, tol).run(acc, 0.01, 17.25) for tol in (1e-6, 1e-9))
    assert default.fate == tight.fate == "at rest"
    assert default.max_rotation == pytest.approx(tight.max_rotation, rel=1e-5)
    assert default.tie_plastic_elongation == pytest.approx(tight.tie_plastic_elongation, rel=1e-5)
