"""The bounces after an impact, ended once they surely die out (docs/model.md §3.3).

* The restoring acceleration at θ = 0 that the rule bounds is Eq. 10's own (the kernel's
  right-hand side at θ = 0), for both pivots and both sides.
* Its bound on how long the bounces last holds against the kernel following every bounce,
  and both agree with the closed form of a ball bouncing under constant gravity with a
  coefficient of restitution e: flights of 2v·eᵏ/g, together 2v/(g·(1 − e)).
* The rule changes no result: fate, peaks, final state, the instant the fate was decided
  and the history at every sample are the same bit for bit with it and without it, over the
  time histories of whole IDAs of six walls; only fewer impacts are followed.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from frp_assess.dynamics import IdaSettings, Rebars, RockingModel, ida
from frp_assess.dynamics.kernel import Buffers, Ground, history_length, simulate
from frp_assess.dynamics.kernel.jumps import (
    CHATTER_SAFETY,
    CHATTER_SAMPLES,
    chatter_ends,
    restoring_at_rest,
)
from frp_assess.dynamics.kernel.params import NO_TIES, REST_VELOCITY, KernelParams, kernel_record
from frp_assess.dynamics.kernel.steppers import acceleration
from tests.conftest import synthetic_record
from tests.dynamics.walls import CFRP, SIX_WALLS, WALL

DT = 0.005  #: [s]


def _run(
    prm: KernelParams, acc: np.ndarray, c: float, n_tail: int, history: bool
) -> tuple[Any, list[np.ndarray]]:
    size = history_length(acc.size + n_tail, DT, prm.collapse_mode) if history else 1
    hist = [np.zeros(size) for _ in range(3)]
    buf = Buffers(*hist, np.zeros(2), np.zeros(2, np.int64))
    out = simulate(Ground(acc, DT, c, n_tail), prm, NO_TIES, 0.0, 0.0, history, buf)
    return out, hist


@pytest.mark.parametrize("pivot", ["edge", "crushing"])
@pytest.mark.parametrize("bars", [None, CFRP])
def test_restoring_acceleration_is_eq10_at_rest(pivot: str, bars: Rebars | None) -> None:
    """restoring_at_rest(u, side) = −side·θ''(θ = 0) of the kernel, for both sides, any K_s."""
    prm = RockingModel(WALL, "two-sided", bars).with_options(pivot=pivot).params
    assert (prm.xi > 0.0) == (pivot == "crushing")
    for side in (1.0, -1.0):
        for u in np.linspace(-0.5, 0.5, 11):
            for k_s in (0.0, prm.k_bar):
                exact = -side * acceleration(0.0, side, float(u), k_s, 0.0, 0.0, prm)
                assert restoring_at_rest(float(u), side, prm) == pytest.approx(exact, rel=1e-13)


@pytest.mark.parametrize("mechanism", ["one-sided", "two-sided"])
@pytest.mark.parametrize("u", [0.0, 0.03, -0.03])
@pytest.mark.parametrize("duration", [0.3, 0.6])
def test_bounces_last_what_the_closed_form_says_and_the_bound_holds(
    mechanism: str, u: float, duration: float
) -> None:
    """From θ = 0 with θ' = v under a constant input u (in g), followed bounce by bounce
    (rule off): the wall is at rest after the closed form's time (Σ 2·vₖ/g over the bounces
    the kernel follows, vₖ = v·eᵏ down to its rest velocity; 2v/(g(1 − e)) for all of them)
    to within 2 % plus two samples, and within the rule's bound, which must hold.  The rule
    ends the bounces at once exactly when its bound fits in CHATTER_SAFETY of the stretch it
    may scan (at most CHATTER_SAMPLES samples: the 0.6 s sequences do not fit in 1 s / 2)."""
    model = RockingModel(WALL, mechanism, None).with_options(pivot="edge")
    prm = model.params._replace(settle_chatter=False)
    e = prm.e_impact
    side = 1.0  # the first flight: θ > 0
    g_first = restoring_at_rest(u, side, prm)
    g_other = restoring_at_rest(u, -side, prm) if mechanism == "two-sided" else g_first
    # a sequence of about ``duration``: bounces low enough for the flights to be parabolas
    v = duration * min(g_first, g_other) * (1.0 - e) / 2.0
    acc = kernel_record(np.full(400, u * prm.g))  # 2 s of constant input, in m/s²
    size = history_length(acc.size, DT, prm.collapse_mode)
    hist = [np.zeros(size) for _ in range(3)]
    buf = Buffers(*hist, np.zeros(2), np.zeros(2, np.int64))
    out = simulate(Ground(acc, DT, 1.0, 0), prm, NO_TIES, 0.0, v, True, buf)
    theta = hist[0][: out.samples]
    moving = np.flatnonzero(theta != 0.0)
    t_rest = (moving[-1] + 1) * DT  # the first sample from which the wall stays at rest
    # the closed form: flights alternate sides on a two-sided wall (g_first, g_other, ...)
    flights, speed, k = 0.0, v, 0
    while speed >= REST_VELOCITY * prm.p:
        flights += 2.0 * speed / (g_first if k % 2 == 0 or mechanism == "one-sided" else g_other)
        speed *= e
        k += 1
    assert out.impacts == k
    assert abs(t_rest - flights) <= 0.02 * flights + 2 * DT
    # the rule's bound (the safety factor aside) is never shorter than what the kernel follows
    bound = 2.0 * v / (min(g_first, g_other) * (1.0 - e))
    assert flights <= bound
    last = acc.size - 1
    say = chatter_ends(v, side, acc, 0, 0.0, DT, 1.0 / prm.g, acc.size, last, 1.0, 0.0, prm)
    assert say == (bound <= CHATTER_SAFETY * min(last, CHATTER_SAMPLES) * DT)
    assert say == (duration < 0.5)


def test_no_end_while_the_input_can_uplift_the_wall() -> None:
    """Input beyond the uplift threshold anywhere in the stretch needed: never at rest."""
    prm = RockingModel(WALL, "two-sided", None).with_options(pivot="edge").params
    quiet = np.zeros(400)
    spike = quiet.copy()
    spike[100] = 1.5 * prm.tan_ax * prm.g  # one sample above g·tan α_x, 0.5 s ahead
    g = restoring_at_rest(0.0, 1.0, prm)
    v = 0.4 * g * (1.0 - prm.e_impact) / 2.0  # bounces for 0.4 s: 0.8 s of record needed
    for acc, expected in ((quiet, True), (spike, False)):
        rec = kernel_record(acc)
        assert (
            chatter_ends(
                v, 1.0, rec, 0, 0.0, DT, 1.0 / prm.g, rec.size, rec.size - 1, 1.0, 0.0, prm
            )
            is expected
        )
    # the spike beyond the stretch needed does not matter: bounces of 0.1 s
    rec = kernel_record(spike)
    v_short = v / 4.0
    assert chatter_ends(
        v_short, 1.0, rec, 0, 0.0, DT, 1.0 / prm.g, rec.size, rec.size - 1, 1.0, 0.0, prm
    )


def test_no_end_when_a_bounce_could_reach_the_peak() -> None:
    """The first bounce's height v²/(2g) must stay below half of the peak so far."""
    prm = RockingModel(WALL, "one-sided", None).with_options(pivot="edge").params
    rec = kernel_record(np.zeros(2000))
    v = 1e-4
    height = v * v / (2.0 * restoring_at_rest(0.0, 1.0, prm))
    args = (rec, 0, 0.0, DT, 1.0 / prm.g, rec.size, rec.size - 1)
    assert chatter_ends(v, 1.0, *args, 3.0 * height, 0.0, prm)
    assert not chatter_ends(v, 1.0, *args, 1.5 * height, 0.0, prm)


@pytest.mark.parametrize("mechanism, bars, options", SIX_WALLS)
def test_the_rule_changes_no_result(mechanism: str, bars: Rebars | None, options: dict) -> None:
    """Every time history of the IDA of each wall under two records, with and without a
    history: the same outcome (fate, peaks, final state, collapse and decision instants,
    ruptures, samples) and the same history at every sample, bit for bit; with the rule,
    fewer impacts are followed (at least a tenth fewer over the IDAs: it is at work)."""
    model = RockingModel(WALL, mechanism, bars).with_options(**options)
    on = model.params
    off = on._replace(settle_chatter=False)
    assert on.settle_chatter
    fields = (
        "status fate decided_time collapse_time peak peak_with_bar ruptures final_theta "
        "final_omega samples"
    ).split()
    impacts_on = impacts_off = 0
    for seed in (3, 4):
        acc = synthetic_record(seed, duration=10.0, dt=DT)
        result = ida(model, acc, DT, IdaSettings(max_multiplier=20.0))
        rec = kernel_record(acc)
        n_tail = model.tail_samples(DT)
        for point in result.curve:
            for history in (False, True):
                a, hist_a = _run(on, rec, point.multiplier, n_tail, history)
                b, hist_b = _run(off, rec, point.multiplier, n_tail, history)
                for name in fields:
                    x, y = getattr(a, name), getattr(b, name)
                    assert x == y or (math.isnan(x) and math.isnan(y)), (point.multiplier, name)
                for x, y in zip(hist_a, hist_b, strict=True):
                    assert np.array_equal(x, y)
                if not history:
                    impacts_on += a.impacts
                    impacts_off += b.impacts
    assert impacts_on <= 0.9 * impacts_off
