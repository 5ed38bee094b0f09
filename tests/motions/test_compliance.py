"""Code compliance checks (frp_assess.motions.compliance): EN 1998-1 §3.2.3.1.2 and
NTC 2018 §3.2.3.6, and the scaling helpers."""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.motions.compliance import (
    DEFAULT_T1,
    check_compliance,
    ec8_range,
    ntc_band_factor,
    ntc_range,
    scale_records,
    scale_to_ntc_band,
    scale_to_pga,
)
from frp_assess.motions.record import G, Record
from frp_assess.motions.spectra import preset_spectrum


def test_ranges():
    assert ec8_range(1.0) == (0.2, 2.0)
    assert ntc_range(0.5) == (0.15, 2.0)  # the larger of 0.15-2.0 s and 0.15-2T1
    assert ntc_range(1.5) == (0.15, 3.0)
    assert DEFAULT_T1 == 1.0


@pytest.fixture
def noise_set(record_factory):
    return [Record(f"n{i}", 0.01, record_factory(i, duration=12.0)) for i in range(4)]


def _by_clause(report, code, fragment):
    return [c for c in report.checks if c.code == code and fragment in c.requirement]


def test_checks_are_computed_from_the_set(noise_set):
    """Each check's margin is the mean/target ratio found minus the limit, recomputed here."""
    s = preset_spectrum("A1")
    rep = check_compliance(noise_set, s, recorded=True)
    ratio = rep.mean / rep.target
    for code, (lo, hi) in (("EN 1998-1", ec8_range(1.0)), ("NTC 2018", ntc_range(1.0))):
        inside = (rep.periods >= lo) & (rep.periods <= hi)
        low = _by_clause(rep, code, "≥ 90%")[0]
        assert low.margin == pytest.approx(ratio[inside].min() - 0.9)
        assert low.passed == (ratio[inside].min() >= 0.9)
    high = _by_clause(rep, "NTC 2018", "≤ 130%")[0]
    inside = (rep.periods >= 0.15) & (rep.periods <= 2.0)
    assert high.margin == pytest.approx(1.3 - ratio[inside].max())
    pga = _by_clause(rep, "EN 1998-1", "PGA")[0]
    assert pga.margin == pytest.approx(np.mean([r.pga_g for r in noise_set]) / s.pga_g - 1)
    assert rep.passed == all(c.passed for c in rep.checks)
    assert not _by_clause(rep, "NTC 2018", "duration")  # no duration check for recorded


def test_too_few_records_fail(noise_set):
    rep = check_compliance(noise_set[:2], preset_spectrum("A2"))
    count = _by_clause(rep, "EN 1998-1", "at least 3")[0]
    assert not count.passed and count.margin == -1 and not rep.passed


def test_short_records_fail_ntc_duration(noise_set):
    rep = check_compliance(noise_set, preset_spectrum("A2"))
    dur = _by_clause(rep, "NTC 2018", "total duration")[0]
    assert not dur.passed and dur.margin == pytest.approx(12.0 - 25.0)


def test_scale_to_pga_and_scale_records(noise_set):
    scaled = scale_to_pga(noise_set, 0.3)
    assert np.mean([r.pga_g for r in scaled]) == pytest.approx(0.3)
    twice = scale_records(scaled, 2.0)
    assert twice[0].acc == pytest.approx(2 * scaled[0].acc)
    ratio = float(twice[0].meta["scale_factor"]) / (0.3 / np.mean([r.pga_g for r in noise_set]))
    assert ratio == pytest.approx(2.0, rel=1e-5)


def test_ntc_band_scaling_centres_the_set(noise_set):
    """After scaling, min and max of mean/target sit symmetrically (in log) in 0.9-1.3."""
    s = preset_spectrum("A3")
    factor, feasible = ntc_band_factor(noise_set, s)
    scaled = scale_to_ntc_band(noise_set, s)
    rep = check_compliance(scaled, s, recorded=True, periods=np.geomspace(0.15, 2.0, 60))
    r = rep.mean / rep.target
    assert r.min() * r.max() == pytest.approx(0.9 * 1.3, rel=1e-6)
    band = _by_clause(rep, "NTC 2018", "≥ 90%") + _by_clause(rep, "NTC 2018", "≤ 130%")
    assert all(c.passed for c in band) == feasible


def test_single_sine_set_fails_the_spectrum_check():
    """A set of narrow-band records cannot match a broad target: the check must say so."""
    t = np.arange(0, 30, 0.01)
    acc = 0.2 * G * np.sin(2 * np.pi * t / 0.3)
    recs = [Record(f"s{i}", 0.01, acc) for i in range(3)]
    rep = check_compliance(recs, preset_spectrum("A1"), recorded=True)
    assert not _by_clause(rep, "EN 1998-1", "≥ 90%")[0].passed
    assert not _by_clause(rep, "NTC 2018", "≤ 130%")[0].passed
