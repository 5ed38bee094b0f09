"""The sensitivity of the assessed option to the model conventions (issue 16 §3): each variant
changes exactly one convention, the first row is the case itself, and a rerun reuses the cache."""

from __future__ import annotations

import pytest

from frp_assess.api import run_assessment
from frp_assess.assess.convention_sensitivity import convention_variants
from tests.assess.test_run import small_inputs


def test_variants_change_one_convention_each():
    inputs = small_inputs()
    model = inputs.case_models()[1]  # GFRP external 1 ‰
    variants = dict(convention_variants(model))
    base = variants.pop("as assessed")
    assert base is model
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
    assert len(sens.rows) == len(convention_variants(inputs.case_models()[1]))
    _, again = run_assessment(inputs, tmp_path, jobs=2, pdf=False, write=False)
    assert again.computed == 0
