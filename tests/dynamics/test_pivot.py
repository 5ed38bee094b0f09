"""The crushing pivot (docs/model.md §1.1) against hand calculations.

The pivot sits at x/2 from the compressed edge, x = N/(0.85·f_d), N = W + T_u (W alone
unreinforced).  References written here, never read back from the model: static moment
balance about the shifted pivot (gravity, ground inertia, bar), the activation acceleration
g·(B/2 − x/2)/(H/2), and the energy integral of a block of the real wall's mass and inertia
I' = m·(B² + H²)/12 + m·R'² about that pivot.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import (
    IdaSettings,
    ModelOptions,
    PivotGeometry,
    Rebars,
    RockingModel,
    Wall,
    ida,
)
from frp_assess.dynamics.kernel.steppers import acceleration
from frp_assess.motions.record import G

B, H, W_UNIT = 0.3, 3.0, 18e3  # [m], [m], [N/m³]
F_D = 1.5e6  # [Pa]
E, EPS_U, C = 46e9, 0.015, 0.5  # GFRP [Pa], [-], strain factor [-]
CRUSHING = ModelOptions(pivot="crushing")


def hand_depth(ratio: float | None) -> float:
    """x [m] = (W + T_u) / (0.85·f_d), per metre of wall."""
    weight = W_UNIT * B * H
    t_u = 0.0 if ratio is None else E * ratio * 1e-3 * B * C * EPS_U
    return (weight + t_u) / (0.85 * F_D)


def bars(position: str, ratio: float = 1.0) -> Rebars:
    return Rebars(E, EPS_U, position, ratio, C)  # type: ignore[arg-type]


def test_unreinforced_activation_by_hand() -> None:
    """a_RM = g·(B/2 − x/2)/(H/2) with x = W/(0.85·f_d): moments about the shifted pivot."""
    x = hand_depth(None)
    assert x == pytest.approx(W_UNIT * B * H / (0.85 * F_D))  # 16.2 kN/m on 1.275 MPa
    model = RockingModel(Wall(B, H, W_UNIT, F_D), "two-sided", None, CRUSHING)
    a_rm = G * (B / 2 - x / 2) / (H / 2)
    assert model.pivot.depth == pytest.approx(x, rel=1e-12)
    assert model.a_rm == pytest.approx(a_rm, rel=1e-12)
    # at rest, the kernel's θ'' vanishes exactly at u = −a_RM/g and changes sign across it
    prm = model.params
    assert acceleration(0.0, 1.0, -a_rm / G, 0.0, prm) == pytest.approx(0.0, abs=1e-12)
    assert acceleration(0.0, 1.0, -1.01 * a_rm / G, 0.0, prm) > 0.0
    # the IDA starts from the same activation: C0·PGA = a_RM
    acc = 0.2 * G * np.sin(2 * np.pi * np.arange(200) * 0.01)
    res = ida(model, acc, 0.01, IdaSettings(max_multiplier=1.5))
    assert res.c0 * res.pga == pytest.approx(a_rm, rel=1e-12)


@pytest.mark.parametrize("position,arm", [("centred", B / 2), ("external", B)])
@pytest.mark.parametrize("theta", [0.0, 0.01, 0.03, 0.06])
def test_static_multiplier_by_hand(position: str, arm: float, theta: float) -> None:
    """λ(θ) from the moment balance about the pivot at x/2, with the bar stretched by θ.

    Gravity W·[(B − x)/2·cos θ − H/2·sin θ] plus the bar T·b'·cos(θ/2), T = E·A·2b'·sin(θ/2)/H,
    b' = b_r − x/2, balance the ground's inertia W·λ·[(B − x)/2·sin θ + H/2·cos θ].
    """
    x = hand_depth(1.0)
    a = (B - x) / 2
    b = arm - x / 2
    weight = W_UNIT * B * H
    area = 1.0e-3 * B
    tension = E * area * 2 * b * math.sin(theta / 2) / H
    restoring = weight * (a * math.cos(theta) - H / 2 * math.sin(theta))
    restoring += tension * b * math.cos(theta / 2)
    lam = restoring / (weight * (a * math.sin(theta) + H / 2 * math.cos(theta)))
    model = RockingModel(Wall(B, H, W_UNIT, F_D), "two-sided", bars(position), CRUSHING)
    prm = model.params
    # the kernel is at equilibrium under u = −λ (ground pushing the wall towards θ > 0)
    assert acceleration(theta, 1.0, -lam, prm.k_bar, prm) == pytest.approx(0.0, abs=1e-10)
    if theta == 0.0:
        assert lam == pytest.approx((B - x) / H)
    # the edge pivot's λ is larger: the crushed pivot shortens every lever arm
    edge = RockingModel(Wall(B, H, W_UNIT), "two-sided", bars(position)).params
    lam_edge = -(math.sin(edge.alpha - theta) + edge.k_bar * math.sin(theta)) / math.cos(
        edge.alpha - theta
    )
    assert -lam_edge > lam


def test_rupture_rotation_and_inertia_by_hand() -> None:
    x = hand_depth(1.0)
    b = B - x / 2  # external bar
    model = RockingModel(Wall(B, H, W_UNIT, F_D), "two-sided", bars("external"), CRUSHING)
    assert model.theta_max == pytest.approx(2 * math.asin(C * EPS_U * H / (2 * b)))
    m = W_UNIT * B * H / G
    r = 0.5 * math.hypot(B - x, H)
    inertia = m * (B**2 + H**2) / 12 + m * r**2
    assert model.params.p2 == pytest.approx(m * G * r / inertia)
    # and x = 0 gives the paper's I0 = (4/3)·m·R², p² = 3g/(4R)
    edge = PivotGeometry(Wall(B, H, W_UNIT), None, 0.0)
    assert edge.p2 == pytest.approx(3 * G / (4 * 0.5 * math.hypot(B, H)))


def test_infinite_strength_is_the_edge_pivot() -> None:
    """f_d → ∞: the crushing model is the edge model (constants and the same C on a record)."""
    ramp = np.minimum(np.arange(1500) * 0.01 / 3.0, 1.0)
    acc = 0.25 * G * ramp * np.sin(2 * np.pi * 1.5 * np.arange(1500) * 0.01)
    for rebars in (None, bars("external", 1.5)):
        edge = RockingModel(Wall(B, H, W_UNIT), "one-sided", rebars)
        strong = RockingModel(Wall(B, H, W_UNIT, 1e30), "one-sided", rebars, CRUSHING)
        for name in ("p2", "alpha", "k_bar", "theta_max", "rupture_energy", "e_impact"):
            assert getattr(strong.params, name) == pytest.approx(getattr(edge.params, name))
        settings = IdaSettings(tolerance=1e-3)
        c_edge = ida(edge, acc, 0.01, settings).collapse_multiplier
        c_strong = ida(strong, acc, 0.01, settings).collapse_multiplier
        assert c_edge is not None and c_strong is not None
        assert c_strong == pytest.approx(c_edge, rel=2e-3)
    # and a weak masonry lowers C
    weak = RockingModel(Wall(B, H, W_UNIT, 0.4e6), "one-sided", None, CRUSHING)
    c_weak = ida(weak, acc, 0.01, IdaSettings(tolerance=1e-3)).collapse_multiplier
    c_edge = ida(RockingModel(Wall(B, H, W_UNIT), "one-sided"), acc, 0.01).collapse_multiplier
    assert c_weak is not None and c_edge is not None and c_weak < c_edge


@pytest.mark.parametrize(
    "mechanism,position", [("two-sided", "centred"), ("one-sided", "external")]
)
def test_energy_conserved_about_the_crushed_pivot(mechanism: str, position: str) -> None:
    """Free vibration, perfectly elastic impacts: E = θ'²/2 + p'²·cos(α' − |θ|)
    + p'²·K'·(1 − cos θ) is constant, with α', p'², K' computed here by hand."""
    x = hand_depth(2.0)
    arm = B / 2 if position == "centred" else B
    b = arm - x / 2
    m = W_UNIT * B * H / G
    r = 0.5 * math.hypot(B - x, H)
    alpha = math.atan((B - x) / H)
    p2 = m * G * r / (m * (B**2 + H**2) / 12 + m * r**2)
    k = E * 2.0e-3 * B * b**2 / (H * m * G * r)
    model = RockingModel(
        Wall(B, H, W_UNIT, F_D),
        mechanism,  # type: ignore[arg-type]
        bars(position, 2.0),
        ModelOptions(restitution=1.0, pivot="crushing"),
    )
    theta0 = 0.6 * 2 * math.asin(C * EPS_U * H / (2 * b))  # below the rupture rotation
    dt = 0.002
    res = model.run(np.zeros(int(6.0 / dt)), dt, history=True, theta0=theta0)
    assert res.impacts >= 4 and not res.ruptures
    h = res.history
    assert h is not None
    e = 0.5 * h.omega**2 + p2 * np.cos(alpha - np.abs(h.theta)) + p2 * k * (1 - np.cos(h.theta))
    swing = p2 * (1 - math.cos(theta0)) * (1 + k)
    assert np.max(np.abs(e - e[0])) < 1e-6 * swing
    # the bar's strain history is measured about the pivot too: e/H = 2b'·sin(|θ|/2)/H
    assert h.strain[1:] == pytest.approx(2 * b * np.sin(np.abs(h.theta[1:]) / 2) / H)


def test_a_base_that_cannot_carry_n_has_no_pivot() -> None:
    """x ≥ B: no mechanism; the model runs with the edge pivot (the assessment drops it)."""
    heavy = bars("external", 20.0)
    model = RockingModel(Wall(B, H, W_UNIT, 0.5e6), "two-sided", heavy, CRUSHING)
    assert hand_depth(20.0) * F_D / 0.5e6 > B
    assert model.pivot_used == "edge" and model.pivot.depth == 0.0
    assert model.params == RockingModel(Wall(B, H, W_UNIT), "two-sided", heavy).params
    light = RockingModel(Wall(B, H, W_UNIT, F_D), "two-sided", bars("external"), CRUSHING)
    assert light.pivot_used == "crushing"
    with pytest.raises(ValueError, match="cannot carry"):
        PivotGeometry(Wall(B, H, W_UNIT), heavy, B)
    with pytest.raises(ValueError, match="pivot must be"):
        ModelOptions(pivot="middle")  # type: ignore[arg-type]


@pytest.mark.parametrize("rule", ["energy-transfer", "velocity-continuous"])
def test_rupture_about_the_crushed_pivot_hands_over_eq12_energy(rule: str) -> None:
    """Rupture at θ'_max = 2·asin(ε_max·H/(2b')) with the jump of Eq. 12: per unit I', the
    unreinforced energy after equals the total before (energy-transfer), or is lower by
    U_r'/I' = ½·(E·A/H)·(2b'·sin(θ'_max/2))²/I' (velocity-continuous); constants by hand."""
    x = hand_depth(1.0)
    b = B - x / 2  # external bar
    m = W_UNIT * B * H / G
    r = 0.5 * math.hypot(B - x, H)
    alpha = math.atan((B - x) / H)
    inertia = m * (B**2 + H**2) / 12 + m * r**2
    p2 = m * G * r / inertia
    ea = E * 1.0e-3 * B
    k = ea * b**2 / (H * m * G * r)
    tm = 2 * math.asin(C * EPS_U * H / (2 * b))
    u_r = 0.5 * ea / H * (2 * b * math.sin(tm / 2)) ** 2 / inertia
    assert u_r == pytest.approx(p2 * k * (1 - math.cos(tm)))  # Eq. 6 is the bar's potential
    model = RockingModel(
        Wall(B, H, W_UNIT, F_D),
        "two-sided",
        bars("external"),
        ModelOptions(restitution=1.0, rupture=rule, pivot="crushing"),  # type: ignore[arg-type]
    )
    need = p2 * (math.cos(alpha - tm) - math.cos(alpha)) + u_r
    dt = 0.001
    res = model.run(np.zeros(int(1.5 / dt)), dt, history=True, omega0=math.sqrt(2 * 1.2 * need))
    assert res.ruptures and res.ruptures[0].side == 1
    h = res.history
    assert h is not None
    i = int(res.ruptures[0].time / dt)
    assert h.theta[i] < tm <= h.theta[i + 1]

    def energy(theta: np.ndarray, omega: np.ndarray, kk: float) -> np.ndarray:
        return 0.5 * omega**2 + p2 * np.cos(alpha - np.abs(theta)) + p2 * kk * (1 - np.cos(theta))

    before = energy(h.theta[: i + 1], h.omega[: i + 1], k)
    after = energy(h.theta[i + 1 : i + 40], h.omega[i + 1 : i + 40], 0.0)
    expected = before[0] if rule == "energy-transfer" else before[0] - u_r
    assert np.ptp(before) < 1e-8 * u_r
    assert after == pytest.approx(np.full(after.shape, expected), abs=1e-8 * u_r)
