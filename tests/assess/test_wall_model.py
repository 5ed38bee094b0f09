"""One builder of the wall model (assess/wall_model.py): run, study, ida/simulate and the TUI's
preview build the same model of the same case (docs/model.md §1.1).

Before it, the study and the TUI's preview built their walls without f_d, so that
``pivot: crushing`` silently ran (and showed) the edge pivot.  Hand values: rubble stone at
LC1, f_m = 1.0 MPa (Circolare 2019 Tab. C8.5.I, minimum), FC = 1.35 (Tab. C8.5.IV), so
f_d = 1.0/1.35 = 0.7407 MPa; B = 0.4 m, H = 3 m, w = 19 kN/m³: W = 19·0.4·3 = 22.8 kN/m,
x_W = W/(0.85·f_d) = 22.8/629.63 = 0.036212 m, a_RM = (B − x_W)/H = 0.121263 g.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

import pytest

from frp_assess.assess.from_project import inputs_from_project
from frp_assess.assess.wall_model import WallInput, base_problem, rocking_model
from frp_assess.cli.wall_args import build_model
from frp_assess.config import Project
from frp_assess.dynamics import ModelOptions
from frp_assess.errors import InputError
from frp_assess.study import parse_study
from frp_assess.study.plan import StudyPlan
from frp_assess.tui.core.editor_state import wall_derived

F_D = 1.0 / 1.35  # [MPa]
X_W = 19.0 * 0.4 * 3.0 / (0.85 * F_D * 1e3)  # [m]


def project(pivot: str = "crushing", **wall: Any) -> dict[str, Any]:
    return {
        "project": {"name": "one builder"},
        "wall": {
            "thickness": 0.4,
            "height": 3.0,
            "masonry": "rubble-stone",
            "mechanism": "one-sided",
            **wall,
        },
        "seismic": {
            "spectrum": {"type": "preset", "name": "A2"},
            "records": {"artificial": {"count": 1, "seed": 1, "duration": 14.0}},
        },
        "interventions": [{"material": "GFRP", "position": "centred", "ratio": 1.0}],
        "analysis": {"pivot": pivot},
        "bars": {"design_values": False, "whole_bars": False},
    }


def study(pivot: str = "crushing") -> dict[str, Any]:
    return {
        "name": "one builder",
        "height": [3.0],
        "thickness": [0.4],
        "ratio": [1.0],
        "material": ["GFRP"],
        "position": ["centred"],
        "mechanism": ["one-sided"],
        "spectrum": ["A2"],
        "unit_weight": 19.0,
        "masonry": "rubble-stone",
        "model": {"pivot": pivot},
    }


def run_inputs(data: dict[str, Any]) -> Any:
    return inputs_from_project(Project.model_validate(data), Path("."))


def test_hand_values() -> None:
    model = run_inputs(project()).model_for(None)
    assert model.wall.compressive_strength == pytest.approx(F_D * 1e6)
    assert X_W == pytest.approx(0.036212, abs=1e-6)
    assert model.a_rm_g == pytest.approx((0.4 - X_W) / 3.0)
    assert model.a_rm_g == pytest.approx(0.121263, abs=1e-6)


@pytest.mark.parametrize("pivot", ["crushing", "edge"])
def test_a_study_builds_the_runs_model(pivot: str) -> None:
    """The study's case and the run's case: the same wall (with f_d), bars and options."""
    inputs = run_inputs(project(pivot))
    plan = StudyPlan(parse_study(study(pivot)))
    urm, gfrp = plan.case(0), plan.case(1)
    assert plan.model(urm) == inputs.model_for(None)
    assert plan.model(gfrp) == inputs.model_for(inputs.options[0])
    assert plan.model(urm).a_rm_g == inputs.model_for(None).a_rm_g
    assert plan.model(gfrp).K == inputs.model_for(inputs.options[0]).K
    if pivot == "crushing":  # the bug: the study's wall had no f_d and turned about its edge
        assert plan.model(urm).a_rm_g == pytest.approx((0.4 - X_W) / 3.0)
    else:
        assert plan.model(urm).a_rm_g == pytest.approx(0.4 / 3.0)


def test_a_study_takes_the_projects_strength_rules() -> None:
    """f_m given wins over the masonry type; LC2 takes the mean and FC = 1.20; neither: the
    lowest f_m of the table (1.0 MPa), as a project."""
    given = StudyPlan(parse_study({**study(), "compressive_strength": 2.4}))
    assert given.design_strength == pytest.approx(2.4 / 1.35)
    lc2 = StudyPlan(parse_study({**study(), "knowledge_level": "LC2"}))
    assert lc2.design_strength == pytest.approx(1.5 / 1.20)  # rubble stone 1.0–2.0 MPa
    bare = {k: v for k, v in study().items() if k != "masonry"}
    assert StudyPlan(parse_study(bare)).design_strength == pytest.approx(1.0 / 1.35)


@pytest.mark.parametrize("pivot", ["crushing", "edge"])
def test_the_tui_preview_shows_the_runs_a_rm(pivot: str) -> None:
    data = project(pivot)
    derived = wall_derived(data["wall"], data["analysis"], data.get("code_check"))
    assert not isinstance(derived, str)
    model = run_inputs(data).model_for(None)
    assert derived.a_rm == model.a_rm_g
    assert derived.depth == (pytest.approx(X_W) if pivot == "crushing" else 0.0)
    lc3 = {**data, "code_check": {"knowledge_level": "LC3"}}
    d3 = wall_derived(lc3["wall"], lc3["analysis"], lc3["code_check"])
    assert not isinstance(d3, str)
    assert d3.a_rm == run_inputs(lc3).model_for(None).a_rm_g


def test_the_command_line_builds_through_the_builder_at_the_edge() -> None:
    """ida/simulate have no masonry strength: f_d infinite, the edge pivot."""
    args = argparse.Namespace(
        thickness=0.4, height=3.0, unit_weight=19.0, mechanism="one-sided",
        modulus=46.0, ultimate_strain=0.015, position="centred", ratio=1.0,
        strain_factor=0.5, restitution="energy", rupture="energy-transfer",
        collapse="overturning", tail=0.0, rtol=1e-8,
    )  # fmt: skip
    model = build_model(args)
    edge = run_inputs(project("edge"))
    assert math.isinf(model.wall.compressive_strength)
    assert model.a_rm_g == edge.model_for(None).a_rm_g
    assert model.rebars == edge.model_for(edge.options[0]).rebars


def test_a_base_that_cannot_carry_the_weight_is_refused_everywhere() -> None:
    """f_m = 0.1 MPa: f_d = 0.0741 MPa, 0.85·f_d = 62.96 kPa < w·H = 18·4 = 72 kPa, so
    x_W = w·B·H/(0.85·f_d) = 1.144·B ≥ B."""
    weak = WallInput(0.3, 4.0, 18.0, 0.1 / 1.35)
    problem = base_problem(weak)
    assert problem is not None and "cannot carry the wall's weight" in problem
    assert base_problem(WallInput(0.3, 3.4, 18.0, 0.1 / 1.35)) is None  # 61.2 < 62.96 kPa
    with pytest.raises(InputError) as e:
        rocking_model(weak, "one-sided", None, ModelOptions())
    assert e.value.key == "wall.thickness" and "\n" not in str(e.value)
    data = project(compressive_strength=0.1, height=4.0, thickness=0.3, unit_weight=18.0)
    with pytest.raises(InputError, match="cannot carry the wall's weight"):
        run_inputs(data)
    with pytest.raises(InputError, match="cannot carry the wall's weight"):
        StudyPlan(
            parse_study(
                {**study(), "height": [4.0], "thickness": [0.3], "unit_weight": 18.0}
                | {"compressive_strength": 0.1}
            )
        )
    derived = wall_derived(data["wall"], data["analysis"])
    assert isinstance(derived, str) and "cannot carry the wall's weight" in derived
