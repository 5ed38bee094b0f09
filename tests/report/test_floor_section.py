"""The report's issue-15 parts (frp_assess.report.annex_floor): the wall above ground on page 1
and in §3.4 with the floor spectra, the code's checks in §4.4 and their verdicts in the summary,
FC in the capacity/demand wording.  Built on the fixture with the issue-15 fields added."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from reportlab.graphics.shapes import Drawing

from frp_assess.numbers import check_verdicts, checks_line, checks_summary, no_retrofit_caveats
from frp_assess.report import annex_floor, build_report, build_story
from frp_assess.report.annex_floor import linear_check
from frp_assess.report.lang import Lang
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import AssessmentResult, BuildingResult, FloorSpectraResult
from tests.report.test_checks_section import CHECKS
from tests.report.test_report import DATA, story_text

EN, IT = Lang("en"), Lang("it")
BUILDING = BuildingResult(
    height=9.0,
    storeys=3,
    wall_base=6.0,
    z_over_h=6.0 / 9.0,
    period=0.30,
    period_default=0.05 * 9.0**0.75,
    damping=0.05,
    gamma1=9.0 / 7.0,
    psi1=6.0 / 9.0,
    shaken_by="the wall's base at Z = 6 m moved with that floor; a_dyn in ground terms",
)
SPECTRA = FloorSpectraResult(
    periods=(0.05, 0.1, 0.3, 1.0),
    mean=(0.5, 0.8, 1.9, 0.2),
    code=(0.6, 0.9, 2.0, 0.3),
    ground=(0.4, 0.6, 0.6, 0.2),
    records=((0.4, 0.7, 2.1, 0.2), (0.6, 0.9, 1.7, 0.2)),
)


def _above_ground() -> AssessmentResult:
    base = from_json(DATA.read_text(encoding="utf-8"))
    urm = base.urm
    best = next(c for c in base.cases if c.rank == 1)
    checks = replace(
        CHECKS,
        cases=(
            replace(CHECKS.cases[0], case=urm.name),
            replace(CHECKS.cases[1], case=best.name),
        ),
    )
    records = tuple(replace(r, floor_pga=2.0 * r.pga) for r in urm.records)
    cases = tuple(
        replace(c, records=records if c is urm else c.records, fc=1.35) for c in base.cases
    )
    return replace(
        base, cases=cases, building=BUILDING, floor_spectra=SPECTRA, kinematic_checks=checks
    )


def test_story_states_the_floor_motion_the_checks_and_fc():
    results = _above_ground()
    text = story_text(build_story(results))
    page1 = text.split("B.2  Inputs")[0]
    assert "Wall above ground." in page1 and "Z = 6 m" in page1
    assert "2.00–2.00 times the ground records'" in page1  # floor_pga = 2·pga in the fixture
    assert "The code's checks" in page1
    assert (
        f"{EN.t('annex.urm')}: passes nonlinear SLC, IDA; fails linear, nonlinear SLV, "
        "time history" in page1
    )
    assert "B.3.4 The motion at the wall's base" in text
    assert "B.4.4 The code's kinematic checks of every case" in text
    assert "Knowledge level LC1, confidence factor FC = 1.35" in text
    assert "divided by the same confidence factor, FC = 1.35" in text
    assert "fc_in_ida" not in text  # the report names no key of the project file


def test_ground_level_results_have_none_of_it():
    base = from_json(DATA.read_text(encoding="utf-8"))
    text = story_text(build_story(base))
    assert "Wall above ground" not in text and "B.3.4 The motion" not in text
    assert "B.4.4 The code's kinematic" not in text
    # the fixture's cases have FC = 1 with knowledge level LC1 (FC 1.35)
    assert "is not divided by the confidence factor" in text


def test_floor_rows_say_whether_t1_is_the_default():
    rows = dict(annex_floor.floor_rows(_above_ground(), EN))
    # 0.30 s given; the default 0.05·9^0.75 = 0.2598 s is named beside it
    assert rows["first-mode period T_1"].startswith("0.300 s (given; the default")
    assert "0.260 s" in rows["first-mode period T_1"]
    default = replace(BUILDING, period=BUILDING.period_default)
    rows = dict(annex_floor.floor_rows(replace(_above_ground(), building=default), EN))
    assert "(default C1·H_b^0.75" in rows["first-mode period T_1"]


def test_floor_chart_is_drawn_only_with_the_spectra():
    assert isinstance(annex_floor.floor_spectra_chart(_above_ground(), EN), Drawing)
    assert annex_floor.floor_spectra_chart(replace(_above_ground(), floor_spectra=None), EN) is None


def test_the_italian_annex_rebuilds_the_floor_sentence_from_the_values():
    """The run's English sentence (building.shaken_by) is not copied into an Italian report:
    the annex says it from Z and the records' floor PGA (2·PGA in the fixture)."""
    text = annex_floor.floor_sentence(_above_ground(), IT)
    assert text is not None and "Z = 6 m" in text and "da 2,00 a 2,00 volte" in text
    assert BUILDING.shaken_by not in text
    rows = dict(annex_floor.floor_rows(_above_ground(), IT))
    assert rows["periodo del primo modo T_1"].startswith("0,300 s (assegnato")


def test_check_verdict_lines():
    urm_checks = CHECKS.cases[0]
    # the fixture of test_checks_section: linear fails, SLV fails, SLC passes, time history
    # fails (it fell), IDA passes on the mean
    assert check_verdicts(urm_checks) == [
        ("linear", False),
        ("nonlinear SLV", False),
        ("nonlinear SLC", True),
        ("time history", False),
        ("IDA", True),
    ]
    assert checks_line(urm_checks) == (
        "passes nonlinear SLC, IDA; fails linear, nonlinear SLV, time history"
    )
    # the annex says the console's line in words of the catalogue, in both languages
    assert annex_floor.checks_line(urm_checks, EN) == checks_line(urm_checks)
    assert annex_floor.checks_line(urm_checks, IT) == (
        "soddisfa non lineare SLC, IDA; non soddisfa lineare, non lineare SLV, analisi al passo"
    )
    results = _above_ground()
    rows = checks_summary(results)
    assert rows[0][0] == results.urm.name
    best = next(c for c in results.cases if c.rank == 1)
    assert rows[1][0].startswith(best.name + " (")


def test_no_retrofit_caveat_names_the_failing_code_checks():
    results = _above_ground()
    caveats = no_retrofit_caveats(results)
    assert any("linear, nonlinear SLV, time history" in c for c in caveats)


def test_above_ground_pdf_builds_and_the_fields_round_trip(tmp_path: Path):
    results = _above_ground()
    assert from_json(to_json(results)) == results
    out = tmp_path / "report.pdf"
    build_report(results, out)
    assert out.read_bytes().startswith(b"%PDF")


def test_linear_check_at_height_on_page_1():
    results = _above_ground()
    text = story_text(build_story(results))
    page1 = text.split("B.2  Inputs")[0]
    # the linear check of the checks' fixture: a0* = 0.098 g against a_Z/q = 0.125 g
    assert "a0* = 0.098 g against 0.125 g (ratio 0.78: not satisfied)" in page1
    ground = from_json(DATA.read_text(encoding="utf-8"))
    k = ground.code_check
    assert linear_check(ground).demand == k.demand and linear_check(ground).ratio == k.ratio
