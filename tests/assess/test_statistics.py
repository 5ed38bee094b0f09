"""Record-to-record statistics and the lognormal fragility fit.

The fit is checked against scipy's own maximum-likelihood fits on known samples:
``scipy.stats.lognorm.fit(data, floc=0)`` (shape s = β, scale = θ) and, for records that did
not collapse, the same fit on ``scipy.stats.CensoredData`` with right-censored values.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from frp_assess.assess.statistics import (
    LognormalFragility,
    collapse_probability,
    fit_lognormal_fragility,
    record_statistics,
)


def test_record_statistics_by_hand():
    s = record_statistics([0.5, 0.2, 0.4, 0.6, 0.3])
    assert s.count == 5
    assert s.mean == pytest.approx(0.4)
    assert s.median == pytest.approx(0.4)
    # deviations −0.2, −0.1, 0, 0.1, 0.2: Σd² = 0.1, sample variance 0.1/4
    assert s.std == pytest.approx(math.sqrt(0.025))
    assert s.cov == pytest.approx(math.sqrt(0.025) / 0.4)
    assert s.least_favourable == 0.2 and s.least_favourable_index == 1
    assert s.censored == 0


def test_record_statistics_counts_censored_and_single_record():
    s = record_statistics([0.3, 1.0], collapsed=[True, False])
    assert s.censored == 1 and s.least_favourable_index == 0
    one = record_statistics([0.7])
    assert one.std == 0.0 and one.cov == 0.0 and one.median == 0.7
    with pytest.raises(ValueError):
        record_statistics([0.3, -0.1])
    with pytest.raises(ValueError):
        record_statistics([0.3, 0.4], collapsed=[True])


@pytest.mark.parametrize("seed,n", [(1, 7), (2, 7), (3, 40)])
def test_lognormal_fit_matches_scipy(seed, n):
    rng = np.random.default_rng(seed)
    data = np.exp(rng.normal(math.log(0.35), 0.4, n))
    fit = fit_lognormal_fragility(data)
    s, loc, scale = stats.lognorm.fit(data, floc=0)
    assert loc == 0
    assert fit.median == pytest.approx(scale, rel=1e-6)
    assert fit.beta == pytest.approx(s, rel=1e-6)
    assert fit.method == "mle" and fit.collapsed == n and fit.censored == 0


def test_lognormal_fit_on_a_sample_with_known_log_moments():
    # ln a = ln 0.3 + 0.5·(−1.5, −0.5, 0.5, 1.5)/√1.25: mean ln 0.3, divisor-n std 0.5
    z = np.array([-1.5, -0.5, 0.5, 1.5]) / math.sqrt(1.25)
    fit = fit_lognormal_fragility(0.3 * np.exp(0.5 * z))
    assert fit.median == pytest.approx(0.3)
    assert fit.beta == pytest.approx(0.5)
    assert fit.probability(0.3) == pytest.approx(0.5)
    assert fit.probability(0.3 * math.exp(0.5)) == pytest.approx(stats.norm.cdf(1.0))
    assert collapse_probability(fit, 0.0) == 0.0


@pytest.mark.parametrize("seed", [4, 5])
def test_censored_fit_matches_scipy_censored_data(seed):
    rng = np.random.default_rng(seed)
    sample = np.exp(rng.normal(math.log(0.5), 0.45, 9))
    c_max = float(np.quantile(sample, 0.7))  # records above it "did not collapse" by c_max
    collapsed = sample[sample <= c_max]
    censored = np.full(np.count_nonzero(sample > c_max), c_max)
    fit = fit_lognormal_fragility(collapsed, censored)
    data = stats.CensoredData(uncensored=collapsed, right=censored)
    s, _, scale = stats.lognorm.fit(data, floc=0)
    assert fit.method == "censored-mle" and fit.censored == censored.size
    assert fit.median == pytest.approx(scale, rel=1e-3)
    assert fit.beta == pytest.approx(s, rel=1e-3)

    def log_likelihood(beta: float, median: float) -> float:  # scipy's densities
        dist = stats.lognorm(beta, scale=median)
        return float(np.sum(dist.logpdf(collapsed)) + np.sum(dist.logsf(censored)))

    # at least as likely as scipy's optimum (scipy's optimizer stops a little earlier)
    assert log_likelihood(fit.beta, fit.median) >= log_likelihood(s, scale) - 1e-9
    # dropping the non-collapsing records would bias the median low
    assert fit.median > fit_lognormal_fragility(collapsed).median


def test_censoring_far_below_tells_nothing_far_above_tells_a_lot():
    data = [0.2, 0.25, 0.31, 0.4, 0.5]
    plain = fit_lognormal_fragility(data)
    low = fit_lognormal_fragility(data, [1e-6])  # survived a negligible intensity
    assert low.median == pytest.approx(plain.median, rel=1e-5)
    assert low.beta == pytest.approx(plain.beta, rel=1e-5)
    high = fit_lognormal_fragility(data, [5.0])  # survived ten times the largest collapse
    assert high.beta > plain.beta and high.median > plain.median


def test_fit_needs_two_different_collapses():
    with pytest.raises(ValueError, match="two different"):
        fit_lognormal_fragility([0.3])
    with pytest.raises(ValueError, match="two different"):
        fit_lognormal_fragility([0.3, 0.3], [0.5])


def test_probability_is_the_lognormal_cdf():
    frag = LognormalFragility(median=0.4, beta=0.3, collapsed=7, censored=0, method="mle")
    for a in (0.1, 0.4, 0.9):
        assert frag.probability(a) == pytest.approx(stats.lognorm.cdf(a, 0.3, scale=0.4))


def test_the_normal_distribution_is_scipy_stats_norm_to_the_last_bit():
    """The module computes Φ, ln φ and ln(1 − Φ) with scipy.special instead of importing
    scipy.stats (0.4 s at start-up); the likelihood the censored fit minimises and the
    probability it reports must be scipy.stats.norm's, bit for bit."""
    from frp_assess.assess.statistics import _negative_log_likelihood

    rng = np.random.default_rng(8)
    for _ in range(200):
        ln_x = rng.normal(-0.7, 0.5, int(rng.integers(2, 12)))
        ln_c = rng.normal(-0.2, 0.5, int(rng.integers(1, 5)))
        mu, log_beta = float(rng.normal(-0.5, 0.3)), float(rng.normal(-1.0, 0.5))
        beta = math.exp(log_beta)
        z = (ln_x - mu) / beta
        exact = np.sum(stats.norm.logpdf(z)) - ln_x.size * log_beta - np.sum(ln_x)
        survived = np.sum(stats.norm.logsf((ln_c - mu) / beta))
        expected = float(-(exact + survived))
        assert _negative_log_likelihood(np.array([mu, log_beta]), ln_x, ln_c) == expected
        frag = LognormalFragility(math.exp(mu), beta, 5, 0, "mle")
        a = float(np.exp(rng.normal(mu, 1.0)))
        assert collapse_probability(frag, a) == float(
            stats.norm.cdf(math.log(a / frag.median) / beta)
        )
