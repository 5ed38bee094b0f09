"""Wall and rebar constants of docs/model.md §1–2 and the paper's Eqs. 6–11, 13–14, by hand."""

from __future__ import annotations

import math

import pytest

from frp_assess.dynamics import Rebars, Wall, housner_two_sided, one_sided, velocity_ratio

G = 9.80665


def test_wall_constants():
    w = Wall(thickness=0.4, height=3.0, unit_weight=18e3)
    assert w.alpha == pytest.approx(math.atan(0.4 / 3.0))
    assert w.R == pytest.approx(0.5 * math.sqrt(0.16 + 9.0))
    assert w.mass == pytest.approx(18e3 * 1.2 / G)
    assert w.I0 == pytest.approx(4 / 3 * w.mass * w.R**2)
    assert w.p2 == pytest.approx(w.mass * G * w.R / w.I0)  # definition, = 3g/(4R)
    assert w.a_rm == pytest.approx(G * math.tan(w.alpha))


def test_wall_rejects_nonsense():
    with pytest.raises(ValueError):
        Wall(thickness=-0.4, height=3.0, unit_weight=18e3)
    with pytest.raises(ValueError):
        Wall(thickness=3.0, height=0.4, unit_weight=18e3)


@pytest.mark.parametrize("position,b_factor,r_p", [("centred", 0.5, 1.0), ("external", 1.0, 4.0)])
def test_rebar_constants(position, b_factor, r_p):
    w = Wall(thickness=0.4, height=3.0, unit_weight=18e3)
    bars = Rebars(46e9, 0.015, position, 2.0)
    assert bars.lever_arm(w) == pytest.approx(b_factor * w.R * 2 * math.sin(w.alpha))  # Eqs. 8–9
    A = 2e-3 * 0.4
    assert bars.area(w) == pytest.approx(A)
    K = math.sin(w.alpha) * math.tan(w.alpha) * r_p / 2 * 46e9 * A / (w.mass * G)
    assert bars.stiffness_term(w) == pytest.approx(K)
    # K from the potential: d(U_r)/dθ / (I0 p²) = K sin θ (Eq. 6 → Eq. 10)
    th, d = 0.03, 1e-6
    dU = (bars.stored_energy(w, th + d) - bars.stored_energy(w, th - d)) / (2 * d)
    assert dU / (w.I0 * w.p2) == pytest.approx(K * math.sin(th), rel=1e-6)
    # Eq. 6 in the paper's form
    e = bars.elongation(w, th)
    assert bars.stored_energy(w, th) == pytest.approx(
        0.25 * e * e * 46e9 * A / (w.R * math.cos(w.alpha))
    )
    arg = 0.5 * 0.015 * 3.0 / (2 * bars.lever_arm(w))
    assert bars.rupture_rotation(w) == pytest.approx(2 * math.asin(arg))  # Eq. 11
    assert bars.strain(w, bars.rupture_rotation(w)) == pytest.approx(0.5 * 0.015)


def test_bar_that_cannot_break():
    w = Wall(thickness=0.1, height=3.0, unit_weight=18e3)
    assert math.isinf(Rebars(46e9, 0.5, "centred", 1.0, strain_factor=1.0).rupture_rotation(w))


def test_restitution_values_at_7_5_degrees():
    """docs/model.md §3: at α = 7.5°, √r = 0.974 (two-sided) and 0.450 (one-sided)."""
    a = math.radians(7.5)
    assert velocity_ratio("energy", "two-sided", a) == pytest.approx(0.974, abs=5e-4)
    assert velocity_ratio("energy", "one-sided", a) == pytest.approx(
        0.450, abs=1e-3
    )  # 0.45050: docs/model.md truncates
    assert velocity_ratio("velocity", "two-sided", a) == pytest.approx(housner_two_sided(a))
    assert velocity_ratio("velocity", "one-sided", a) == pytest.approx(one_sided(a))
    assert velocity_ratio(0.8, "one-sided", a) == 0.8
    with pytest.raises(ValueError):
        velocity_ratio(1.5, "one-sided", a)
