"""Record-to-record scatter, fragility and the stored IDA curve of each case in results.json
(issue 16 §3): statistics recomputed here with numpy, the fragility against scipy's lognormal
fit (no censoring on this project), the curve against an independent IDA."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

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
        shape, _loc, scale = stats.lognorm.fit(a, floc=0)
        fr = sc.fragility
        assert fr is not None
        assert fr.median == pytest.approx(scale, rel=1e-6)
        assert fr.beta == pytest.approx(shape, rel=1e-6)
        p = stats.norm.cdf(math.log(demand / scale) / shape)
        assert fr.p_collapse_at_demand == pytest.approx(p, rel=1e-6, abs=1e-300)
        # the curve: every multiplier the search ran, sorted, ending at the first collapse
        for r, rec in zip(case.records, recs, strict=True):
            ref = ida(model, rec.acc, rec.dt, inputs.ida)
            assert r.curve == tuple((p.multiplier, p.collapsed, p.peak_ratio) for p in ref.curve)
            cs = [c for c, _, _ in r.curve]
            assert cs == sorted(cs) and len(cs) == ref.runs
            first = min(c for c, collapsed, _ in r.curve if collapsed)
            assert first == r.collapse_multiplier
