"""The kernel's shortcuts against the work they save (docs/model.md §4.2–4.3).

Each shortcut must give what the longer way gives:

* the step-size factor without the power, below the error where it is capped at 5;
* the quiet-step test: a Hermite cubic whose Bernstein control points lie in (0, top) never
  leaves (0, top) (the convex-hull property of the Bernstein form; Farin, *Curves and Surfaces
  for CAGD*, 5th ed., §5.3), checked by dense sampling; one that starts at θ = 0 after an
  impact, only when the search on its cubic finds nothing;
* the crossing on the cubic (Newton inside a bracket) against numpy's polynomial roots;
* the event located with its last correction on the Taylor cubic against Newton run to the
  end on the integrator (the impacts of free rocking against Housner's closed form, with all
  of these shortcuts at work: tests/validation/test_free_rocking.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.dynamics import RockingModel, Wall
from frp_assess.dynamics.kernel import events as ev
from frp_assess.dynamics.kernel.params import (
    STEP_GROWTH_MAX,
    STEP_SAFETY,
    STEP_SHRINK_MIN,
)
from frp_assess.dynamics.kernel.step_control import (
    SLIVER,
    grow_threshold,
    quiet,
    step_length,
    step_size,
)
from frp_assess.dynamics.kernel.steppers import acceleration, step


@pytest.mark.parametrize("order", [5, 3])
def test_step_factor_without_the_power_is_the_same(order: int) -> None:
    """h_new = h·min(5, max(0.2, 0.9·err^e)) for every accepted err, the power skipped or not
    (no step long enough to reach the next sample: h_enough out of reach)."""
    exponent = -1.0 / order
    threshold = grow_threshold(exponent)
    errs = np.concatenate([np.geomspace(1e-12, 1.0, 4001), [threshold, threshold * 1.0000001]])
    for err in errs:
        accepted, h = step_size(float(err), 1.0, 1.0, exponent, threshold, math.inf, order)
        expected = min(STEP_GROWTH_MAX, max(STEP_SHRINK_MIN, STEP_SAFETY * err**exponent))
        assert accepted
        assert h == expected


@pytest.mark.parametrize("order", [5, 3])
def test_step_long_enough_for_the_sample_takes_the_same_next_step(order: int) -> None:
    """With the power skipped once the proposal surely reaches h_enough, the next step
    (:func:`step_length` for every rest ≤ dt) is the one the exact proposal gives; and the
    shortcut is not vacuous: it is taken for many of the errors."""
    exponent = -1.0 / order
    threshold = grow_threshold(exponent)
    dt = 0.005
    h_enough = (1.0 - SLIVER) * dt
    rng = np.random.default_rng(5)
    skipped = 0
    for _ in range(4000):
        hh = dt * float(rng.uniform(0.05, 1.0))
        err = float(10.0 ** rng.uniform(-5.0, 0.0))
        accepted, h = step_size(err, hh, hh, exponent, threshold, h_enough, order)
        exact = hh * min(STEP_GROWTH_MAX, max(STEP_SHRINK_MIN, STEP_SAFETY * err**exponent))
        assert accepted
        if h != exact:
            skipped += 1
            assert h >= h_enough and exact >= h_enough
        for rest in (dt, 0.999 * dt, 0.5 * dt, 0.01 * dt, hh):
            assert step_length(h, rest, True) == step_length(exact, rest, True)
    assert skipped > 400


def test_quiet_steps_stay_inside() -> None:
    """Whenever the test says quiet, the cubic sampled at 2001 points stays in (0, top); and
    the test is not vacuous: it says quiet for many of the random steps."""
    rng = np.random.default_rng(7)
    u = np.linspace(0.0, 1.0, 2001)
    quiet_steps = 0
    for _ in range(4000):
        y0, y1 = rng.uniform(-0.2, 1.2, 2)
        m0, m1 = rng.normal(0.0, 0.5, 2)
        top = 1.0
        if quiet(y0, y1, m0, m1, top):
            quiet_steps += 1
            c0, c1, c2, c3 = ev.hermite(y0, y1, m0, m1)
            y = c0 + u * (c1 + u * (c2 + u * c3))
            assert y.min() > 0.0 and y.max() < top
    assert quiet_steps > 400


def test_a_step_that_starts_at_an_impact_is_quiet_only_when_its_search_finds_nothing() -> None:
    """y0 = 0 (the step right after an impact): when the test says quiet, the cubic stays in
    (0, top) on (0, 1] (dense sampling) and the search it saves finds no event and no turning
    point above ``top`` (the first crossing of 0 and of ``top`` on the cubic: none)."""
    rng = np.random.default_rng(13)
    u = np.linspace(0.0, 1.0, 2001)[1:]
    quiet_steps = other = 0
    for _ in range(4000):
        y1 = float(rng.uniform(-0.2, 1.2))
        m0 = float(abs(rng.normal(0.0, 0.8)))
        m1 = float(rng.normal(0.0, 0.8))
        top = 1.0
        c = ev.hermite(0.0, y1, m0, m1)
        r1, r2 = ev.critical_points(c[1], c[2], c[3])
        if quiet(0.0, y1, m0, m1, top):
            quiet_steps += 1
            y = c[0] + u * (c[1] + u * (c[2] + u * c[3]))
            assert y.min() > 0.0 and y.max() < top
            assert ev.first_crossing(*c, r1, r2, 0.0, False) < 0.0
            assert ev.first_crossing(*c, r1, r2, top, True) < 0.0
        else:
            other += 1
    assert quiet_steps > 400 and other > 400


def test_crossing_on_the_cubic_matches_the_polynomial_roots() -> None:
    """The first crossing of a level by a Hermite cubic, against numpy.roots: the smallest
    real root in (0, 1] where the cubic passes the level in the asked direction."""
    rng = np.random.default_rng(11)
    found = 0
    for _ in range(3000):
        y0, y1 = rng.uniform(-1.0, 1.0, 2)
        m0, m1 = rng.normal(0.0, 2.0, 2)
        level = float(rng.uniform(-0.5, 0.5))
        up = bool(rng.integers(2))
        c = ev.hermite(y0, y1, m0, m1)
        r1, r2 = ev.critical_points(c[1], c[2], c[3])
        u = ev.first_crossing(*c, r1, r2, level, up)
        roots = np.roots([c[3], c[2], c[1], c[0] - level])
        real = sorted(
            r.real
            for r in roots
            if abs(r.imag) < 1e-9
            and 0.0 < r.real <= 1.0
            # the direction of the crossing: the sign of the slope there
            and ((c[1] + 2 * c[2] * r.real + 3 * c[3] * r.real**2) > 0) == up
        )
        if not real:
            continue
        found += 1
        assert u == pytest.approx(real[0], abs=1e-8)
    assert found > 500


WALL = Wall(thickness=0.4, height=3.0, unit_weight=18e3)  # no f_d: the edge pivot, Eq. 10
MODEL = RockingModel(WALL, "two-sided")
#: a wall at θ0 falling back at θ0' [rad/s]: the impact comes after about 10 ms, inside a
#: step of 20 ms (p·h ≈ 0.04, as in the kernel's steps)
THETA0 = 1e-3
OMEGA0 = -0.1
STEP = 0.02  # [s]


def test_event_with_the_taylor_correction_matches_newton_to_the_end() -> None:
    """The impact of a wall moving back towards θ = 0, located from a rough guess by the
    kernel (its last correction on the Taylor cubic) and by Newton written out here and run
    to the end on the same Dormand-Prince step: the same instant to 1e-12 s, θ' to 1e-9."""
    prm = MODEL.params
    a1 = acceleration(THETA0, 1.0, 0.0, 0.0, 0.0, 0.0, prm)
    tau0 = 0.008
    tau, om, resid = ev.locate_level(
        THETA0, OMEGA0, a1, STEP, tau0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, prm
    )
    t = tau0
    om_e = math.nan
    for _ in range(50):
        th_e, om_e, _a, _err = step(THETA0, OMEGA0, t, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, a1, prm)
        if abs(th_e) <= 1e-16:
            break
        t -= th_e / om_e
    assert resid == 0.0  # the kernel returns exactly 0 when it took the Taylor correction
    assert tau == pytest.approx(t, abs=1e-12)
    assert om == pytest.approx(om_e, rel=1e-9)


#: a slow crossing: the wall just after a small impact, θ = 0 and θ' = 1e-6 rad/s outward,
#: with no ground motion: it rises to about 3e-12 rad and is back at θ = 0 after
#: 2·θ'/(p²·sin α) ≈ 4 µs (the last impacts of an impact sequence before rest, §3.3)
SLOW_OMEGA0 = 1e-6


@pytest.mark.parametrize("fixed_step", [None, 1e-4])
def test_slow_crossing_is_located_in_time_not_only_in_rotation(fixed_step: float | None) -> None:
    """A crossing at |θ'| = 1e-6 rad/s: an instant off by δt leaves θ within θ'·δt of the
    level but θ' off by θ''·δt.  Closed form (energy, docs/model.md §3.1): with constant
    ground acceleration the motion is reversible, so the wall is back at θ = 0 with
    θ' = −θ'0 exactly.  A bound of 1e-13 rad on θ (the old test) allowed δt up to 1e-7 s,
    θ' off by 2 % here; the instant must be the integrator's own to EVENT_TIME_TOLERANCE."""
    model = MODEL if fixed_step is None else MODEL.with_options(fixed_step=fixed_step)
    prm = model.params
    a1 = acceleration(0.0, 1.0, 0.0, 0.0, 0.0, 0.0, prm)
    period = 2.0 * SLOW_OMEGA0 / (prm.p2 * prm.sin_a)  # ≈ the return time [s]
    h = 2.0 * period
    tau, om, _resid = ev.locate_level(
        0.0, SLOW_OMEGA0, a1, h, 0.9 * period, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, prm
    )
    assert tau == pytest.approx(period, rel=1e-6)
    assert om == pytest.approx(-SLOW_OMEGA0, rel=1e-9)
