"""Record-to-record scatter, fragility and the stored IDA curve of each case in results.json
(issue 16 §3): statistics recomputed here with numpy, the fragility against scipy's lognormal
fit (no censoring on this project), the curve against an independent IDA."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize, stats

from frp_assess.api import prepare_records, run_assessment
from frp_assess.dynamics import ida
from tests.assess.test_run import small_inputs


def test_scatter_fragility_and_curve(tmp_path):
    inputs = small_inputs()
    results, _ = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    recs = prepare_records(inputs).records
    demand = results.demand.pga
    for case, model in zip(results.cases, inputs.case_models(), strict=True):
        a = np.array([r.a_dyn for r in case.records], dtype=float)
        assert np.all(np.isfinite(a))  # every record collapses on this project
        sc = case.scatter
        assert sc.median_a_dyn == pytest.approx(np.median(a))
        assert sc.std_a_dyn == pytest.approx(np.std(a, ddof=1))
        assert sc.cov == pytest.approx(np.std(a, ddof=1) / np.mean(a))
        assert sc.least_favourable_record == case.records[int(np.argmin(a))].record
        assert sc.records_without_collapse == 0
        # the effective capacity (docs/model.md §11): the fragility is the binomial maximum
        # of the likelihood of the collapse fractions (Baker 2015 eq. 11), found here
        # independently: the likelihood written with scipy.stats, its best point on a grid of
        # (θ, β), then Nelder-Mead from there
        fractions = sc.collapse_fraction
        assert fractions and all(f.records == len(case.records) for f in fractions)
        x = np.array([f.intensity for f in fractions])
        z = np.array([f.collapsed for f in fractions])
        n = np.array([f.records for f in fractions])

        def nll(q: np.ndarray, x=x, z=z, n=n) -> float:  # type: ignore[no-untyped-def]
            p = stats.norm.cdf((np.log(x) - q[0]) / q[1])
            return -float(np.sum(stats.binom.logpmf(z, n, p)))

        grid = [(mu, b) for mu in np.log(x) for b in np.geomspace(0.01, 2.0, 40)]
        start = min(grid, key=lambda q: nll(np.array(q)))
        opts = {"xatol": 1e-10, "fatol": 1e-12, "maxiter": 4000}
        ref = optimize.minimize(nll, np.array(start), method="Nelder-Mead", options=opts)
        scale, shape = math.exp(ref.x[0]), ref.x[1]
        fr = sc.fragility
        assert fr is not None and fr.method == "binomial-mle"
        assert nll(np.array([math.log(fr.median), fr.beta])) <= ref.fun + 1e-6
        assert fr.median == pytest.approx(scale, rel=1e-3)
        assert fr.beta == pytest.approx(shape, rel=1e-2)
        p = stats.norm.cdf(math.log(demand / fr.median) / fr.beta)
        assert fr.p_collapse_at_demand == pytest.approx(p, rel=1e-6, abs=1e-300)
        # the curve: every multiplier the sampling ran, sorted; the first collapse on it
        for r, rec in zip(case.records, recs, strict=True):
            ref = ida(model, rec.acc, rec.dt, inputs.ida)
            assert r.curve == tuple((p.multiplier, p.collapsed, p.peak_ratio) for p in ref.curve)
            cs = [c for c, _, _ in r.curve]
            assert cs == sorted(cs) and len(cs) == ref.runs
            first = min(c for c, collapsed, _ in r.curve if collapsed)
            assert first == r.first_collapse_multiplier
