"""Issue 16 §1–2 in the results: the pivot check drops options from the ranking (and says
why), design mode stops below the pivot's largest ratio, the bars as built and the masonry
strength are in results.json, the report and the CLI.

References (hand calculations written here, docs/model.md §1.1): the weight W = w·B·H
[kN/m], the bar at rupture T_u = E·ρ·B·ε [kN/m] (E in GPa → ·10⁶ kN/m², ρ in ‰ → ·10⁻³),
the stress block x = N/(0.85·f_d·1 m) with f_d in MPa (·10³ kN/m²), the crushing drop rule
x ≥ the bar's distance from the compressed edge (B/2 centred, B external), and a_RM about
the crushed pivot g·(B − x)/H.  The ranking rule is that of docs/results-json.md.
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
from frp_assess.assess.results import rank_cases
from frp_assess.assess.runner import design_search
from frp_assess.cli.run import built_lines, dropped_lines, ranking_rows
from frp_assess.report import as_built_section
from frp_assess.report.document import build_report
from frp_assess.report.tables import ranking_table
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import AssessmentResult
from tests.assess.test_as_built import RatioRunner, inputs_of
from tests.assess.test_run import small_inputs

_CACHE: dict[str, AssessmentResult] = {}


def small_result(tmp_path: Path) -> AssessmentResult:
    """The small wall of tests/assess/test_run.py (B 0.3 m, H 3 m, w 18 kN/m³; GFRP external
    1 ‰ and CFRP centred 2 ‰), run once per session."""
    if "r" not in _CACHE:
        _CACHE["r"], _ = run_assessment(
            small_inputs(), tmp_path, jobs=2, pdf=False, created="2026-01-01", write=False
        )
    return _CACHE["r"]


def test_the_pivot_check_of_each_case_by_hand_and_the_dropped_get_no_rank(
    tmp_path: Path,
) -> None:
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
        assert case.pivot.dropped == (x >= distance)
        assert (case.rank is None) == case.pivot.dropped
        if case.pivot.dropped:
            assert "dropped:" in case.pivot.reason
    # the unreinforced wall turns about the crushed pivot: q = a_dyn / a_RM with
    # a_RM = (B − x)/H [g], x of the weight alone
    urm = r.urm
    x0 = weight / block
    a_rm = (b - x0) / h
    assert r.wall.a_rm == pytest.approx(a_rm, rel=1e-9)
    assert urm.mean_q == pytest.approx(urm.mean_a_dyn / a_rm, rel=1e-9)
    assert urm.pivot is not None and urm.pivot.pivot_shift == pytest.approx(x0 / 2, rel=1e-9)


def test_ranking_drops_a_failing_option_and_says_why(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    urm, a, b = (replace(c, rank=None) for c in r.cases)
    assert a.pivot is not None
    holds = replace(a.pivot, dropped=False)
    fails = replace(a.pivot, dropped=True, reason="B: x/B = 0.600; dropped: too deep")
    # b would rank first (cheapest, meets the target) but fails the pivot check
    a = replace(a, capacity_demand=4.0, meets_target=True, frp_cost=50.0, pivot=holds)
    b = replace(b, capacity_demand=5.0, meets_target=True, frp_cost=1.0, pivot=fails)
    ranked, best = rank_cases((urm, a, b), target=3.0)
    assert [c.rank for c in ranked] == [None, 1, None]
    assert best == a.name
    # the same options with b standing: b first
    ranked2, best2 = rank_cases((urm, a, replace(b, pivot=holds)), target=3.0)
    assert [c.rank for c in ranked2] == [None, 2, 1] and best2 == b.name
    # the reason is shown: CLI ranking and summary line, report ranking table
    result = replace(r, cases=ranked, recommended=best)
    rows = ranking_rows(result)
    assert [row[0] for row in rows] == ["—", "1", "dropped"]
    assert dropped_lines(result) == ["B: x/B = 0.600; dropped: too deep"]
    assert [row[0] for row in ranking_table(result).rows] == ["—", "1", "dropped"]
    assert as_built_section.dropped_reasons(result) == ["B: x/B = 0.600; dropped: too deep"]
    pivot_rows = as_built_section.pivot_table(result.cases).rows
    assert [row[-1] for row in pivot_rows] == ["holds", "holds", "dropped"]


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


def test_design_mode_stops_below_the_pivots_largest_ratio() -> None:
    # B = 0.2 m, H = 3 m, L = 1 m, solid brick (LC default), GFRP centred, crushing pivot: a
    # model ratio is kept only while x < B/2, i.e. ρ < (0.85·f_d·10³·B/2 − W)/(E·10⁶·B·ε·10⁻³)
    inputs = inputs_of("  []", b=0.2, length=1.0)
    inputs = replace(inputs, design=DesignRequest((), ("centred",), (0.5, 20.0), 0.5))
    gfrp = inputs_of("  - {material: GFRP, position: centred, ratio: 1}").options[0].material
    assert inputs.model.pivot == "crushing"
    weight = inputs.unit_weight * 0.2 * 3.0
    eps = inputs.rupture_strain(gfrp)
    f_d = inputs.masonry_strength.f_d
    top = (0.85 * f_d * 1e3 * 0.1 - weight) / (gfrp.elastic_modulus * 1e6 * 0.2 * eps * 1e-3)
    assert 0.5 < top < 20.0  # the cap bites inside the range
    runner = RatioRunner()
    res = design_search(runner, inputs, gfrp, "centred", 100.0)  # type: ignore[arg-type]
    assert res.ratio is None  # the target is never met
    assert runner.ratios and max(runner.ratios) < top
    assert "pivot check (pivot: crushing)" in res.message and "below" in res.message
    # a demand met everywhere: the answer is the lower end, below the cap too
    runner2 = RatioRunner()
    ok = design_search(runner2, inputs, gfrp, "centred", 0.01)  # type: ignore[arg-type]
    assert ok.ratio == pytest.approx(0.5) and ok.ratio_model is not None
    assert ok.ratio_model < top


def test_the_report_sections_render(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    ext = r.options[0].as_built
    assert ext is not None
    # the layout in words, as the layout's numbers say: n × Ød per face at s m
    assert as_built_section.layout_text(ext) == (
        f"{ext.bars_per_line} × Ø{ext.diameter:g} per face (2 faces) at {ext.spacing:.3f} m "
        f"({2 * ext.bars_per_line} bars)"
    )
    flow = as_built_section.section(r)
    text = " ".join(getattr(f, "text", "") or getattr(f, "markup", "") for f in flow)
    assert "The retrofit as built" in text and "The masonry at the pivot" in text
    assert "c·η_a·ε_fk/γ_f" in text or "mean producer values" in text
    assert len(as_built_section.layout_table(r).rows) == 2
    assert [row[0] for row in as_built_section.anchorage_table(r).rows] == [
        c.name for c in r.options
    ]
    out = tmp_path / "report.pdf"
    build_report(r, out)
    assert out.stat().st_size > 10_000
    # results without the new fields: the section says the strength is missing, no crash
    bare = dataclasses.replace(
        r,
        masonry_strength=None,
        cases=tuple(replace(c, as_built=None, pivot=None) for c in r.cases),
    )
    assert as_built_section.section(bare) == []
    assert math.isfinite(r.urm.mean_q)


def test_the_cli_says_how_the_recommended_option_is_built(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    first = r.options[0]
    assert first.as_built is not None
    lines = built_lines(replace(r, recommended=first.name))
    assert lines == [f"  built as {first.as_built.note}; {first.as_built.anchorage.note}"]
    assert built_lines(replace(r, recommended=None)) == []
