"""Issue 16 §1–2 and issue 22 in the results: the compression at the base of each case is
recorded and no option is dropped for it (a toe that crushes is the IDA's failure mode), design
mode searches the whole range, the bars as built, the masonry strength and the failure modes
are in results.json, the report and the CLI.

References (hand calculations written here, docs/model.md §1.1): the weight W = w·B·H
[kN/m], the bar at rupture T_u = E·ρ·B·ε [kN/m] (E in GPa → ·10⁶ kN/m², ρ in ‰ → ·10⁻³),
the stress block x = N/(0.85·f_d·1 m) with f_d in MPa (·10³ kN/m²), and a_RM = g·(B − x_W)/H
with x_W of the weight alone.  The ranking rule is that of docs/results-json.md.
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.api import run_assessment
from frp_assess.assess.inputs import DesignRequest
from frp_assess.assess.results import case_failure_mode
from frp_assess.assess.runner import design_search
from frp_assess.cli.cmd_run import built_lines
from frp_assess.cli.ranking import dropped_lines, ranking_rows
from frp_assess.report import annex_as_built, pivot_section
from frp_assess.report.annex_design_tables import anchorage_table
from frp_assess.report.annex_result_tables import ranking_table
from frp_assess.report.lang import Lang
from frp_assess.report.pdf_document import build_report
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import AssessmentResult
from tests.assess.test_as_built import RatioRunner, inputs_of
from tests.assess.test_run import small_inputs

EN = Lang("en")

_CACHE: dict[str, AssessmentResult] = {}


def small_result(tmp_path: Path) -> AssessmentResult:
    """The small wall of tests/assess/test_run.py (B 0.3 m, H 3 m, w 18 kN/m³; GFRP external
    1 ‰ and CFRP centred 2 ‰), run once per session."""
    if "r" not in _CACHE:
        _CACHE["r"], _ = run_assessment(
            small_inputs(), tmp_path, jobs=2, pdf=False, created="2026-01-01", write=False
        )
    return _CACHE["r"]


def test_the_base_of_each_case_by_hand_and_every_option_is_ranked(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    m = r.masonry_strength
    assert m is not None and m.f_d == pytest.approx(m.f_m / m.confidence_factor)
    b, h, w = 0.3, 3.0, 18.0
    weight = w * b * h  # 16.2 kN/m
    block = 0.85 * m.f_d * 1e3  # kN/m² over 1 m of wall
    for case, distance in zip(r.options, (b, b / 2), strict=True):  # external, centred
        built = case.as_built
        assert built is not None and case.pivot is not None
        s = built.strain
        eps = s.cyclic_factor * (
            s.eta_a * s.characteristic / s.partial_factor  # type: ignore[operator]
            if s.design_values
            else s.mean
        )
        mat = r.materials[case.material or ""]
        t_u = mat.elastic_modulus * 1e6 * case.ratio * 1e-3 * b * eps
        x = (weight + t_u) / block
        assert case.pivot.force == pytest.approx(weight + t_u, rel=1e-9)
        assert case.pivot.depth == pytest.approx(x, rel=1e-9)
        assert not case.pivot.dropped and case.rank is not None
        assert ("the toe crushes before the bar breaks" in case.pivot.reason) == (x >= distance)
    # every case turns about its corner: q = a_dyn / a_RM with a_RM = (B − x_W)/H [g], x_W of
    # the weight alone, for the unreinforced wall and every option alike
    a_rm = (b - weight / block) / h
    assert r.wall.a_rm == pytest.approx(a_rm, rel=1e-9)
    for case in r.cases:
        assert case.mean_q == pytest.approx(case.mean_a_dyn / a_rm, rel=1e-9)
    for case in r.cases:  # the reaction at rest acts at x_W/2 from the corner
        assert case.pivot is not None
        assert case.pivot.pivot_shift == pytest.approx(weight / block / 2, rel=1e-9)


def test_failure_modes_per_record_and_per_case(tmp_path: Path) -> None:
    """Every collapsed record names its failure mode; the case's is the most frequent."""
    r = small_result(tmp_path)
    modes = {"overturning", "rupture then overturning", "crushing", "rupture then crushing"}
    for case in r.cases:
        for rec in case.records:
            assert (rec.failure_mode is None) == (rec.collapse_multiplier is None)
            assert rec.failure_mode is None or rec.failure_mode in modes
        found = [rec.failure_mode for rec in case.records if rec.failure_mode is not None]
        if found:
            assert found.count(case.failure_mode) == max(found.count(f) for f in set(found))
    assert {rec.failure_mode for rec in r.urm.records} <= {"overturning", None}
    # an invented case: a tie goes to the least favourable record's mode
    rec = r.urm.records[0]
    tied = (
        replace(rec, a_dyn=0.3, failure_mode="overturning"),
        replace(rec, a_dyn=0.2, failure_mode="crushing"),
    )
    assert case_failure_mode(tied) == "crushing"
    assert case_failure_mode((replace(rec, a_dyn=None, failure_mode=None),)) is None


def test_a_file_with_a_dropped_option_still_reads_and_shows_why(tmp_path: Path) -> None:
    """No run drops an option for its base any more (docs/model.md §1.1), but a results file
    written when options were dropped still shows the reason and gives that option no rank."""
    r = small_result(tmp_path)
    urm, a, b = (replace(c, rank=None) for c in r.cases)
    assert a.pivot is not None
    holds = replace(a.pivot, dropped=False)
    fails = replace(a.pivot, dropped=True, reason="B: x/B = 0.600; dropped: too deep")
    # b would rank first (cheapest, meets the target) but fails the pivot check
    a = replace(a, capacity_demand=4.0, meets_target=True, frp_cost=50.0, pivot=holds)
    b = replace(b, capacity_demand=5.0, meets_target=True, frp_cost=1.0, pivot=fails)
    # the decision gives b no rank (tests/assess/test_decision.py): a is the first
    ranked, best = (urm, replace(a, rank=1), b), a.name
    # the reason is shown: CLI ranking and summary line, report ranking table
    result = replace(r, cases=ranked, recommended=best)
    rows = ranking_rows(result)
    assert [row[0] for row in rows] == ["—", "1", "dropped"]
    assert dropped_lines(result) == ["B: x/B = 0.600; dropped: too deep"]
    assert [row[0] for row in ranking_table(result, EN).rows] == ["—", "1", "dropped"]
    assert annex_as_built.dropped_reasons(result, EN) == ["B: x/B = 0.600; dropped: too deep"]
    # the pivot table states how each record's collapse ended, not "holds"/"dropped"
    # (issue 39: "holds" beside options whose every record fails by crushing)
    pivot_rows = pivot_section.pivot_table(result, EN).rows
    assert [row[0] for row in pivot_rows] == [c.name for c in result.cases]
    for row, case in zip(pivot_rows, result.cases, strict=True):
        assert row[-1] == pivot_section.modes_text(case, EN)
        assert "holds" not in row[-1] and "dropped" not in row[-1]


def test_new_fields_round_trip_and_old_files_still_read(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    assert r.urm.ratio_asked is None and r.urm.as_built is None and r.urm.pivot is not None
    for case, asked in zip(r.options, (1.0, 2.0), strict=True):
        built = case.as_built
        assert built is not None and case.ratio_asked == asked
        assert built.ratio_asked == asked and case.ratio == built.ratio_model
        # quantities of the bars as built: n bars of H + 2·bond length, mass over the wall
        assert case.frp_mass == built.mass
        assert case.frp_mass_per_m == pytest.approx(built.mass / 5.0)
        assert built.metres == pytest.approx(built.total_bars * built.bar_length)
    text = to_json(r)
    assert from_json(text, file="results.json") == r
    # a file written before these fields: they read as None
    d = json.loads(text)
    del d["masonry_strength"]
    for c in d["cases"]:
        for k in ("ratio_asked", "as_built", "pivot"):
            del c[k]
    old = from_json(json.dumps(d), file="results.json")
    assert old.masonry_strength is None and old.cases[1].pivot is None
    assert old.cases[1].as_built is None and old.cases[1].ratio_asked is None


def test_design_mode_searches_past_the_old_pivot_cap() -> None:
    # B = 0.2 m, H = 3 m, L = 1 m, solid brick (LC default), GFRP centred, crushing pivot:
    # the old drop rule kept a model ratio only while x < B/2; the search now goes beyond it
    inputs = inputs_of("  []", b=0.2, length=1.0)
    inputs = replace(inputs, design=DesignRequest((), ("centred",), (0.5, 20.0), 0.5))
    gfrp = inputs_of("  - {material: GFRP, position: centred, ratio: 1}").options[0].material
    assert inputs.model.pivot == "crushing"
    weight = inputs.unit_weight * 0.2 * 3.0
    eps = inputs.rupture_strain(gfrp)
    f_d = inputs.masonry_strength.f_d
    top = (0.85 * f_d * 1e3 * 0.1 - weight) / (gfrp.elastic_modulus * 1e6 * 0.2 * eps * 1e-3)
    assert 0.5 < top < 20.0  # the old cap was inside the range
    runner = RatioRunner()
    res = design_search(runner, inputs, gfrp, "centred", 100.0)  # type: ignore[arg-type]
    assert res.ratio is None  # the target is never met
    assert runner.ratios and max(runner.ratios) > top
    assert "pivot check" not in res.message


def test_the_report_sections_render(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    ext = r.options[0].as_built
    assert ext is not None
    # the layout in words, as the layout's numbers say: n × Ød per face at s m
    assert annex_as_built.layout_text(ext, EN) == (
        f"{ext.bars_per_line} × Ø{ext.diameter:g} per face (2 faces) at {ext.spacing:.3f} m "
        f"({2 * ext.bars_per_line} bars)"
    )
    flow = annex_as_built.section(r, EN)
    text = " ".join(getattr(f, "text", "") or getattr(f, "markup", "") for f in flow)
    assert "The retrofit as built" in text and "The masonry at the base" in text
    assert "c·η_a·ε_fk/γ_f" in text or "mean producer values" in text
    assert len(annex_as_built.layout_table(r, EN).rows) == 2
    anchorage = anchorage_table(r, EN)
    assert anchorage is not None
    assert [row[0] for row in anchorage.rows] == [c.name for c in r.options]
    out = tmp_path / "report.pdf"
    build_report(r, out)
    assert out.stat().st_size > 10_000
    # results without the new fields: the section says the strength is missing, no crash
    bare = dataclasses.replace(
        r,
        masonry_strength=None,
        cases=tuple(replace(c, as_built=None, pivot=None) for c in r.cases),
    )
    assert annex_as_built.section(bare, EN) == []
    assert math.isfinite(r.urm.mean_q)


def test_the_cli_says_how_the_recommended_option_is_built(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    first = r.options[0]
    assert first.as_built is not None
    lines = built_lines(replace(r, recommended=first.name, retrofit_required=True))
    assert lines == [f"  built as {first.as_built.note}; {first.as_built.anchorage.note}"]
    # a wall that needs no retrofit: the cheapest passing option "if installed"
    optional = built_lines(replace(r, recommended=first.name, retrofit_required=False))
    assert optional == [
        f"  {first.name}, if installed: built as {first.as_built.note}; "
        f"{first.as_built.anchorage.note}"
    ]
    assert built_lines(replace(r, recommended=None)) == []
