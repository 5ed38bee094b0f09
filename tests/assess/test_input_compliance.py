"""A verdict rests on every record set it uses: the assessment's, and the set a limit state
generated for its own spectrum (the SLC time-history check decides too).  If either fails
the code's spectrum-compatibility checks (EC8 §3.2.3.1.2, NTC 2018 §3.2.3.6), the input is
not code-compliant and nothing is "recommended"; the CLI names the set that failed."""

from __future__ import annotations

from dataclasses import replace
from types import SimpleNamespace

import pytest

from frp_assess.assess.results import inputs_code_compliant
from frp_assess.numbers import noncompliant_sets, recommendation_label
from frp_assess.results.checks import KinematicChecks, LimitStateIntensity
from frp_assess.results.json_io import from_json
from tests.report.test_report import DATA


def _checks(slc_compliant: bool | None) -> KinematicChecks:
    states = (
        LimitStateIntensity("SLV", 0.30, None, None, None, None, "site", "records"),
        LimitStateIntensity("SLC", 0.36, None, None, None, None, "site", "records", slc_compliant),
    )
    return KinematicChecks("LC1", 1.35, "FC", True, 0.30, None, (), states, "")


@pytest.mark.parametrize(
    ("main", "slc", "expected"),
    [
        (True, None, True),  # the SLC check uses the assessment's set
        (True, True, True),
        (True, False, False),  # its own set fails: not compliant
        (False, True, False),
        (False, None, False),
    ],
)
def test_every_record_set_must_pass(main: bool, slc: bool | None, expected: bool):
    seismic = SimpleNamespace(compliance=SimpleNamespace(passed=main))
    assert inputs_code_compliant(seismic, _checks(slc)) is expected  # type: ignore[arg-type]
    assert inputs_code_compliant(seismic, None) is main  # type: ignore[arg-type]


def test_the_failing_set_is_named():
    base = from_json(DATA.read_text(encoding="utf-8"), file=str(DATA))
    assert base.compliance.passed
    slc_fails = replace(base, kinematic_checks=_checks(False), input_code_compliant=False)
    assert noncompliant_sets(slc_fails) == "the SLC records (records/SLC/)"
    assert recommendation_label(slc_fails).startswith("Best ranked")
    both = replace(slc_fails, compliance=replace(base.compliance, passed=False))
    assert noncompliant_sets(both) == "the records (table above) and the SLC records (records/SLC/)"
