"""Artificial accelerograms after SIMQKE (Gasparini & Vanmarcke 1976;
frp_assess.motions.simqke) and their code compliance (frp_assess.motions.compliance)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.errors import InputError
from frp_assess.motions.compliance import check_compliance
from frp_assess.motions.envelopes import ENVELOPES, envelope
from frp_assess.motions.record import G
from frp_assess.motions.response import response_spectrum
from frp_assess.motions.simqke import generate_artificial, vanmarcke_psd
from frp_assess.motions.spectra import ec8_spectrum, ntc2018_spectrum, preset_spectrum

SPECTRA = (
    [preset_spectrum(p) for p in ("A1", "A2", "A3")]
    + [ec8_spectrum(0.25, g, t) for t in (1, 2) for g in "ABCDE"]
    + [
        ntc2018_spectrum(0.261, 2.36, 0.347, "B", "T1"),  # a typical site of central Italy
        ntc2018_spectrum(0.25, 2.4, 0.30, "C", "T1"),  # the test vector
        ntc2018_spectrum(0.05, 2.6, 0.25, "D", "T2"),  # low seismicity, soft soil, slope
        ntc2018_spectrum(0.15, 2.5, 0.45, "E", "T4"),  # ridge
    ]
)
SEEDS = range(1, 21)


def test_same_seed_same_numbers_and_record_independence():
    """Record i depends only on (seed, i): same arguments -> identical bits; the first two
    records of a 3-set equal those of a 2-set except for the common set factor."""
    s = preset_spectrum("A2")
    a = generate_artificial(s, count=3, seed=7)
    b = generate_artificial(s, count=3, seed=7)
    for x, y in zip(a, b, strict=True):
        assert np.array_equal(x.acc, y.acc)
    c = generate_artificial(s, count=2, seed=7)
    fa, fc = float(a[0].meta["set_scale_factor"]), float(c[0].meta["set_scale_factor"])
    np.testing.assert_allclose(a[1].acc / fa, c[1].acc / fc, rtol=1e-12, atol=1e-15)
    d = generate_artificial(s, count=1, seed=8)
    assert not np.allclose(d[0].acc, a[0].acc)


def test_record_layout_and_baseline():
    """Names, duration, dt; the baseline correction leaves v(end) = d(end) = 0."""
    recs = generate_artificial(preset_spectrum("A1"), count=2, seed=3, duration=25.0, dt=0.005)
    assert [r.name for r in recs] == ["art-01", "art-02"]
    for r in recs:
        assert r.dt == 0.005 and r.duration == pytest.approx(25.0)
        assert "seed 3" in r.source
        v = np.concatenate(([0.0], np.cumsum(0.5 * (r.acc[1:] + r.acc[:-1]) * r.dt)))
        d = np.sum(0.5 * (v[1:] + v[:-1]) * r.dt)
        assert abs(v[-1]) < 1e-10 and abs(d) < 1e-9
        assert abs(float(r.meta["final_velocity_m_s"])) < 1e-10
        assert abs(r.acc[0]) < 1e-3 * r.pga and abs(r.acc[-1]) < 1e-2 * r.pga


@pytest.mark.parametrize("kind", ENVELOPES)
def test_envelopes(kind):
    t = np.linspace(0, 25, 2501)
    e = envelope(kind, t, 2.5, 10.0, 25.0)
    assert e.max() == pytest.approx(1.0, abs=1e-3) and e.min() >= 0.0
    strong = np.count_nonzero(e >= 2**-0.5) * (t[1] - t[0])
    assert strong >= 10.0 - 0.02  # ≥ 10 s of strong (stationary) part
    recs = generate_artificial(preset_spectrum("A3"), count=1, seed=2, envelope=kind)
    assert recs[0].meta["envelope"] == kind


def test_vanmarcke_psd_reproduces_a_flat_target_roughly():
    """The PSD alone (no iteration) gives a spectrum within ±35 % of the target: Vanmarcke's
    relation is an approximation that the iterations then correct."""
    s = preset_spectrum("A2")
    dt, n = 0.01, 2501
    omega = 2 * math.pi * np.fft.rfftfreq(2 * n, dt)
    t_om = np.where(omega > 0, 2 * math.pi / np.maximum(omega, 1e-9), 10.0)
    psd = vanmarcke_psd(omega, s.sa(np.minimum(t_om, 6.0)) * G * (t_om < 6.0), 0.05, 20.0)
    rng = np.random.default_rng(0)
    amp = np.sqrt(2 * psd * (omega[1] - omega[0]))
    acc = np.zeros(n)
    t = np.arange(n) * dt
    for k in np.nonzero(amp)[0]:
        acc += amp[k] * np.sin(omega[k] * t + rng.uniform(0, 2 * np.pi))
    periods = np.array([0.2, 0.4, 1.0])
    ratio = response_spectrum(acc, dt, periods) / G / s.sa(periods)
    assert np.all((ratio > 0.65) & (ratio < 1.35))


def test_generator_rejects_bad_arguments():
    s = preset_spectrum("A1")
    with pytest.raises(InputError, match="duration"):
        generate_artificial(s, duration=10.0)
    with pytest.raises(InputError, match="envelope"):
        generate_artificial(s, envelope="square")
    with pytest.raises(InputError, match="count"):
        generate_artificial(s, count=0)


@pytest.mark.slow
def test_default_set_of_seven_passes_for_the_presets():
    """Issue 3 defaults (7 records, 25 s, dt = 0.005 s, 10 s stationary) against A1-A3."""
    for name in ("A1", "A2", "A3"):
        s = preset_spectrum(name)
        recs = generate_artificial(s, seed=1)
        report = check_compliance(recs, s)
        assert report.passed, [c for c in report.checks if not c.passed]
        assert report.mean_pga_g >= s.pga_g * (1 - 1e-9)
        assert 1.0 <= float(recs[0].meta["set_scale_factor"]) < 1.15


@pytest.mark.slow
@pytest.mark.parametrize("spectrum", SPECTRA, ids=lambda s: s.name)
def test_generator_passes_ec8_and_ntc_for_20_seeds(spectrum):
    """Issue 3: both codes' checks pass for presets A1-A3, EC8 types 1/2 on all grounds and
    typical NTC sites, 20 seeds each.  Sets of 3 records (the codes' minimum) keep the
    runtime modest; a set of 3 is the harder case, as its mean averages fewer records."""
    factors = []
    for seed in SEEDS:
        recs = generate_artificial(spectrum, count=3, seed=seed)
        report = check_compliance(recs, spectrum)
        assert report.passed, (seed, [c for c in report.checks if not c.passed])
        factors.append(float(recs[0].meta["set_scale_factor"]))
    assert max(factors) < 1.2  # the common factor stays a small correction
