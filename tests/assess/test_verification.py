"""The numerical check (`analysis.integration.verify`, docs/model.md §4.5) and the integration
tolerance as a setting of the run: recorded in results.json and in the cache key."""

from __future__ import annotations

from dataclasses import replace

import pytest

from frp_assess.api import run_assessment
from frp_assess.dynamics import ida
from frp_assess.dynamics.rocking import DEFAULT_TOLERANCE
from frp_assess.results.run_inputs import Integration
from tests.assess.test_run import small_inputs


def test_verify_repeats_every_ida_at_a_tighter_tolerance(tmp_path):
    inputs = replace(small_inputs(), verify=True)
    results, stats = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    nc = results.numerical_check
    assert nc is not None
    pairs = len(results.cases) * len(results.records)
    assert stats.computed == 2 * pairs  # the run and its check
    assert nc.tolerance == DEFAULT_TOLERANCE
    assert nc.check_tolerance == DEFAULT_TOLERANCE / 10
    assert nc.pairs == pairs
    # the largest change is the one between the two computations, found independently here
    worst = 0.0
    models = inputs.case_models()
    from frp_assess.api import prepare_records

    recs = prepare_records(inputs).records
    for m in models:
        tight = m.with_options(tolerance=DEFAULT_TOLERANCE / 10)
        for r in recs:
            a = ida(m, r.acc, r.dt, inputs.ida).collapse_multiplier
            b = ida(tight, r.acc, r.dt, inputs.ida).collapse_multiplier
            assert a is not None and b is not None
            worst = max(worst, abs(b - a) / a)
    assert nc.max_change == worst
    assert results.model.integration == Integration(
        method="Dormand-Prince 5(4), local error control",
        tolerance=DEFAULT_TOLERANCE,
        verify=True,
    )


@pytest.mark.slow
def test_tolerance_is_part_of_the_cache_key(tmp_path):
    inputs = small_inputs()
    _, first = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    _, again = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    looser = replace(inputs, model=replace(inputs.model, tolerance=1e-6))
    results, other = run_assessment(looser, tmp_path, jobs=2, pdf=False, write=False)
    assert again.computed == 0 and again.reused == first.computed
    assert other.computed == first.computed  # nothing reused across tolerances
    assert results.model.integration.tolerance == 1e-6
    assert results.numerical_check is None
