"""Issue 15 wired into a run: FC in the IDA verdict, the building, the floor spectra, the floor
PGA of each record and the code's kinematic checks in the typed results (results.json)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from frp_assess.api import run_assessment
from frp_assess.assess.inputs import BuildingSettings, CodeCheckSettings
from frp_assess.results.json_io import from_json, to_json
from tests.assess.test_run import small_inputs

#: FC of knowledge level LC1, Circolare 2019 Tab. C8.5.IV (the rigid-block default)
FC_LC1 = 1.35


def _run(tmp_path, **kw):
    results, _ = run_assessment(
        small_inputs(**kw), tmp_path, jobs=2, pdf=False, write=False, created="x"
    )
    return results


@pytest.mark.slow
def test_fc_in_the_verdict_fails_a_case_that_passes_without_it(tmp_path):
    off = _run(tmp_path, code_check=CodeCheckSettings(fc_in_ida=False))
    urm_off = off.cases[0]
    assert urm_off.fc == 1.0
    assert urm_off.capacity_demand == pytest.approx(urm_off.design_a_dyn / off.demand.pga)
    # a target between a_dyn/(FC·a_g·S) and a_dyn/(a_g·S): met without FC, missed with it
    target = urm_off.capacity_demand / 1.15
    without = _run(tmp_path, code_check=CodeCheckSettings(fc_in_ida=False), target=target)
    with_fc = _run(tmp_path, code_check=CodeCheckSettings(fc_in_ida=True), target=target)
    assert without.cases[0].meets_target  # the IDA check; the time histories decide too
    assert without.retrofit_required == (not without.cases[0].passes)
    assert not with_fc.cases[0].meets_target and with_fc.retrofit_required
    for a, b in zip(without.cases, with_fc.cases, strict=True):
        assert b.fc == FC_LC1
        assert a.design_a_dyn == b.design_a_dyn  # the same IDAs
        assert b.capacity_demand == pytest.approx(a.capacity_demand / FC_LC1)
        assert b.improvement == a.improvement  # a ratio of a_dyn: FC cancels
        dropped = b.pivot is not None and b.pivot.dropped and not b.is_unreinforced
        assert b.meets_target == (b.capacity_demand >= target and not dropped)


@pytest.mark.slow
def test_knowledge_level_sets_the_fc_of_the_verdict(tmp_path):
    lc3 = _run(tmp_path, code_check=CodeCheckSettings(knowledge_level="LC3"))
    # LC3: FC = 1.00 (Circolare 2019 Tab. C8.5.IV)
    assert all(c.fc == 1.0 for c in lc3.cases)
    lc2 = _run(tmp_path, code_check=CodeCheckSettings(knowledge_level="LC2"))
    assert all(c.fc == 1.2 for c in lc2.cases)  # LC2: FC = 1.20


def test_kinematic_checks_use_the_run_ida(tmp_path):
    results = _run(tmp_path)
    kc = results.kinematic_checks
    assert kc is not None and kc.fc_in_ida and kc.fc == FC_LC1
    assert [c.case for c in kc.cases] == [c.name for c in results.cases]
    for checks, case in zip(kc.cases, results.cases, strict=True):
        ida = checks.ida
        # 3 records (< 7): the least favourable record decides, as the case's verdict
        assert ida.design_value == "least"
        assert ida.zeta_e == pytest.approx(case.capacity_demand)
        assert ida.zeta_e_mean == pytest.approx(case.mean_a_dyn / (FC_LC1 * results.demand.pga))
        assert checks.time_history is not None and len(checks.time_history.peaks) == 3
    assert kc.floor is None and results.building is None and results.floor_spectra is None
    assert all(r.floor_pga is None for c in results.cases for r in c.records)


def test_wall_above_ground_in_the_results(tmp_path):
    building = BuildingSettings(height=10.0, storeys=3, wall_base=9.0, period=0.28, damping=0.05)
    results, _ = run_assessment(
        replace(small_inputs(), building=building), tmp_path, pdf=False, created="x"
    )
    b = results.building
    assert b is not None
    assert b.gamma1 == pytest.approx(9.0 / 7.0)  # 3n/(2n+1), n = 3
    assert b.psi1 == pytest.approx(0.9) and b.z_over_h == pytest.approx(0.9)  # Z/H_b
    assert b.period == 0.28
    assert b.period_default == pytest.approx(0.05 * 10.0**0.75)  # C1·H_b^(3/4)
    assert "Z = 9 m" in b.shaken_by and "ground" in b.shaken_by
    fs = results.floor_spectra
    assert fs is not None and len(fs.records) == len(results.records)
    n = len(fs.periods)
    assert len(fs.mean) == len(fs.code) == len(fs.ground) == n
    for i in range(n):  # the mean is the mean of the records' own spectra
        assert fs.mean[i] == pytest.approx(sum(r[i] for r in fs.records) / len(fs.records))
    # the floor spectrum at Z of the code lies above the ground spectrum at T1
    k = fs.periods.index(0.28)
    assert fs.code[k] > fs.ground[k]
    for case in results.cases:
        for r in case.records:
            assert r.floor_pga is not None and r.floor_pga > r.pga  # the floor amplifies
    assert results.kinematic_checks.floor is not None
    assert results.kinematic_checks.floor.z_over_h == pytest.approx(0.9)
    # the linear check of code_check takes the demand at the wall's base, a_Z/q, as the
    # linear check of kinematic_checks (Circolare 2019 eq. C7.2.7; §C8.7.1.2.1.7)
    lin = results.kinematic_checks.cases[0].linear
    assert results.code_check.demand == pytest.approx(lin.demand, rel=1e-12)
    assert results.code_check.demand > results.demand.pga / results.code_check.behaviour_factor
    assert "a_Z/q" in results.code_check.note
    text = (tmp_path / "results.json").read_text()
    assert from_json(text) == results and to_json(results) == text
