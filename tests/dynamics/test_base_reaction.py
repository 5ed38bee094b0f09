"""The base reaction that follows the bars (docs/model.md §1.1) against hand calculations.

The wall turns about its base corner; the base carries N = W + T(θ) on a stress block of
0.85·f_d (NTC 2018 §7.8.2.2.1) of depth x = N/(0.85·f_d), whose resultant acts at x/2 from the
corner.  References written here, never read back from the model: the static moment balance
about the corner (gravity, ground inertia, bar, reaction), the activation acceleration
g·(B − x_W)/H, the angle where the restoring moment of the unreinforced wall vanishes, the
crushing rotation where x reaches the bar, and the potential V(θ) integrated numerically.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from frp_assess.dynamics import IdaSettings, ModelOptions, Rebars, RockingModel, Wall, ida
from frp_assess.dynamics.kernel.fate import reaction_integral, restoring, tipping_angle
from frp_assess.dynamics.kernel.steppers import acceleration
from frp_assess.motions.record import G

B, H, W_UNIT = 0.3, 3.0, 18e3  # [m], [m], [N/m³]
F_D = 1.5e6  # [Pa]
E, EPS_U, C = 46e9, 0.015, 0.5  # GFRP [Pa], [-], strain factor [-]
WEIGHT = W_UNIT * B * H  # W [N/m]
X_W = WEIGHT / (0.85 * F_D)  # x_W [m]: 16.2 kN/m on 1.275 MPa
R = 0.5 * math.hypot(B, H)
ALPHA = math.atan(B / H)
CRUSHING = ModelOptions(pivot="crushing")


def bars(position: str, ratio: float = 1.0, modulus: float = E) -> Rebars:
    return Rebars(modulus, EPS_U, position, ratio, C)  # type: ignore[arg-type]


def model(
    position: str | None, ratio: float = 1.0, f_d: float = F_D, **options: object
) -> RockingModel:
    rebars = None if position is None else bars(position, ratio)
    opts = ModelOptions(**{"pivot": "crushing", **options})  # type: ignore[arg-type]
    return RockingModel(Wall(B, H, W_UNIT, f_d), "two-sided", rebars, opts)


def arm(position: str) -> float:
    """b_r [m]: B/2 centred (Eq. 8), B external (Eq. 9)."""
    return B / 2 if position == "centred" else B


def kappa(position: str, ratio: float) -> float:
    """κ = 2·b_r·E·A/(H·W): T(θ) = W·κ·sin(|θ|/2)."""
    return 2 * arm(position) * E * ratio * 1e-3 * B / (H * WEIGHT)


@pytest.mark.parametrize("position", [None, "centred", "external"])
def test_uplift_threshold_by_hand(position: str | None) -> None:
    """At rest N = W: the wall uplifts at a_RM = g·(B − x_W)/H, with or without bars."""
    m = model(position)
    a_rm = G * (B - X_W) / H
    assert m.a_rm == pytest.approx(a_rm, rel=1e-12)
    assert m.alpha == pytest.approx(math.atan((B - X_W) / H), rel=1e-12)
    prm = m.params
    # θ'' vanishes at u = −a_RM/g on both sides and changes sign across it
    for s in (1.0, -1.0):
        assert acceleration(0.0, s, -s * a_rm / G, prm.k_bar, 0.0, 0.0, prm) == pytest.approx(
            0.0, abs=1e-12
        )
        assert s * acceleration(0.0, s, -s * 1.01 * a_rm / G, prm.k_bar, 0.0, 0.0, prm) > 0.0
        assert s * acceleration(0.0, s, -s * 0.99 * a_rm / G, prm.k_bar, 0.0, 0.0, prm) < 0.0
    # the IDA starts from it: C0·PGA = a_RM
    acc = 0.2 * G * np.sin(2 * np.pi * np.arange(200) * 0.01)
    res = ida(m, acc, 0.01, IdaSettings(max_multiplier=1.5))
    assert res.c0 * res.pga == pytest.approx(a_rm, rel=1e-12)


@pytest.mark.parametrize("position", ["centred", "external"])
@pytest.mark.parametrize("theta", [0.0, 0.005, 0.02, 0.04])
def test_static_multiplier_by_hand(position: str, theta: float) -> None:
    """λ(θ) from the moment balance about the corner, the bar stretched by θ.

    Gravity W·R·sin(α − θ) and the bar T·b_r·cos(θ/2), T = E·A·2b_r·sin(θ/2)/H, less the
    reaction N·(x/2)·cos θ (N = W + T, x = N/(0.85·f_d)), balance the ground's inertia
    W·λ·R·cos(α − θ).
    """
    b = arm(position)
    tension = E * 1e-3 * B * 2 * b * math.sin(theta / 2) / H
    n = WEIGHT + tension
    x = n / (0.85 * F_D)
    resisting = WEIGHT * R * math.sin(ALPHA - theta) + tension * b * math.cos(theta / 2)
    resisting -= n * x / 2 * math.cos(theta)
    lam = resisting / (WEIGHT * R * math.cos(ALPHA - theta))
    prm = model(position).params
    assert acceleration(theta, 1.0, -lam, prm.k_bar, 0.0, 0.0, prm) == pytest.approx(0.0, abs=1e-10)
    assert acceleration(-theta, -1.0, lam, prm.k_bar, 0.0, 0.0, prm) == pytest.approx(
        0.0, abs=1e-10
    )
    # the edge model (x = 0) resists more
    edge = model(position, pivot="edge").params
    assert acceleration(theta, 1.0, -lam, edge.k_bar, 0.0, 0.0, edge) < 0.0


def test_tipping_angle_of_the_unreinforced_wall_by_hand() -> None:
    """R·sin(α − θ) = (x_W/2)·cos θ at θ = α_x = atan((B − x_W)/H)."""
    alpha_x = math.atan((B - X_W) / H)
    assert R * math.sin(ALPHA - alpha_x) == pytest.approx(X_W / 2 * math.cos(alpha_x), rel=1e-12)
    prm = model(None).params
    assert prm.alpha_x == pytest.approx(alpha_x, rel=1e-14)
    assert restoring(alpha_x, 0.0, prm) == pytest.approx(0.0, abs=1e-15)
    assert tipping_angle(0.0, prm) == prm.alpha_x


@pytest.mark.parametrize("position", ["centred", "external"])
def test_tipping_angle_with_bars_is_the_first_zero_of_the_moment(position: str) -> None:
    """θ* with an intact bar: the moment of the static balance above vanishes there, and is
    positive (restoring) everywhere below."""
    prm = model(position, 3.0).params
    tip = tipping_angle(prm.k_bar, prm)
    b, k = arm(position), kappa(position, 3.0)

    def moment(t: float) -> float:  # per W·R, by hand
        n = 1 + k * math.sin(t / 2)
        x = WEIGHT * n / (0.85 * F_D)
        tension = WEIGHT * k * math.sin(t / 2)
        m = WEIGHT * R * math.sin(ALPHA - t) + tension * b * math.cos(t / 2)
        return (m - WEIGHT * n * x / 2 * math.cos(t)) / (WEIGHT * R)

    assert 0 < tip < math.pi / 2
    assert moment(tip) == pytest.approx(0.0, abs=1e-12)
    assert min(moment(t) for t in np.linspace(0.0, tip, 400)[:-1]) > 0.0
    assert prm.tip_bar == tip


@pytest.mark.parametrize("position,ratio", [("centred", 1.0), ("external", 2.0)])
def test_crushing_rotation_by_hand(position: str, ratio: float) -> None:
    """x(θ_cr) = b_r: W·(1 + κ·sin(θ_cr/2)) = 0.85·f_d·b_r."""
    m = model(position, ratio, f_d=0.6e6)
    x_w = WEIGHT / (0.85 * 0.6e6)
    k = kappa(position, ratio)
    theta_cr = 2 * math.asin((arm(position) / x_w - 1) / k)
    assert m.crushing_rotation == pytest.approx(theta_cr, rel=1e-12)
    assert m.params.theta_cr == m.crushing_rotation
    assert float(m.base_reaction.depth(theta_cr)) == pytest.approx(arm(position), rel=1e-12)
    # a strong masonry never crushes before the bar breaks; no bar, no crushing
    assert model(position, ratio, f_d=50e6).crushing_rotation == math.inf
    assert model(None, f_d=0.6e6).crushing_rotation == math.inf


@pytest.mark.parametrize("k", [0.0, 3.0, 40.0])
@pytest.mark.parametrize("t", [1e-4, 0.05, 0.4, 1.5])
def test_reaction_integral_closed_form(k: float, t: float) -> None:
    """∫₀^t (1 + κ·sin(φ/2))²·cos φ dφ by quadrature."""
    ref, _ = quad(lambda p: (1 + k * math.sin(p / 2)) ** 2 * math.cos(p), 0.0, t, epsabs=1e-15)
    assert reaction_integral(t, k) == pytest.approx(ref, rel=1e-9, abs=1e-15)


def potential_by_hand(theta: np.ndarray, position: str | None, ratio: float) -> np.ndarray:
    """V(θ)/p² = cos(α − |θ|) + K·(1 − cos θ) − ξ·∫₀^|θ| n²·cos φ dφ (trapezoids on a fine
    grid), K = E·A·b_r²/(H·m·g·R), ξ = x_W/(2R)."""
    k_bar = (
        0.0 if position is None else E * ratio * 1e-3 * B * arm(position) ** 2 / (H * WEIGHT * R)
    )
    k = 0.0 if position is None else kappa(position, ratio)
    grid = np.linspace(0.0, float(np.max(np.abs(theta))) * 1.001, 200_001)
    f = (1 + k * np.sin(grid / 2)) ** 2 * np.cos(grid)
    cum = np.concatenate(([0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(grid))))
    reaction = np.interp(np.abs(theta), grid, cum)
    return np.cos(ALPHA - np.abs(theta)) + k_bar * (1 - np.cos(theta)) - X_W / (2 * R) * reaction


@pytest.mark.parametrize(
    "mechanism,position",
    [("two-sided", None), ("two-sided", "centred"), ("one-sided", "external")],
)
def test_energy_conserved_in_free_rocking(mechanism: str, position: str | None) -> None:
    """No ground motion, perfectly elastic impacts: ½θ'² + V(θ) is constant."""
    rebars = None if position is None else bars(position, 2.0)
    m = RockingModel(
        Wall(B, H, W_UNIT, F_D),
        mechanism,  # type: ignore[arg-type]
        rebars,
        ModelOptions(restitution=1.0, pivot="crushing"),
    )
    prm = m.params
    top = min(prm.alpha_x if position is None else prm.tip_bar, m.theta_max, m.crushing_rotation)
    theta0 = 0.6 * top
    dt = 0.002
    res = m.run(np.zeros(int(6.0 / dt)), dt, history=True, theta0=theta0)
    assert res.impacts >= 4 and not res.ruptures and not res.collapsed
    h = res.history
    assert h is not None
    p2 = 3 * G / (4 * R)
    e = 0.5 * h.omega**2 + p2 * potential_by_hand(h.theta, position, 2.0)
    swing = p2 * (1 - math.cos(theta0)) * (1 + m.K)
    assert np.max(np.abs(e - e[0])) < 1e-6 * swing


def test_rupture_hands_over_eq12_and_drops_the_bar_from_the_reaction() -> None:
    """Eq. 12 adds U_r(θ_max)/I0 to ½θ'²; after the rupture the potential is the
    unreinforced one, so ½θ'² + V_free after = ½θ'² + V_bar before + ξ·p²·[I_κ − I_0](θ_max),
    the reaction's share of the bar leaving N (I_κ: the integral of n², by quadrature here)."""
    m = model("external", 1.0, restitution=1.0)
    prm = m.params
    tm = m.theta_max
    assert tm < m.crushing_rotation
    p2 = 3 * G / (4 * R)
    need = p2 * (potential_by_hand(np.array([tm]), "external", 1.0)[0] - math.cos(ALPHA) + 0.0)
    dt = 0.001
    res = m.run(np.zeros(int(1.5 / dt)), dt, history=True, omega0=math.sqrt(2 * 1.2 * need))
    assert res.ruptures and res.ruptures[0].side == 1
    h = res.history
    assert h is not None
    i = int(res.ruptures[0].time / dt)
    before = 0.5 * h.omega[: i + 1] ** 2 + p2 * potential_by_hand(h.theta[: i + 1], "external", 1.0)
    after = 0.5 * h.omega[i + 1 : i + 40] ** 2 + p2 * potential_by_hand(
        h.theta[i + 1 : i + 40], None, 1.0
    )
    k = kappa("external", 1.0)
    i_k, _ = quad(lambda p: (1 + k * math.sin(p / 2)) ** 2 * math.cos(p), 0.0, tm)
    jump = X_W / (2 * R) * p2 * (i_k - math.sin(tm))
    assert np.ptp(before) < 1e-7 * need
    assert after == pytest.approx(np.full(after.shape, before[0] + jump), abs=1e-7 * need)
    assert prm.xi == pytest.approx(X_W / (2 * R))


def test_crushing_is_a_collapse_at_theta_cr() -> None:
    """Pushed outward past θ_cr < θ_max: the toe crushes at θ_cr, a collapse named so."""
    m = model("external", 2.0, f_d=0.6e6)
    tcr = m.crushing_rotation
    assert tcr < m.theta_max
    f_d = 0.6e6
    x_w = WEIGHT / (0.85 * f_d)
    k = kappa("external", 2.0)
    k_bar = E * 2e-3 * B * B**2 / (H * WEIGHT * R)
    i_k, _ = quad(lambda p: (1 + k * math.sin(p / 2)) ** 2 * math.cos(p), 0.0, tcr)
    rise = math.cos(ALPHA - tcr) - math.cos(ALPHA) + k_bar * (1 - math.cos(tcr))
    rise -= x_w / (2 * R) * i_k  # V(θ_cr) − V(0) per p²
    res = m.run(np.zeros(500), 0.002, omega0=math.sqrt(2 * 1.2 * rise) * m.wall.p)
    assert res.fate == "crushed" and res.collapsed and res.failure_mode == "crushing"
    assert res.max_rotation == pytest.approx(tcr, rel=1e-12)
    assert not res.ruptures


def test_rupture_before_crushing_then_overturning() -> None:
    """θ_max < θ_cr: the bar breaks first; the unreinforced wall then falls."""
    m = model("centred", 1.0)
    assert m.theta_max < m.crushing_rotation
    res = m.run(np.zeros(3000), 0.002, omega0=4.0 * m.wall.p * m.theta_max)
    assert res.ruptures and res.fate == "fell"
    assert res.failure_mode == "rupture then overturning"


def test_centred_bar_inside_the_weights_block_crushes_at_c0() -> None:
    """x_W ≥ B/2 with a centred bar: the toe crushes as soon as the wall uplifts, C = C₀."""
    f_d = WEIGHT / (0.85 * 0.55 * B)  # x_W = 0.55·B
    m = model("centred", 1.0, f_d=f_d)
    assert m.crushing_rotation == 0.0
    acc = 0.2 * G * np.sin(2 * np.pi * np.arange(300) * 0.01)
    res = ida(m, acc, 0.01)
    assert res.collapse_multiplier == res.c0 and res.failure_mode == "crushing"
    run = m.run(acc, 0.01, 1.05 * res.c0)
    assert run.fate == "crushed" and run.max_rotation == 0.0
    # the external bar (at B from the corner) is still outside that block
    ext = model("external", 1.0, f_d=f_d)
    assert 0.0 < ext.crushing_rotation


def test_a_base_that_cannot_carry_the_weight_is_refused() -> None:
    """x_W ≥ B: no mechanism, the model refuses the input."""
    f_d = WEIGHT / (0.85 * B)  # x_W = B exactly
    with pytest.raises(ValueError, match="the base cannot carry the wall's weight"):
        model(None, f_d=f_d)
    with pytest.raises(ValueError, match="pivot must be"):
        ModelOptions(pivot="middle")  # type: ignore[arg-type]
    # the edge model takes no strength into account
    RockingModel(Wall(B, H, W_UNIT, f_d), "two-sided", None, ModelOptions(pivot="edge"))


def test_edge_pivot_has_no_reaction_term() -> None:
    """``pivot: edge`` and f_d = ∞ are the paper's constants exactly."""
    for rebars in (None, bars("external", 1.5), bars("centred", 2.0)):
        paper = RockingModel(Wall(B, H, W_UNIT), "two-sided", rebars).params
        edge = RockingModel(
            Wall(B, H, W_UNIT, F_D), "two-sided", rebars, ModelOptions(pivot="edge")
        )
        assert edge.params == paper
        assert paper.xi == 0.0 and paper.theta_cr == math.inf and paper.alpha_x == paper.alpha
        assert paper.tan_ax == math.sin(paper.alpha) / math.cos(paper.alpha)


def test_large_strength_converges_to_the_edge_model() -> None:
    """f_d → ∞: the crushing model tends to the edge one, the gap of a peak rotation at a
    fixed multiplier falling like ξ ∝ 1/f_d, and the collapse multiplier matches at large f_d.

    (The first-collapse multiplier itself is compared only where the IDA's grid C₀·1.1^k has
    not moved: C₀ = a_RM/PGA changes with x_W, and a first collapse found on another grid can
    be another band of the IDA curve.)"""
    t = np.arange(1500) * 0.01
    acc = 0.25 * G * np.minimum(t / 3.0, 1.0) * np.sin(2 * np.pi * 1.5 * t)
    settings = IdaSettings(tolerance=1e-4)
    for rebars in (None, bars("external", 1.5)):
        edge = RockingModel(Wall(B, H, W_UNIT), "one-sided", rebars)
        c_edge = ida(edge, acc, 0.01, settings).collapse_multiplier
        assert c_edge is not None
        peak_edge = edge.run(acc, 0.01, 0.6 * c_edge).max_rotation
        gaps = []
        for f_d in (3e7, 3e8, 3e9):
            m = RockingModel(Wall(B, H, W_UNIT, f_d), "one-sided", rebars, CRUSHING)
            gaps.append(abs(m.run(acc, 0.01, 0.6 * c_edge).max_rotation - peak_edge) / peak_edge)
        assert gaps[0] > 5 * gaps[1] > 25 * gaps[2]
        assert gaps[2] < 1e-3
        strong = RockingModel(Wall(B, H, W_UNIT, 3e14), "one-sided", rebars, CRUSHING)
        c_strong = ida(strong, acc, 0.01, settings).collapse_multiplier
        assert c_strong == pytest.approx(c_edge, rel=1e-6)
