"""How far the number can be trusted: record-to-record statistics and a lognormal fragility.

Inputs are the collapse intensities of one option, one value per record, in any unit of
acceleration (the tool uses a_dyn [g]); every output intensity is in the same unit.

**Statistics.** Mean, median, standard deviation (sample, n − 1), coefficient of variation
and the least favourable record (the smallest collapse intensity), the quantities EC8
§4.3.3.4.3 / NTC 2018 §7.3.5 ask for (``docs/model.md`` §5).  A record that did not collapse
up to C_max enters with its a_dyn(C_max), a lower bound of its collapse intensity: the
statistics then count it in ``censored`` and the mean is a lower bound too.

**Fragility.** P(collapse | IM = a) = Φ(ln(a/θ)/β), fitted by maximum likelihood on the IDA
collapse intensities (the IDA fragility of Baker 2015, Earthquake Spectra 31(1), "Efficient
analytical fragility function fitting using dynamic structural analysis").  Without
non-collapsing records the estimate is closed-form: ln θ = mean of ln a_i, β = their standard
deviation with divisor n (the same as ``scipy.stats.lognorm.fit(a, floc=0)``).
With the effective collapse intensity (docs/model.md §11) the fit is instead to the collapse
outcomes of the records at each sampled intensity, by binomial maximum likelihood
(:func:`fit_binomial_fragility`, Baker 2015's multiple-stripe form).  Rule for the
records that did not collapse up to C_max: they are **right-censored** at a_dyn(C_max) — all
that is known is that their collapse intensity is larger — and enter the likelihood through
the survival 1 − Φ(ln(c_j/θ)/β).  Dropping them would bias θ low; counting them as collapses
at C_max would too.  At least two different collapse intensities are needed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize
from scipy.special import log_ndtr, ndtr

from frp_assess import libm

# The standard normal distribution from scipy.special, as scipy.stats.norm computes it
# (cdf = ndtr, log survival = log_ndtr(-z), log density = -z²/2 - ln √(2π)): the same
# numbers without importing scipy.stats, which costs ~0.4 s at every start of the tool.
_LOG_SQRT_2PI = math.log(math.sqrt(2 * math.pi))


@dataclass(frozen=True)
class RecordStatistics:
    """Record-to-record statistics of the collapse intensity of one option.

    Attributes:
        count: number of records.
        mean, median, std: [unit of the input]; std is the sample deviation (n − 1 divisor,
            0 for one record).
        cov: std/mean [-].
        least_favourable: the smallest value [unit of the input].
        least_favourable_index: its position in the input.
        censored: records that did not collapse (their value is a lower bound).
    """

    count: int
    mean: float
    median: float
    std: float
    cov: float
    least_favourable: float
    least_favourable_index: int
    censored: int


def _positive_array(values: Sequence[float], name: str) -> np.ndarray:
    a = np.asarray(values, dtype=float).ravel()
    if a.size and not (np.all(np.isfinite(a)) and np.all(a > 0)):
        raise ValueError(f"{name} must be finite and > 0")
    return a


def record_statistics(
    values: Sequence[float], collapsed: Sequence[bool] | None = None
) -> RecordStatistics:
    """Statistics of ``values`` (one per record); ``collapsed[i]`` False marks a record that
    did not collapse up to C_max (its value is then a_dyn(C_max))."""
    a = _positive_array(values, "values")
    if a.size == 0:
        raise ValueError("no records")
    flags = np.ones(a.size, bool) if collapsed is None else np.asarray(collapsed, bool)
    if flags.shape != a.shape:
        raise ValueError("collapsed must have one flag per value")
    mean = float(a.mean())
    std = float(a.std(ddof=1)) if a.size > 1 else 0.0
    i = int(np.argmin(a))
    return RecordStatistics(
        count=int(a.size),
        mean=mean,
        median=float(np.median(a)),
        std=std,
        cov=std / mean,
        least_favourable=float(a[i]),
        least_favourable_index=i,
        censored=int(np.count_nonzero(~flags)),
    )


@dataclass(frozen=True)
class LognormalFragility:
    """A lognormal fragility curve.

    Attributes:
        median: θ [unit of the input].
        beta: dispersion β, the standard deviation of ln IM at collapse [-].
        collapsed: records that collapsed (exact observations); ``binomial-mle``: the
            collapsed outcomes over the sampled intensities.
        censored: records that did not collapse up to C_max (right-censored);
            ``binomial-mle``: the standing outcomes.
        method: ``mle`` (closed form), ``censored-mle`` (numerical), both on per-record
            capacities, or ``binomial-mle`` (:func:`fit_binomial_fragility`, on the collapse
            outcomes at each sampled intensity).
    """

    median: float
    beta: float
    collapsed: int
    censored: int
    method: str

    def probability(self, demand: float) -> float:
        """P(collapse) at the intensity ``demand`` [unit of the input]: Φ(ln(a/θ)/β)."""
        return collapse_probability(self, demand)


def collapse_probability(fragility: LognormalFragility, demand: float) -> float:
    """Φ(ln(demand/θ)/β); 0 for a demand ≤ 0."""
    if demand <= 0:
        return 0.0
    return float(ndtr(math.log(demand / fragility.median) / fragility.beta))


def _negative_log_likelihood(params: np.ndarray, ln_x: np.ndarray, ln_c: np.ndarray) -> float:
    mu, log_beta = params
    beta = math.exp(log_beta)
    z = (ln_x - mu) / beta
    exact = np.sum(-(z**2) / 2.0 - _LOG_SQRT_2PI) - ln_x.size * log_beta - np.sum(ln_x)
    survived = np.sum(log_ndtr(-((ln_c - mu) / beta)))
    return float(-(exact + survived))


def fit_lognormal_fragility(
    collapse_intensities: Sequence[float], censored_at: Sequence[float] = ()
) -> LognormalFragility:
    """Maximum-likelihood lognormal fragility (module docstring for the censoring rule).

    Args:
        collapse_intensities: intensity at the first collapse of each record that collapsed.
        censored_at: for each record that did not collapse, the largest intensity run
            (a_dyn at C_max).
    """
    x = _positive_array(collapse_intensities, "collapse_intensities")
    c = _positive_array(censored_at, "censored_at")
    ln_x = libm.log(x)
    if x.size < 2 or np.ptp(ln_x) == 0.0:
        raise ValueError("a fragility needs at least two different collapse intensities")
    mu0 = float(ln_x.mean())
    beta0 = float(ln_x.std())  # divisor n: the maximum-likelihood estimate
    if c.size == 0:
        return LognormalFragility(math.exp(mu0), beta0, int(x.size), 0, "mle")
    ln_c = libm.log(c)
    result = minimize(
        _negative_log_likelihood,
        np.array([mu0, math.log(beta0)]),
        args=(ln_x, ln_c),
        method="Nelder-Mead",
        options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 4000},
    )
    if not result.success:
        raise RuntimeError(f"censored fragility fit did not converge: {result.message}")
    mu, log_beta = result.x
    return LognormalFragility(
        math.exp(mu), math.exp(log_beta), int(x.size), int(c.size), "censored-mle"
    )


def _binomial_negative_log_likelihood(
    params: np.ndarray, ln_im: np.ndarray, fell: np.ndarray, stood: np.ndarray
) -> float:
    mu, log_beta = params
    z = (ln_im - mu) / math.exp(log_beta)
    return float(-(np.sum(fell * log_ndtr(z)) + np.sum(stood * log_ndtr(-z))))


def fit_binomial_fragility(
    intensities: Sequence[float], collapsed: Sequence[int], runs: Sequence[int]
) -> LognormalFragility | None:
    """Lognormal fragility fitted by binomial maximum likelihood to the collapse outcomes at
    each sampled intensity (Baker 2015, Earthquake Spectra 31(1), eq. 11: the product over the
    intensities x_j of C(n_j, z_j)·p_j^z_j·(1 − p_j)^(n_j − z_j), p_j = Φ(ln(x_j/θ)/β)),
    ``collapsed[j]`` of ``runs[j]`` records having fallen at ``intensities[j]``.

    None when the outcomes are separated (every collapse at or above every survival): the
    likelihood then grows without bound as β → 0 and no lognormal is determined.
    """
    x = _positive_array(intensities, "intensities")
    z = np.asarray(collapsed, dtype=float)
    n = np.asarray(runs, dtype=float)
    if not (x.shape == z.shape == n.shape) or np.any(z < 0) or np.any(z > n):
        raise ValueError("one count of collapses (0..runs) per intensity")
    ln_x = libm.log(x)
    fell_at = ln_x[z > 0]
    stood_at = ln_x[z < n]
    if fell_at.size == 0 or stood_at.size == 0 or fell_at.min() >= stood_at.max():
        return None
    # start: the median between the lowest collapse and the highest survival, β from their span
    mu0 = 0.5 * (float(fell_at.min()) + float(stood_at.max()))
    beta0 = max(0.05, 0.5 * (float(stood_at.max()) - float(fell_at.min())))
    result = minimize(
        _binomial_negative_log_likelihood,
        np.array([mu0, math.log(beta0)]),
        args=(ln_x, z, n - z),
        method="Nelder-Mead",
        options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 4000},
    )
    if not result.success:
        raise RuntimeError(f"binomial fragility fit did not converge: {result.message}")
    mu, log_beta = result.x
    return LognormalFragility(
        math.exp(mu), math.exp(log_beta), int(z.sum()), int((n - z).sum()), "binomial-mle"
    )
