"""Each limit state checked at its own spectrum (assess.limit_states, docs/model.md §5.5).

Hand calculations from NTC 2018 §3.2.3.2.1 (Eqs. 3.2.2-3.2.7, Tab. 3.2.IV for subsoil B:
S_S = 1.40 − 0.40·F0·a_g within [1.00, 1.20], C_C = 1.10·(T_C*)^−0.20; T_C = C_C·T_C*,
T_D = 4.0·a_g + 1.6 s; η = √(10/(5 + ξ[%])) ≥ 0.55) and Circolare 2019 §C8.7.1.2.1.6-9 on
the paper's wall (H = 3 m, α = 7.5°, pivot at the edge, FC = 1.35 of LC1): d0 = B/2,
d_SLC = 0.6·d0 = 0.118487 m, a(d_SLC) = tan(α − θ)·g/FC = 0.379785 m/s², T_SLC =
1.56·π·√(d_SLC/a) = 2.737421 s (the worked example of tests/assess/test_kinematic_checks.py).

The site's parameters are written here by hand (not read from the grid): SLV a_g = 0.255 g,
F0 = 2.376, T_C* = 0.335 s; SLC a_g = 0.327 g, F0 = 2.408, T_C* = 0.353 s (close to Norcia's).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frp_assess.assess.decision import TH_SLC, TH_SLV, Evidence, verdict
from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    Material,
    RecordFile,
    RetrofitOption,
)
from frp_assess.assess.kinematic_checks import (
    IdaSummary,
    kinematic_checks,
    limit_state_demands,
)
from frp_assess.assess.limit_states import (
    limit_state_spectrum,
    own_spectra,
    spectrum_compatible_records,
)
from frp_assess.assess.seismic import state_records
from frp_assess.dynamics import ModelOptions
from frp_assess.motions import ElasticSpectrum, Record, ntc2018_spectrum
from frp_assess.motions.site import SiteHazard
from frp_assess.motions.site.hazard import LimitStateHazard

G = 9.80665
ALPHA = math.radians(7.5)
B = 3.0 * math.tan(ALPHA)
T_SLC = 2.737421  # s, hand value (module docstring)
D_SLC = 0.118487  # m
SLV = (0.255, 2.376, 0.335)  # a_g [g], F0, T_C* [s]
SLC = (0.327, 2.408, 0.353)
SITE = SiteHazard(
    42.79,
    13.09,
    50.0,
    "II",
    1.0,
    50.0,
    {
        "SLO": LimitStateHazard(30.0, 30.0, 0.08, 2.3, 0.27),
        "SLD": LimitStateHazard(50.0, 50.0, 0.103, 2.32, 0.279),
        "SLV": LimitStateHazard(475.0, 475.0, *SLV),
        "SLC": LimitStateHazard(975.0, 975.0, *SLC),
    },
    (),
)
CFRP = Material("CFRP", 150.0, 0.013, 1550.0, 0.0)


def _soil_b_s(ag: float, f0: float) -> float:
    """S = S_S·S_T for subsoil B, T1 (S_T = 1)."""
    return min(1.2, max(1.0, 1.40 - 0.40 * f0 * ag))


def _inputs(state: str = "SLV", site: SiteHazard | None = SITE, **changes: object):
    ag, f0, tc = SITE[state].ag, SITE[state].F0, SITE[state].Tc_star
    base: dict[str, object] = {
        "thickness": B,
        "height": 3.0,
        "unit_weight": 18.0,
        "mechanism": "one-sided",
        "spectrum": ntc2018_spectrum(ag, f0, tc, "B", "T1", 0.05),
        "site": site,
        "site_limit_state": state,
        "records": ArtificialRecords(),
        "options": (RetrofitOption("CFRP external 1‰", CFRP, "external", 1.0),),
        "model": ModelOptions(pivot="edge"),
    }
    base.update(changes)
    return AssessmentInputs(**base)  # type: ignore[arg-type]


def test_the_slc_spectrum_is_built_from_the_slc_parameters_at_the_site():
    """S_S(SLC) = 1.40 − 0.40·2.408·0.327 = 1.085034 (in [1, 1.2]): a_g·S = 0.354806 g;
    SLV: 1.40 − 0.40·2.376·0.255 = 1.157648, a_g·S = 0.295200 g."""
    inputs = _inputs()
    slc = limit_state_spectrum(inputs, "SLC")
    assert slc.pga_g == pytest.approx(0.327 * 1.085034, rel=1e-6)
    assert slc.pga_g == pytest.approx(0.354806, rel=1e-5)
    assert limit_state_spectrum(inputs, "SLV").pga_g == pytest.approx(0.295200, rel=1e-5)
    # the assessment built for SLC: its SLV checks still take the SLV spectrum
    at_slc = _inputs("SLC")
    assert limit_state_spectrum(at_slc, "SLV").pga_g == pytest.approx(0.295200, rel=1e-5)
    assert limit_state_spectrum(at_slc, "SLC") is at_slc.spectrum


def test_nonlinear_static_slc_demand_is_read_on_the_slc_spectrum():
    """d_SLC demand = S_De(T_SLC) at 10 % damping of the SLC spectrum.  T_C = C_C·T_C* with
    C_C = 1.10·0.353^−0.2, T_D = 4·0.327 + 1.6 = 2.908 s > T_SLC = 2.737421 s > T_C, so
    Se = a_g·S·η·F0·T_C/T and S_De = a_g·S·η·F0·T_C·T·g/4π² (increasing in T: its largest
    value up to T_SLC is at T_SLC).  η(10 %) = √(10/15).  The SLV check keeps a_g·S of SLV."""
    ag, f0, tc_star = SLC
    s = _soil_b_s(ag, f0)
    t_c = 1.10 * tc_star**-0.20 * tc_star
    assert t_c < T_SLC < 4.0 * ag + 1.6
    eta = math.sqrt(10.0 / 15.0)
    demand = ag * s * eta * f0 * t_c * T_SLC * G / (4.0 * math.pi**2)
    checks = kinematic_checks(_inputs())
    urm = checks.cases[0]
    assert urm.slc.d_limit == pytest.approx(D_SLC, rel=1e-5)
    assert urm.slc.period == pytest.approx(T_SLC, rel=1e-5)
    assert urm.slc.a_g == pytest.approx(ag * s, rel=1e-9)
    assert urm.slc.demand == pytest.approx(demand, rel=1e-5)
    assert urm.slc.a_g_capacity == pytest.approx(ag * s * D_SLC / demand, rel=1e-4)
    assert urm.slv.a_g == pytest.approx(SLV[0] * _soil_b_s(SLV[0], SLV[1]), rel=1e-9)
    # the linear check is an SLV check: a_g·S of SLV over q = 2
    assert urm.linear.demand == pytest.approx(urm.slv.a_g / 2.0, rel=1e-9)


def test_time_history_slc_motions_reach_the_slc_pga():
    """Each record of the SLC time-history check has PGA = a_g,SLC·S_SLC = 0.354806 g (in
    m/s²: ×g), those of SLV 0.295200 g; a recorded set is scaled, not regenerated."""
    t = np.arange(0.0, 2.0, 0.01)
    record = Record("r", 0.01, 0.7 * np.sin(2.0 * np.pi * t) * np.exp(-t))
    inputs = _inputs(records=(RecordFile("r.txt"),))
    assert not spectrum_compatible_records(inputs, "SLC")
    demands = limit_state_demands(inputs, [record], None)
    for state, pga in (("SLC", 0.354806), ("SLV", 0.295200)):
        motions = demands[state].motions
        assert motions is not None
        ((acc, dt),) = motions
        assert dt == 0.01
        assert float(np.max(np.abs(acc))) == pytest.approx(pga * G, rel=1e-5)


def test_artificial_records_of_the_slc_spectrum_only_with_the_site_known():
    """A set of its own for SLC: the site known, artificial records, SLC not the state the
    assessment's set was generated for."""
    assert spectrum_compatible_records(_inputs(), "SLC")
    assert not spectrum_compatible_records(_inputs(), "SLV")
    assert spectrum_compatible_records(_inputs("SLC"), "SLV")
    assert not spectrum_compatible_records(_inputs(site=None), "SLC")


def test_the_ida_capacity_demand_at_each_limit_state():
    """a_dyn/(FC·a_g·S) with the mean a_dyn 0.6 g, FC = 1.35 (LC1): at SLV 0.6/(1.35·0.295200)
    = 1.505570, at SLC 0.6/(1.35·0.354806) = 1.252637; the deciding line is the
    assessment's limit state's (SLV here)."""
    checks = kinematic_checks(_inputs(), ida={"Unreinforced": IdaSummary(0.6, 0.5, 7)})
    urm = checks.cases[0]
    assert urm.ida is not None and urm.ida.limit_state == "SLV"
    assert urm.ida.zeta_e == pytest.approx(1.505570, rel=1e-5)
    slv, slc = urm.ida_limit_states
    assert (slv.limit_state, slc.limit_state) == ("SLV", "SLC")
    assert slv.zeta_e == pytest.approx(1.505570, rel=1e-5)
    assert slc.zeta_e == pytest.approx(1.252637, rel=1e-5)
    assert [i.source for i in checks.intensities] == ["site", "site"]
    assert checks.intensities[1].a_g_s == pytest.approx(0.354806, rel=1e-5)
    assert checks.intensities[1].ag == SLC[0] and checks.intensities[1].F0 == SLC[1]


def test_a_typed_spectrum_says_one_spectrum():
    """Given by its parameters (no site): SLV and SLC both at its a_g·S, and the results say
    so (source "typed", the sentence "One spectrum")."""
    spectrum = ElasticSpectrum("test", "ec8", 0.25, 0.15, 0.5, 1.5)
    inputs = _inputs(site=None, spectrum=spectrum)
    assert not own_spectra(inputs)
    checks = kinematic_checks(inputs, ida={"Unreinforced": IdaSummary(0.6, 0.5, 7)})
    assert [i.source for i in checks.intensities] == ["typed", "typed"]
    assert [i.a_g_s for i in checks.intensities] == [0.25, 0.25]
    assert checks.intensity_basis.startswith("One spectrum is given")
    urm = checks.cases[0]
    assert urm.slv.a_g == urm.slc.a_g == 0.25
    assert urm.ida is not None and urm.ida.demand == 0.25


def _evidence(peaks: tuple[float, ...], peaks_slc: tuple[float, ...] | None) -> Evidence:
    return Evidence(
        name="A",
        cost=1.0,
        mass=1.0,
        a_dyn=(0.6,) * 7,
        censored=(False,) * 7,
        demand=0.3,
        target=1.0,
        peaks=peaks,
        d0=0.2,
        d_slv=0.08,
        d_slc=0.12,
        peaks_slc=peaks_slc,
    )


def test_the_slc_time_history_decides_on_its_own_peaks():
    """SLV peaks 0.02 m (margin min(0.08/0.02, 0.2/0.02) = 4); SLC peaks 0.15 m under the
    stronger SLC motions: mean 0.15 > d_SLC = 0.12 m, margin 0.12/0.15 = 0.8, fails and
    governs.  Without SLC peaks of its own, SLC reads the SLV peaks: 0.12/0.02 = 6, passes."""
    v = verdict(_evidence((0.02,) * 7, (0.15,) * 7))
    by_name = {c.name: c for c in v.checks}
    assert by_name[TH_SLV].passed and by_name[TH_SLV].margin == pytest.approx(4.0)
    assert not by_name[TH_SLC].passed
    assert by_name[TH_SLC].margin == pytest.approx(0.8)
    assert v.governing_check == TH_SLC and not v.passes
    one = {c.name: c for c in verdict(_evidence((0.02,) * 7, None)).checks}
    assert one[TH_SLC].passed and one[TH_SLC].margin == pytest.approx(6.0)


def test_the_slc_set_is_generated_for_the_slc_spectrum():
    """Artificial records with the site known: a set of their own for SLC only (SLV is the
    assessment's), whose mean PGA reaches a_g·S of SLC, 0.354806 g (EC8 §3.2.3.1.2(4)b, the
    generator's set factor), and which is checked against the SLC spectrum."""
    inputs = _inputs(records=ArtificialRecords(count=3, seed=5, duration=25.0, dt=0.02))
    own = state_records(inputs)
    assert list(own) == ["SLC"] and len(own["SLC"]) == 3
    assert all(r.dt == 0.02 for r in own["SLC"])
    assert sum(r.pga_g for r in own["SLC"]) / 3 >= 0.354806 * (1 - 1e-6)
    checks = kinematic_checks(inputs, state_records=own)
    slv, slc = checks.intensities
    assert slv.records_compliant is None and slc.records_compliant is True
    assert "records/SLC/" in slc.records and "seed 5" in slc.records
