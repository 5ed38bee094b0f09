"""The report's sentence on the action each limit state is checked at (report.annex_checks)."""

from __future__ import annotations

from types import SimpleNamespace

from frp_assess.report.annex_checks import intensities_text
from frp_assess.report.lang import Lang
from frp_assess.results.checks import KinematicChecks, LimitStateIntensity


def _results(source: str, slv: float, slc: float) -> SimpleNamespace:
    states = tuple(
        LimitStateIntensity(s, a, None, None, None, None, source, "records")
        for s, a in (("SLV", slv), ("SLC", slc))
    )
    kc = KinematicChecks("LC1", 1.35, "FC", True, slv, None, (), states, "")
    return SimpleNamespace(kinematic_checks=kc)


def test_each_limit_state_with_its_own_intensity_in_both_languages():
    """Site known: both a_g·S shown, 3 decimals, the language's decimal separator."""
    results = _results("site", 0.2952, 0.35481)
    en = intensities_text(results, Lang("en"))  # type: ignore[arg-type]
    assert "own spectrum" in en
    assert "SLV a<sub>g</sub>·S = 0.295 g; SLC a<sub>g</sub>·S = 0.355 g" in en
    it = intensities_text(results, Lang("it"))  # type: ignore[arg-type]
    assert "SLV a<sub>g</sub>·S = 0,295 g; SLC a<sub>g</sub>·S = 0,355 g" in it


def test_a_typed_spectrum_says_one_spectrum():
    results = _results("typed", 0.25, 0.25)
    en = intensities_text(results, Lang("en"))  # type: ignore[arg-type]
    assert en.startswith("One spectrum") and "0.250 g" in en
    assert "0,250 g" in intensities_text(results, Lang("it"))  # type: ignore[arg-type]


def test_results_without_intensities_have_no_sentence():
    results = SimpleNamespace(kinematic_checks=None)
    assert intensities_text(results, Lang("en")) == ""  # type: ignore[arg-type]
