"""The report states a_RM and the rupture strain as the model computed them.

With the crushing pivot (docs/model.md §1.1) results.json ``wall.a_rm`` is g·(B − x)/H, not
g·tan α; with design values (docs/model.md §2.1) the rupture strain is c·η_a·ε_fk/γ_f, not
c·ε_u (the report's §2.3 and §2.4 said c·ε_u for both, §4.1 g·tan α for both). References,
written here: the small wall of tests/assess/test_run.py (B = 0.3 m, H = 3 m) has
tan α = B/H = 0.1, so a_RM about its edge is 0.100 g, and about the crushed pivot (B − x)/H
with x the depth printed in the label (rounded to 1 mm: 0.001/3 g at most).
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.report import annex_input_tables as tb
from frp_assess.report import build_story, pivot_section
from frp_assess.results.model import AssessmentResult
from tests.report.test_report import EN, story_text
from tests.results.test_pivot_and_as_built import small_result


def edge_pivot(r: AssessmentResult) -> AssessmentResult:
    """The same results as if run with ``pivot: edge`` (a_RM = g·tan α = 0.1 g)."""
    cases = tuple(
        c
        if c.pivot is None
        else replace(c, pivot=replace(c.pivot, model_pivot="edge", pivot_shift=0.0))
        for c in r.cases
    )
    return replace(r, cases=cases, wall=replace(r.wall, a_rm=0.1))


def strain_values(r: AssessmentResult, design: bool) -> AssessmentResult:
    """The same results with ``bars.design_values`` set to ``design`` on every option."""
    cases = []
    for c in r.cases:
        if c.as_built is not None:
            strain = replace(c.as_built.strain, design_values=design)
            c = replace(c, as_built=replace(c.as_built, strain=strain))
        cases.append(c)
    return replace(r, cases=tuple(cases))


def test_crushing_pivot_a_rm_is_labelled_with_its_formula(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    label, value = tb.wall_property_rows(r, EN)[-1]
    assert "g·tan α" not in label
    m = re.search(r"g·\(B − x\)/H \(crushing pivot, x = (\d+) mm\)", label)
    assert m is not None, label
    x = int(m.group(1)) / 1000
    assert float(value.split()[0]) == pytest.approx((0.3 - x) / 3.0, abs=1e-3)
    text = story_text(build_story(r))
    assert "half the compressed zone under its weight" in text
    assert "crushed under its weight" not in text  # the base does not crush at rest
    assert "against g·tan α = 0.100 g about the edge" in text


def test_edge_pivot_a_rm_is_g_tan_alpha(tmp_path: Path) -> None:
    r = edge_pivot(small_result(tmp_path))
    label, value = tb.wall_property_rows(r, EN)[-1]
    assert label == "rocking activation a_RM = g·tan α"
    assert value == "0.100 g"
    assert "half the compressed zone under its weight" not in story_text(build_story(r))


def test_rupture_strain_words_follow_design_values(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    assert all(c.as_built is not None for c in r.options)
    design = strain_values(r, design=True)
    rows = dict((k, v) for k, v in tb.model_rows(design, EN) if isinstance(k, str))
    assert "cyclic strain factor c (ε_max = c·η_a·ε_fk/γ_f)" in rows
    text = story_text(build_story(design))
    assert "ε_max = c·η_a·ε_fk/γ_f with c = 0.5 (CNR-DT 200 design values" in text
    assert "ε_max = c·ε_u with c" not in text
    mean = strain_values(r, design=False)
    rows = dict((k, v) for k, v in tb.model_rows(mean, EN) if isinstance(k, str))
    assert "cyclic strain factor c (ε_max = c·ε_u)" in rows
    assert "ε_max = c·ε_u with c = 0.5 (mean values)" in story_text(build_story(mean))


def test_pivot_paragraph_states_the_rule_the_model_ran(tmp_path: Path) -> None:
    """docs/model.md §1.1 (issue 39: the paragraph described a model that no longer ran): the
    wall turns about its corner, the base reaction N = W + T(θ) acts at x/2 and follows the
    bars at every instant, the toe crushes when x reaches the acting bar, nothing is dropped;
    with the edge pivot the paragraph states the x/B = 0.10 limit (DEFAULT_PIVOT_LIMIT) at
    which the edge model overstates the lever arm, without dropping anything."""
    r = small_result(tmp_path)
    text = pivot_section.masonry_text(r, EN)
    assert "follows the bars at every instant" in text
    assert "the toe crushes" in text and "No option is dropped" in text
    assert "held for the whole" not in text and "sized on" not in text
    edge = replace(
        r,
        cases=tuple(
            c if c.pivot is None else replace(c, pivot=replace(c.pivot, rule="edge"))
            for c in r.cases
        ),
    )
    text = pivot_section.masonry_text(edge, EN)
    assert "deeper than x/B = 0.10" in text
    assert "dropped when" not in text and "stated fraction" not in text


def test_record_files_are_not_called_recorded_records(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    files = replace(r, seismic=replace(r.seismic, records_kind="recorded"))
    n = len(r.records)
    assert f"{n} records read from files, " in story_text(build_story(files))
    assert "recorded records" not in story_text(build_story(files))
    assert f"{n} artificial records, " in story_text(build_story(r))


def test_dropped_count_agrees_with_its_verb(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    n = len(r.options)
    # no option is dropped for its base any more (docs/model.md §1.1): every one is ranked
    assert sum(c.rank is None for c in r.options) == 0
    assert "fails the pivot check" not in story_text(build_story(r))
    one = replace(r, cases=(*r.cases[:-1], replace(r.cases[-1], rank=None)))  # an older file
    text = story_text(build_story(one))
    assert f"1 of {n} options fails the pivot check" in text
    assert "and is dropped from the ranking: see section B.6.4" in text
    every = replace(r, cases=(r.cases[0], *(replace(c, rank=None) for c in r.options)))
    assert f"{n} of {n} options fail the pivot check" in story_text(build_story(every))


def test_fc_sentence_does_not_contradict_its_knowledge_level(tmp_path: Path) -> None:
    """Circolare 2019 Tab. C8.5.IV: LC2 gives FC = 1.20; the report once printed
    "FC = 1.2 (LC2; ... uses LC1's FC = 1.35)", two values for one factor."""
    from frp_assess.report import body_front
    from frp_assess.report.doc_model import markup_text
    from frp_assess.report.lang import Lang

    r = small_result(tmp_path)
    assert r.kinematic_checks is not None
    lc2 = replace(
        r,
        cases=tuple(replace(c, fc=1.2) for c in r.cases),
        kinematic_checks=replace(r.kinematic_checks, knowledge_level="LC2", fc=1.2),
        masonry_strength=None,
    )
    text = " ".join(
        markup_text(getattr(b, "markup", "")) for b in body_front.knowledge_section(lc2, Lang())
    )
    assert "Knowledge level LC2, confidence factor FC = 1.2 " in text
    assert "divided by the same confidence factor, FC = 1.2:" in text
    assert "1.35" not in text.split("Circolare 2019 §C8.7.1.2.1.3")[0]
    # the LC1 rule is stated as not applying, with the FC that does apply (issue 39: "the FC
    # sentence cites LC1 beside FC = 1.2")
    assert "so the FC of the knowledge level reached applies: FC = 1.2 (LC2)" in text
