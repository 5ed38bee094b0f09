"""The collapse fractions at the ladder's intensities and the fragility fitted to them
(docs/model.md §11; Baker 2015, Earthquake Spectra 31(1), eq. 11), against independent
computations written here."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize
from scipy.stats import binom, norm

from frp_assess.assess.collapse_fraction import collapse_fractions, fraction_fragility
from frp_assess.assess.demand_window import on_collapse_window, scaled_demands
from frp_assess.assess.statistics import fit_binomial_fragility
from frp_assess.dynamics import IdaPoint, IdaResult, IdaSettings
from frp_assess.dynamics.effective import ladder
from frp_assess.motions import G
from frp_assess.results.verdict import NearDemand

#: intensities [g], records run and collapsed at each (a multiple-stripe analysis)
IM = [0.2, 0.3, 0.4, 0.6, 0.8, 1.0]
RUNS = [40, 40, 40, 40, 40, 40]
FELL = [1, 4, 11, 24, 33, 38]


def test_binomial_fit_is_the_maximum_of_the_likelihood_written_here() -> None:
    """θ, β maximise Σ log Binom(z_j; n_j, Φ(ln(x_j/θ)/β)), maximised independently here with
    scipy.stats.binom and L-BFGS-B on (ln θ, β) from another start."""
    fit = fit_binomial_fragility(IM, FELL, RUNS)
    assert fit is not None and fit.method == "binomial-mle"

    def nll(p: np.ndarray) -> float:
        prob = norm.cdf((np.log(IM) - p[0]) / p[1])
        return -float(np.sum(binom.logpmf(FELL, RUNS, prob)))

    ref = minimize(nll, np.array([math.log(0.3), 0.8]), method="L-BFGS-B",
                   bounds=[(-5, 5), (0.01, 5)], options={"ftol": 1e-14, "gtol": 1e-10})  # fmt: skip
    assert fit.median == pytest.approx(math.exp(ref.x[0]), rel=1e-4)
    assert fit.beta == pytest.approx(ref.x[1], rel=1e-4)
    assert fit.collapsed == sum(FELL) and fit.censored == sum(RUNS) - sum(FELL)


def test_separated_outcomes_have_no_lognormal() -> None:
    """Every collapse above every survival: the likelihood grows as β → 0, no fit."""
    assert fit_binomial_fragility([0.1, 0.2, 0.3], [0, 0, 5], [5, 5, 5]) is None
    assert fit_binomial_fragility([0.1, 0.2], [0, 0], [5, 5]) is None


def _result(c0: float, pga: float, outcomes: list[bool], st: IdaSettings) -> IdaResult:
    """A record whose sampling ran the first len(outcomes) ladder points (and one point off
    the ladder, which the fractions must ignore)."""
    steps = ladder(c0, st.max_multiplier * c0, st.ladder_ratio, st.offset)
    curve = [IdaPoint(float(c), f, 0.5) for c, f in zip(steps, outcomes, strict=False)]
    curve.append(IdaPoint(float(steps[1]) * 1.001, True, 1.0))
    curve.sort(key=lambda p: p.multiplier)
    return IdaResult(
        pga, c0, None, None, None, len(curve), None, tuple(curve), capacity="effective"
    )


def test_fractions_count_the_ladder_points_and_the_early_stop_as_collapsed() -> None:
    """Two records of the same a_RM: record A stands, stands, falls, stands, falls (then its
    sampling stopped), record B stands four times and falls; at level k the fraction counts A
    as fallen past its last point.  Intensities C₀·r^k·PGA/g, the same for both."""
    st = IdaSettings(capacity="effective")
    a = _result(0.5, 2.0, [False, False, True, False, True], st)
    b = _result(0.25, 4.0, [False, False, False, False, True, True], st)
    fr = collapse_fractions([a, b], st)
    assert [f.collapsed for f in fr] == [0, 0, 1, 0, 2, 2]
    assert all(f.records == 2 for f in fr)
    r = st.ladder_ratio
    assert [f.intensity for f in fr] == pytest.approx([1.0 / G * r**k for k in range(6)])
    fit = fraction_fragility(fr)
    assert fit is not None and fit.method == "binomial-mle"
    assert collapse_fractions([a, b], st) == fr
    first = IdaSettings(capacity="first-collapse")
    assert (
        collapse_fractions(
            [_result(0.5, 2.0, [True], first).__class__(2.0, 0.5, 0.5, 1.0, 1.0, 1, None)], first
        )
        == ()
    )


def test_a_level_not_run_takes_the_nearest_sample() -> None:
    """The default sampling runs the coarse ladder (every 8th level) below its first collapse:
    a level it skipped takes the outcome of the nearest sample in ln C (the midpoint rule of
    the integral).  By hand: samples at levels 0 (stands), 9 (falls), 10 (stands); levels 1–4
    are nearer level 0 (stand), 5–8 nearer level 9 (fall); none above the last sample."""
    st = IdaSettings(capacity="effective")
    steps = ladder(1.0, st.max_multiplier, st.ladder_ratio, st.offset)
    curve = tuple(IdaPoint(float(steps[k]), k == 9, 0.5) for k in (0, 9, 10))
    res = IdaResult(2.0, 1.0, None, None, None, 3, None, curve, capacity="effective")
    fr = collapse_fractions([res], st)
    assert [f.collapsed for f in fr] == [0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 0]


def test_a_collapse_window_at_the_demand() -> None:
    """The verdict at the demand against 0.98× and 1.02×: differs = on a collapse window."""
    near = (NearDemand(0.98, True), NearDemand(1.02, True))
    assert not on_collapse_window(True, near)
    assert on_collapse_window(False, near)
    assert on_collapse_window(True, (NearDemand(0.98, True), NearDemand(1.02, False)))
    assert not on_collapse_window(None, near)


def test_scaled_demands_scale_every_motion() -> None:
    from frp_assess.assess.check_demand import LimitStateDemand

    acc = np.array([0.0, 1.0, -2.0])
    d = {"SLV": LimitStateDemand(0.3, lambda t, x: 0.0, 1.0, [(acc, 0.01)]),  # type: ignore[arg-type]
         "SLC": LimitStateDemand(0.4, lambda t, x: 0.0, 1.0, None)}  # type: ignore[arg-type]  # fmt: skip
    out = scaled_demands(d, 1.02)
    assert out["SLC"].motions is None
    assert out["SLV"].motions is not None
    np.testing.assert_array_equal(out["SLV"].motions[0][0], acc * 1.02)
    assert out["SLV"].a_g == 0.3
