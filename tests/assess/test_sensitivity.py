"""The sensitivity of the assessed option to the model conventions (issue 16 §3): each variant
changes exactly one convention, the first row is the case itself, and a rerun reuses the cache."""

from __future__ import annotations

from dataclasses import replace

import pytest

from frp_assess.api import run_assessment
from frp_assess.assess.cache import IdaCache
from frp_assess.assess.convention_sensitivity import convention_variants
from frp_assess.assess.runner import IdaRunner
from frp_assess.dynamics import ida
from tests.assess.test_floor_input import RECORDS
from tests.assess.test_run import small_inputs


def test_variants_change_one_convention_each():
    inputs = small_inputs()
    model = inputs.case_models()[1]  # GFRP external 1 ‰
    every = convention_variants(model, inputs.ida)
    variants = {v.label: v.model for v in every}
    base = variants.pop("as assessed")
    assert base is model
    # the numerical spread (effective capacity, docs/model.md §11): the same model, the run's
    # sampling with its ladder shifted by half a step; every other variant runs the run's
    assert inputs.ida.capacity == "effective"
    step = next(v for v in every if v.settings is not None)
    shifted = replace(inputs.ida, offset=0.5)
    assert step.model is model and step.label.startswith("numerical spread: ")
    assert step.label.endswith("(offset 0.5)")
    assert step.settings == shifted
    assert sum(v.settings is not None for v in every) == 1
    # with the first collapse (§5): the hunt at √s
    first = replace(inputs.ida, capacity="first-collapse")
    hunt = next(v for v in convention_variants(model, first) if v.settings is not None)
    finer = replace(first, step_ratio=first.step_ratio**0.5)
    assert hunt.label == f"IDA step ratio s = {finer.step_ratio:.4g}"
    assert hunt.settings == finer
    o = model.options
    assert variants["restitution: velocity"].options == o.__class__(
        **{**o.__dict__, "restitution": "velocity"}
    )
    assert variants["collapse: end-of-record"].options.collapse == "end-of-record"
    assert variants["collapse: first-exceedance"].options.collapse == "first-exceedance"
    assert variants["rupture: velocity-continuous"].options.rupture == "velocity-continuous"
    assert variants["strain factor c = 1"].rebars.strain_factor == 1.0
    e = model.rebars.elastic_modulus
    moduli = sorted(m.rebars.elastic_modulus for k, m in variants.items() if k.startswith("E "))
    assert moduli == pytest.approx([0.9 * e, 1.1 * e])
    for m in variants.values():  # the wall and the record set stay the same
        assert m.wall == model.wall and m.mechanism == model.mechanism


def test_variants_every_case_has_come_first_in_the_same_order():
    """The recommendation's i-th variant is matched with another option's i-th (the option
    that takes over under a convention): the unreinforced wall's variants are a prefix."""
    inputs = small_inputs()
    urm, gfrp = inputs.case_models()[0], inputs.case_models()[1]
    bare = [v.label for v in convention_variants(urm, inputs.ida)]
    assert [v.label for v in convention_variants(gfrp, inputs.ida)][: len(bare)] == bare


def test_sensitivity_in_results_and_cached(tmp_path):
    inputs = small_inputs()
    results, first = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    sens = results.sensitivity
    case = next(c for c in results.cases if c.name == sens.case)
    assert case.rank == 1 or results.recommended is None
    row0 = sens.rows[0]
    assert row0.variant == "as assessed"
    assert row0.design_a_dyn == case.design_a_dyn
    assert row0.capacity_demand == case.capacity_demand
    assert len(sens.rows) == len(convention_variants(inputs.case_models()[1], inputs.ida))
    # the numerical spread is one of the rows (and of the conventions of the robustness check)
    assert sum(r.variant.startswith("numerical spread: ") for r in sens.rows) == 1
    conventions = [c.variant for c in results.robustness.conventions]
    assert conventions == [r.variant for r in sens.rows]
    _, again = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    assert again.computed == 0


def test_runner_runs_a_search_of_its_own_when_given_one(tmp_path):
    """``IdaRunner.run(settings=...)`` searches with those settings, as ``ida`` itself does with
    them (more time histories on the ladder at √r), and keys them apart from the run's in the
    cache."""
    inputs = small_inputs()
    model = inputs.case_models()[1]
    runner = IdaRunner(RECORDS[:1], inputs, IdaCache(tmp_path), jobs=1)
    finer = replace(inputs.ida, ladder_ratio=inputs.ida.ladder_ratio**0.5)
    [[coarse]] = runner.run([model])
    [[fine]] = runner.run([model], settings=finer)
    assert (runner.computed, runner.reused) == (2, 0)  # not the first one from the cache
    assert fine == ida(model, RECORDS[0].acc, RECORDS[0].dt, finer)
    assert coarse == ida(model, RECORDS[0].acc, RECORDS[0].dt, inputs.ida)
    assert fine.runs > coarse.runs
