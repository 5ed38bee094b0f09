"""The code checks with the loads a wall carries (docs/model.md §12 "Code checks"), against
numbers computed by hand from the Circolare's formulas:

* α₀ = [Σ P_k·δ_Py − Σ F_k·δ_F + L_i] / Σ (P_k + Q_k)·δ_PQx (Circolare 2019 eq. C8.7.1.1),
  a unit virtual rotation about the outer base corner: δ_Py the horizontal lever of a weight,
  δ_F the height of a thrust, δ_PQx the height of a mass (H/2 for the wall, H for a floor);
  L_i = min(F_y, F_a/i_t)·h_t for a tie at its capacity;
* e* = (Σ P·δ)²/(Σ P · Σ P·δ²) (eq. C8.7.1.5) with the carried loads;
* a0* = α₀·g/(e*·FC) (eq. C8.7.1.3).

The wall: B = 0.4 m, H = 6 m, w = 18 kN/m³, so W = 18·0.4·6 = 43.2 kN/m, W·B/2 = 8.64 and
W·H/2 = 129.6 kNm/m; the edge pivot (x₀ = 0) unless said.  The floor: P = 10 kN/m at
d = 0.3 m, carried: P·d = 3.0, P·H = 60.0 kNm/m.  The thrust: F = 1 kN/m at h = 5.5 m,
F·h = 5.5 kNm/m.  The tie: Ø20 (A_s = π·20²/4 = 314.159 mm²), S235, every 3 m, 8 m long,
at h_t = 5.8 m: F_y = 314.159e-6·235e6/3 = 24 609.14 N/m, L_i = 24.60914·5.8 = 142.73303 kNm/m.
The checks are called directly: the kernel does not read the loads yet (issue 40).
"""

from __future__ import annotations

import math

import pytest

from frp_assess.assess.code_check import simple_overturning_check
from frp_assess.assess.inputs import CodeCheckSettings
from frp_assess.assess.kinematic_capacity import CapacityCurve
from frp_assess.assess.kinematic_checks import (
    case_checks,
    displacement_spectrum,
    linear_check,
    model_capacity_curve,
)
from frp_assess.assess.kinematic_nonlinear import limit_state_check
from frp_assess.assess.load_inputs import LoadsInput, ThrustInput, TieInput, TopLoadInput
from frp_assess.assess.loaded_capacity import LoadedCapacityCurve
from frp_assess.assess.loaded_overturning import loaded_alpha0, loaded_e_star, overturning_result
from frp_assess.assess.wall_model import WallInput, rocking_model
from frp_assess.dynamics import ModelOptions
from frp_assess.motions import ElasticSpectrum

G = 9.80665
FC_LC1 = 1.35
EDGE = ModelOptions(pivot="edge")
WALL = WallInput(0.4, 6.0, 18.0, 1.5)  # f_d = 1.5 MPa: used by the crushing pivot only
FLOOR = TopLoadInput("floor", 10.0, 0.3, True)
ROOF = TopLoadInput("roof", 4.0, 0.2, False)
THRUST = ThrustInput("rafters", 1.0, 5.5)
TIE = TieInput("catena", 5.8, math.pi * 20.0**2 / 4.0, 3.0, 8.0, diameter=20.0)
#: anchorage 30 kN per tie every 3 m: F_a/i_t = 10 kN/m < F_y = 24.609 kN/m, brittle
BRITTLE = TieInput("catena", 5.8, math.pi * 20.0**2 / 4.0, 3.0, 8.0, anchorage=30.0)
SPECTRUM = ElasticSpectrum("test", "ec8", 0.25, 0.15, 0.5, 1.5)

#: e* with the floor carried: (129.6 + 60)² / ((43.2 + 10)·(43.2·36/4 + 10·36))
E_STAR_FLOOR = (129.6 + 60.0) ** 2 / ((43.2 + 10.0) * (43.2 * 36.0 / 4.0 + 10.0 * 36.0))
#: the hand values of (loads, α₀, e*)
CONFIGURATIONS = [
    # a floor: (8.64 + 3.0)/(129.6 + 60) = 11.64/189.6
    ("floor", LoadsInput(top=(FLOOR,)), 0.0613924050632911, 0.9024002313475997),
    # a floor and a thrust: (8.64 + 3.0 − 5.5)/189.6 = 6.14/189.6
    ("floor+thrust", LoadsInput(top=(FLOOR,), thrusts=(THRUST,)), 0.0323839662447257,
     0.9024002313475997),
    # a floor and a tie: (8.64 + 3.0 + 142.73303)/189.6 = 154.37303/189.6
    ("floor+tie", LoadsInput(top=(FLOOR,), ties=(TIE,)), 0.8142037248317313,
     0.9024002313475997),
    # a floor and a brittle tie: L_i = 10·5.8 = 58: (11.64 + 58)/189.6
    ("floor+brittle-tie", LoadsInput(top=(FLOOR,), ties=(BRITTLE,)), 0.3672995780590717,
     0.9024002313475997),
    # a restrained roof holds (4·0.2 = 0.8) but brings no inertia: (8.64 + 0.8)/129.6, e* = 1
    ("restrained roof", LoadsInput(top=(ROOF,)), 0.0728395061728395, 1.0),
]  # fmt: skip


def _model(loads: LoadsInput, options: ModelOptions = EDGE):  # type: ignore[no-untyped-def]
    return rocking_model(WALL, "one-sided", None, options, loads=loads.loads())


def test_hand_values_are_the_formulas() -> None:
    """The literals above are the arithmetic of the docstring (a check of the test itself)."""
    assert CONFIGURATIONS[0][2] == pytest.approx(11.64 / 189.6, rel=1e-12)
    assert CONFIGURATIONS[1][2] == pytest.approx(6.14 / 189.6, rel=1e-12)
    f_y = math.pi * 20.0**2 / 4.0 * 1e-6 * 235e6 / 3.0 / 1e3
    assert CONFIGURATIONS[2][2] == pytest.approx((11.64 + f_y * 5.8) / 189.6, rel=1e-12)
    assert CONFIGURATIONS[3][2] == pytest.approx((11.64 + 58.0) / 189.6, rel=1e-12)
    assert CONFIGURATIONS[4][2] == pytest.approx(9.44 / 129.6, rel=1e-12)
    assert E_STAR_FLOOR == pytest.approx(35948.16 / 39836.16, rel=1e-12)


@pytest.mark.parametrize(("name", "loads", "alpha0", "e_star"), CONFIGURATIONS)
def test_alpha0_and_a0_star_against_hand_calculations(
    name: str, loads: LoadsInput, alpha0: float, e_star: float
) -> None:
    """α₀, e* and the linear check's a0* = α₀/(e*·FC) [g] at LC1 (FC = 1.35), demand
    a_g·S/q = 0.25/2."""
    model = _model(loads)
    assert loaded_alpha0(model) == pytest.approx(alpha0, rel=1e-12)
    assert loaded_e_star(model) == pytest.approx(e_star, rel=1e-12)
    lin = linear_check(model, 0.25, "LC1", 2.0)
    assert lin.alpha0 == pytest.approx(alpha0, rel=1e-12)
    assert lin.e_star == pytest.approx(e_star, rel=1e-12)
    assert lin.a0_star == pytest.approx(alpha0 / (e_star * FC_LC1), rel=1e-12)
    assert lin.demand == 0.125
    assert lin.passed == (alpha0 / (e_star * FC_LC1) >= 0.125)


def test_alpha0_terms_add_up_for_a_reviewer() -> None:
    """results.json's terms: each force × lever, the sums and α₀ of the floor, thrust and
    tie, (8.64 + 3.0 − 5.5 + 142.73303)/189.6."""
    loads = LoadsInput(top=(FLOOR,), thrusts=(THRUST,), ties=(TIE,))
    out = overturning_result(_model(loads), loads)
    by = {(t.name, t.role): t for t in out.terms}
    assert by[("wall weight W", "stabilising")].moment == pytest.approx(8.64, rel=1e-12)
    assert by[("floor", "stabilising")].moment == pytest.approx(3.0, rel=1e-12)
    assert by[("rafters", "overturning")].moment == pytest.approx(5.5, rel=1e-12)
    assert by[("catena", "internal work")].force == pytest.approx(24.60914245, rel=1e-9)
    assert by[("catena", "internal work")].lever == 5.8
    assert by[("wall weight W", "inertia")].moment == pytest.approx(129.6, rel=1e-12)
    assert by[("floor", "inertia")].moment == pytest.approx(60.0, rel=1e-12)
    assert out.stabilising == pytest.approx(11.64, rel=1e-12)
    assert out.inertia == pytest.approx(189.6, rel=1e-12)
    expected = (11.64 - 5.5 + 24.609142453120047 * 5.8) / 189.6
    assert out.alpha0 == pytest.approx(expected, rel=1e-12)
    assert out.alpha0_without_ties == pytest.approx(6.14 / 189.6, rel=1e-12)
    assert out.formula.endswith(f"= {expected:.4g}")
    # M* = e*·(W + P)/g [kg/m]
    assert out.m_star == pytest.approx(E_STAR_FLOOR * 53.2e3 / G, rel=1e-12)


def test_crushing_pivot_takes_n0_x0_over_2() -> None:
    """Pivot crushing: N₀ = 43.2 + 10 = 53.2 kN/m, x₀ = 53.2/(0.85·1500) = 0.0417255 m,
    N₀·x₀/2 = 1.109898 kNm/m off the stabilising moments: α₀ = (11.64 − 1.109898)/189.6."""
    model = _model(LoadsInput(top=(FLOOR,)), ModelOptions(pivot="crushing"))
    x0 = 53.2 / (0.85 * 1500.0)
    assert loaded_alpha0(model) == pytest.approx((11.64 - 53.2 * x0 / 2.0) / 189.6, rel=1e-12)


def test_no_load_is_todays_check_exactly() -> None:
    """Without loads: the wall's own α₀ = a_RM/g, e* = 1 and its capacity curve, the same
    objects and numbers as before loads existed."""
    for options in (EDGE, ModelOptions(pivot="crushing")):
        model = _model(LoadsInput(), options)
        lin = linear_check(model, 0.25, "LC2", 2.0)
        today = simple_overturning_check(model.a_rm_g * 6.0, 6.0, 0.25, "LC2", 2.0)
        assert lin == today
        curve = model_capacity_curve(model, 1.2)
        assert type(curve) is CapacityCurve


def test_capacity_curve_with_a_floor_closed_form() -> None:
    """A floor, edge pivot: α(θ) = [W·(B/2·c − H/2·s) + P·(d·c − H·s)] / [W·(H/2·c + B/2·s)
    + P·(H·c + d·s)], which vanishes at tan θ0 = (W·B/2 + P·d)/(W·H/2 + P·H) = α₀;
    d = d_C·(W·H²/4 + P·H²)/((H/2)·(W·H/2 + P·H)) (eq. C8.7.1.4, the centroid as control
    point); a = α·g/(e*·FC)."""
    model = _model(LoadsInput(top=(FLOOR,)))
    curve = model_capacity_curve(model, FC_LC1)
    assert isinstance(curve, LoadedCapacityCurve)
    theta0 = math.atan(11.64 / 189.6)
    assert curve.theta0 == pytest.approx(theta0, rel=1e-10)
    ratio = (43.2 * 9.0 + 10.0 * 36.0) / (3.0 * 189.6)
    r, alpha = 0.5 * math.hypot(0.4, 6.0), math.atan(0.4 / 6.0)
    d_c = r * (math.sin(alpha) - math.sin(alpha - theta0))
    assert curve.d0 == pytest.approx(d_c * ratio, rel=1e-9)
    assert curve.a0 == pytest.approx(11.64 / 189.6 * G / (E_STAR_FLOOR * FC_LC1), rel=1e-12)
    t = 0.02
    c, s = math.cos(t), math.sin(t)
    hold = 43.2 * (0.2 * c - 3.0 * s) + 10.0 * (0.3 * c - 6.0 * s)
    drive = 43.2 * (3.0 * c + 0.2 * s) + 10.0 * (6.0 * c + 0.3 * s)
    d_t = r * (math.sin(alpha) - math.sin(alpha - t)) * ratio
    assert curve.a_at(d_t) == pytest.approx(hold / drive * G / (E_STAR_FLOOR * FC_LC1), rel=1e-9)
    slv = limit_state_check(curve, "SLV", displacement_spectrum(SPECTRUM, None), 0.25)
    assert slv.d_limit == pytest.approx(0.4 * curve.d0, rel=1e-12)


def test_tie_on_the_capacity_curve_and_in_d0() -> None:
    """The tie's force on the curve is k_t·h_t·sin θ up to F_y (k_t = 210e9·314.159e-6/(8·3)
    = 2.748894e6 N/m per m): at θ = 0.001 it is 2.748894e6·5.8·sin 0.001 = 15.944 kN/m, its
    moment F·h_t·cos θ.  d0 counts a ductile tie (θ0 beyond the floor's atan α₀) and not a
    brittle one (θ0 the floor's), whose loss at sin θ = 10e3/(2.748894e6·5.8) is a drop."""
    ductile = model_capacity_curve(_model(LoadsInput(top=(FLOOR,), ties=(TIE,))), FC_LC1)
    brittle = model_capacity_curve(_model(LoadsInput(top=(FLOOR,), ties=(BRITTLE,))), FC_LC1)
    floor = model_capacity_curve(_model(LoadsInput(top=(FLOOR,))), FC_LC1)
    assert isinstance(ductile, LoadedCapacityCurve) and isinstance(brittle, LoadedCapacityCurve)
    k = 210e9 * math.pi * 100e-6 / (8.0 * 3.0)
    t = 0.001
    c, s = math.cos(t), math.sin(t)
    hold = 43.2e3 * (0.2 * c - 3.0 * s) + 10e3 * (0.3 * c - 6.0 * s) + k * 5.8 * s * 5.8 * c
    drive = 43.2e3 * (3.0 * c + 0.2 * s) + 10e3 * (6.0 * c + 0.3 * s)
    assert ductile.multiplier(t) == pytest.approx(hold / drive, rel=1e-12)
    assert ductile.theta0 > floor.theta0 + 0.1
    assert brittle.theta0 == pytest.approx(floor.theta0, rel=1e-12)
    loss = math.asin(10e3 / (k * 5.8))
    assert brittle.tie_losses == pytest.approx((loss,), rel=1e-12)
    assert brittle.multiplier(loss, after=True) == pytest.approx(floor.multiplier(loss), rel=1e-12)
    # the loss drops the capacity by more than 50 % of its largest value: d_SLV stops there
    assert brittle.rupture_limit == pytest.approx(brittle._displacement(loss), rel=1e-12)
    # at d_SLV the tie still holds (the value just before its loss, as for a bar rupture):
    # α = (hold + F_a/i_t·h_t·cos θ)/drive at the loss, F_a/i_t = 10 kN/m
    c, s = math.cos(loss), math.sin(loss)
    hold = 43.2e3 * (0.2 * c - 3.0 * s) + 10e3 * (0.3 * c - 6.0 * s) + 10e3 * 5.8 * c
    drive = 43.2e3 * (3.0 * c + 0.2 * s) + 10e3 * (6.0 * c + 0.3 * s)
    a_loss = hold / drive * G / (brittle.e_star * FC_LC1)
    assert brittle.a_at(brittle.rupture_limit) == pytest.approx(a_loss, rel=1e-9)
    assert brittle.a_at(brittle.rupture_limit * (1.0 + 1e-9)) < 0.5 * a_loss


def test_case_checks_with_loads_without_the_kernel() -> None:
    """Every supporting check of a loaded case (no records: no time history), its linear α₀
    the hand value of the floor and the tie, its SLV limit 0.40·d0."""
    model = _model(LoadsInput(top=(FLOOR,), ties=(TIE,)))
    out = case_checks(
        "tie", model, a_g=0.25, sd=displacement_spectrum(SPECTRUM, None),
        settings=CodeCheckSettings(),
    )  # fmt: skip
    assert out.linear.alpha0 == pytest.approx(CONFIGURATIONS[2][2], rel=1e-12)
    assert out.capacity.e_star == pytest.approx(E_STAR_FLOOR, rel=1e-12)
    assert out.slv.d_limit == pytest.approx(0.4 * out.capacity.d0, rel=1e-12)
    assert out.slc.d_limit == pytest.approx(0.6 * out.capacity.d0, rel=1e-12)
