"""Good paths of the project file: template, defaults, libraries, expansion, round trip."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest
import yaml

import frp_assess
from frp_assess.cli import main
from frp_assess.config import (
    FRP_MATERIALS,
    MASONRY,
    Intervention,
    Project,
    dump_project,
    load_project,
    load_project_text,
    validate_data,
)
from frp_assess.config.schema import CONFIDENCE_FACTORS, format_ratio
from frp_assess.config.walls_file import PER_WALL_BLOCKS as PER_WALL
from frp_assess.errors import InputError

PACKAGE = Path(frp_assess.__file__).parent
TEMPLATE = PACKAGE / "templates" / "wall.yaml"
REPO = PACKAGE.parent

MINIMAL = """\
wall: {thickness: 0.3, height: 2.5, masonry: rubble-stone, mechanism: two-sided}
seismic:
  spectrum: {type: preset, name: A2}
"""


def minimal_data(**extra: object) -> dict[str, object]:
    data: dict[str, object] = {
        "wall": {"thickness": 0.4, "height": 3.0, "unit_weight": 18.0, "mechanism": "one-sided"},
        "seismic": {"spectrum": {"type": "ec8", "ag": 0.25, "ground": "B"}},
    }
    data.update(extra)
    return data


def test_template_loads_and_documents_every_top_level_key() -> None:
    loaded = load_project(TEMPLATE)
    project = loaded.project
    assert project.wall.thickness == 0.40 and project.wall.length == 6.0
    assert project.unit_weight_kn() == 18.0
    assert project.seismic.records.artificial is not None
    text = TEMPLATE.read_text(encoding="utf-8")
    for key in Project.model_fields:
        # an optional block without a default may be shown commented out
        assert f"\n{key}:" in text or f"\n# {key}:" in text, key


def test_repo_templates_symlink_points_at_the_package_template() -> None:
    link = REPO / "templates"
    if not link.exists():
        pytest.skip("not a source checkout")
    assert link.is_symlink() and not Path(link.readlink()).is_absolute()
    assert (link / "wall.yaml").read_bytes() == TEMPLATE.read_bytes()


def test_building_block_maps_onto_the_inputs() -> None:
    """T1 defaults to 0.05·H_b^0.75 (Circolare 2019 eq. C7.3.2): 0.05·10^0.75 = 0.28117 s."""
    from frp_assess.assess.from_project import inputs_from_project

    block = {"height": 10.0, "storeys": 3, "wall_base": 9.0}
    project = validate_data(minimal_data(building=block))
    b = inputs_from_project(project, Path(".")).building
    assert b is not None
    assert (b.height, b.storeys, b.wall_base, b.damping) == (10.0, 3, 9.0, 0.05)
    assert b.period == pytest.approx(0.28117, abs=5e-6)
    assert b.z_over_h == pytest.approx(0.9)
    given = validate_data(minimal_data(building={**block, "period": 0.4, "damping": 0.08}))
    b = inputs_from_project(given, Path(".")).building
    assert b is not None and (b.period, b.damping) == (0.4, 0.08)
    assert inputs_from_project(validate_data(minimal_data()), Path(".")).building is None


def test_defaults_of_optional_blocks() -> None:
    project = load_project_text(MINIMAL, "mini.yaml").project
    assert project.wall.length == 1.0
    assert project.unit_weight_kn() == MASONRY["rubble-stone"].unit_weight == 19.0
    rec = project.seismic.records
    assert rec.files is None and rec.scale_to_spectrum
    assert (rec.artificial.count, rec.artificial.seed) == (7, 1)
    assert (rec.artificial.duration, rec.artificial.dt) == (25.0, 0.005)
    assert project.seismic.t1 == 1.0
    a = project.analysis
    assert (a.restitution, a.rupture, a.collapse) == ("energy", "energy-transfer", "overturning")
    assert (a.strain_factor, a.free_vibration_tail, a.target) == (0.5, 0.0, 1.0)
    assert (a.ida.step_ratio, a.ida.tolerance, a.ida.max_multiplier) == (1.10, 0.005, 100.0)
    assert project.design is None
    assert project.code_check.knowledge_level == "LC1"
    assert project.code_check.behaviour_factor == 2.0
    assert project.code_check.confidence_factor == 1.35
    assert project.costs.currency == "EUR"
    assert project.expand_interventions() == []
    assert project.material_table() == FRP_MATERIALS


def test_explicit_unit_weight_wins_over_masonry() -> None:
    data = minimal_data()
    data["wall"] = {**data["wall"], "masonry": "soft-stone", "unit_weight": 14.0}
    assert validate_data(data).unit_weight_kn() == 14.0
    data["wall"].pop("unit_weight")
    assert validate_data(data).unit_weight_kn() == 16.0


def test_restitution_accepts_a_velocity_ratio() -> None:
    project = validate_data(minimal_data(analysis={"restitution": 0.9}))
    assert project.analysis.restitution == 0.9
    with pytest.raises(InputError, match="analysis.restitution"):
        validate_data(minimal_data(analysis={"restitution": 0}))


def test_sweep_expands_to_18_named_options() -> None:
    sweep = {
        "material": ["GFRP", "BFRP", "CFRP"],
        "position": ["centred", "external"],
        "ratio": [1, 2, 3],
    }
    project = validate_data(minimal_data(interventions=[{"sweep": sweep}]))
    options = project.expand_interventions()
    assert len(options) == 18
    assert all(isinstance(o, Intervention) for o in options)
    assert options[0] == Intervention(
        name="GFRP centred 1‰", material="GFRP", position="centred", ratio=1.0
    )
    assert options[-1].name == "CFRP external 3‰"
    assert len({o.name for o in options}) == 18


def test_expansion_drops_duplicates_keeping_the_first() -> None:
    items = [
        {"name": "my GFRP", "material": "GFRP", "position": "external", "ratio": 2.0},
        {"material": "GFRP", "position": "centred", "ratio": 1.5},
        {"sweep": {"material": ["GFRP"], "position": ["external"], "ratio": [1, 2, 2.0]}},
    ]
    options = validate_data(minimal_data(interventions=items)).expand_interventions()
    assert [o.name for o in options] == ["my GFRP", "GFRP centred 1.5‰", "GFRP external 1‰"]


def test_two_different_options_with_one_name_are_rejected() -> None:
    items = [
        {"name": "A", "material": "GFRP", "position": "external", "ratio": 2.0},
        {"name": "A", "material": "CFRP", "position": "external", "ratio": 2.0},
    ]
    with pytest.raises(InputError, match=r"interventions\[1\]: two different options"):
        validate_data(minimal_data(interventions=items))


@pytest.mark.parametrize(("ratio", "text"), [(1.0, "1"), (1.5, "1.5"), (0.25, "0.25"), (10, "10")])
def test_format_ratio(ratio: float, text: str) -> None:
    assert format_ratio(ratio) == text


def test_material_overrides_and_additions() -> None:
    materials = {
        "GFRP": {"price": 6.5},
        "CFRP-HM": {"elastic_modulus": 210, "ultimate_strain": 0.008, "density": 1600, "price": 35},
    }
    items = [{"material": "CFRP-HM", "position": "external", "ratio": 1}]
    project = validate_data(minimal_data(materials=materials, interventions=items))
    table = project.material_table()
    assert list(table) == ["GFRP", "BFRP", "CFRP", "CFRP-HM"]
    assert table["GFRP"].price == 6.5
    assert table["GFRP"].elastic_modulus == 46.0
    assert table["GFRP"].source == FRP_MATERIALS["GFRP"].source
    assert table["CFRP-HM"].elastic_modulus == 210.0 and table["CFRP-HM"].source == "user input"


def test_library_values() -> None:
    g, b, c = FRP_MATERIALS["GFRP"], FRP_MATERIALS["BFRP"], FRP_MATERIALS["CFRP"]
    assert (g.elastic_modulus, g.ultimate_strain, g.density, g.price) == (46, 0.015, 2000, 8)
    assert (b.elastic_modulus, b.ultimate_strain, b.density, b.price) == (50, 0.020, 2000, 10)
    assert (c.elastic_modulus, c.ultimate_strain, c.density, c.price) == (150, 0.013, 1550, 35)
    assert all("indicative" in m.description and m.source for m in FRP_MATERIALS.values())
    weights = {k: m.unit_weight for k, m in MASONRY.items()}
    assert weights == {
        "rubble-stone": 19,
        "roughly-cut-stone": 20,
        "good-split-stone": 21,
        "soft-stone": 16,
        "squared-blocks": 22,
        "solid-brick-lime-mortar": 18,
        "semi-solid-brick-cement-mortar": 15,
    }
    assert MASONRY["soft-stone"].unit_weight_range == (13, 16)
    assert all("C8.5.I" in m.source for m in MASONRY.values())
    assert CONFIDENCE_FACTORS == {"LC1": 1.35, "LC2": 1.20, "LC3": 1.00}


def test_round_trip_of_the_template() -> None:
    project = load_project(TEMPLATE).project
    text = dump_project(project)
    again = load_project_text(text, "dumped.yaml").project
    assert again == project
    assert list(project.model_dump()) == list(Project.model_fields)
    assert text.index("wall:") < text.index("seismic:") < text.index("interventions:")


def test_round_trip_with_files_table_and_numeric_restitution(tmp_path: Path) -> None:
    (tmp_path / "rec").mkdir()
    (tmp_path / "rec" / "a.txt").write_text("0 0\n0.01 0.1\n", encoding="utf-8")
    text = """\
wall: {thickness: 0.3, height: 2.5, unit_weight: 17, mechanism: two-sided}
seismic:
  spectrum: {type: table, periods: [0, 0.5, 2], accelerations: [0.2, 0.5, 0.1]}
  records:
    files: [{path: rec/a.txt, format: two-column, units: m/s2, name: A}]
    scale_to_spectrum: false
analysis: {restitution: 0.85}
design: {materials: [BFRP], ratio_range: [1, 4]}
code_check: {knowledge_level: LC3, behaviour_factor: 2.5}
"""
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    loaded = load_project(path)
    assert loaded.base_dir == tmp_path
    assert loaded.record_paths() == [(tmp_path / "rec" / "a.txt").resolve()]
    assert loaded.line_of("seismic", "records", "files", 0, "path") == 5
    assert loaded.line_of("analysis", "restitution") == 7
    assert loaded.line_of("design", "nothing", "here") == 8
    assert loaded.project.code_check.confidence_factor == 1.0
    again = load_project_text(dump_project(loaded.project), str(path)).project
    assert again == loaded.project


def test_record_files_are_resolved_next_to_the_project_file(tmp_path: Path) -> None:
    (tmp_path / "a.txt").write_text("0 0\n0.01 0.1\n", encoding="utf-8")
    text = MINIMAL + "  records: {files: [{path: a.txt}]}\n"
    (tmp_path / "p.yaml").write_text(text, encoding="utf-8")
    assert load_project(tmp_path / "p.yaml").project.seismic.records.files[0].path == "a.txt"
    with pytest.raises(InputError, match="record file 'a.txt' not found"):
        load_project_text(text, str(tmp_path / "elsewhere" / "p.yaml"))


def test_free_text_accepts_any_scalar() -> None:
    project = validate_data(minimal_data(project={"name": 2024, "notes": None}))
    assert project.project.name == "2024" and project.project.notes == ""


def test_validate_data_without_lines_names_the_key() -> None:
    with pytest.raises(InputError) as info:
        validate_data(minimal_data(costs={"currency": "EUR", "instalation_per_metre": 1}))
    assert str(info.value) == (
        "<data>: costs.instalation_per_metre: unknown key 'instalation_per_metre' "
        "(did you mean 'installation_per_metre'?)"
    )


def test_cli_validate_prints_a_summary(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate", str(TEMPLATE)]) == 0
    out = capsys.readouterr().out
    assert "OK" in out and "B = 0.4 m" in out and "7 artificial" in out
    assert "19 after expansion" in out and "NTC 2018" in out


def test_cli_schema_prints_valid_json_schema(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["schema"]) == 0
    schema = json.loads(capsys.readouterr().out)
    assert set(schema["properties"]) == {*Project.model_fields, "walls"}
    assert schema["additionalProperties"] is False
    assert set(schema["required"]) == {"seismic"}  # and exactly one of wall / walls:
    assert schema["oneOf"] == [{"required": ["wall"]}, {"required": ["walls"]}]
    item = schema["$defs"]["WallItemSpec"]["properties"]  # a building's wall: wall's keys + 4
    assert set(item) == {*schema["$defs"]["WallSpec"]["properties"], *PER_WALL, "name"}
    wall = schema["$defs"]["WallSpec"]["properties"]
    assert all("description" in field for field in wall.values())


def test_every_field_has_a_description() -> None:
    from pydantic import BaseModel

    seen: set[type[BaseModel]] = set()
    todo: list[type[BaseModel]] = [Project]
    while todo:
        model = todo.pop()
        if model in seen:
            continue
        seen.add(model)
        for name, field in model.model_fields.items():
            assert field.description, f"{model.__name__}.{name}"
        for sub in model.__pydantic_fields__.values():
            for typ in _models_in(sub.annotation):
                todo.append(typ)
    assert len(seen) >= 15


def _models_in(annotation: object) -> list[type]:
    from typing import get_args

    from pydantic import BaseModel

    out: list[type] = []
    stack = [annotation]
    while stack:
        a = stack.pop()
        if isinstance(a, type) and issubclass(a, BaseModel):
            out.append(a)
        stack.extend(get_args(a))
    return out


def test_cli_new_copies_the_template(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "north-facade.yaml"
    assert main(["new", str(target)]) == 0
    project = load_project(target).project
    assert project.project.name == "north facade"
    assert main(["new", str(target)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--force" in err
    target.write_text("changed", encoding="utf-8")
    assert main(["new", str(target), "--force"]) == 0
    assert load_project(target).project.project.name == "north facade"


def test_cli_new_quotes_a_name_that_is_not_plain_yaml(tmp_path: Path) -> None:
    target = tmp_path / "wall: #1.yaml"
    assert main(["new", str(target)]) == 0
    assert load_project(target).project.project.name == "wall: #1"


def test_config_imports_no_ui_nor_parallel_layers() -> None:
    """The schema takes the model's options from the dynamics package (declared once there);
    it never reaches up to the layers that use it (tests/test_layering.py has the full table)."""
    forbidden = (
        "textual",
        "rich",
        "frp_assess.assess",
        "frp_assess.cli",
        "frp_assess.tui",
    )
    for path in sorted((PACKAGE / "config").glob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            for name in names:
                assert not name.startswith(forbidden), f"{path.name} imports {name}"


def test_exponent_without_dot_is_a_number() -> None:
    text = MINIMAL.replace("rubble-stone", "rubble-stone, length: 12e-1") + (
        "analysis: {ida: {tolerance: 5e-3}}\n"
    )
    project = load_project_text(text, "e.yaml").project
    assert project.wall.length == 1.2 and project.analysis.ida.tolerance == 0.005
    assert yaml.safe_load("x: 5e-3") == {"x": "5e-3"}  # what PyYAML alone would give


def test_min_artificial_duration_matches_the_generator():
    """The schema's shortest artificial record equals what the SIMQKE generator accepts
    (envelope rise + stationary part + 1 s), so no valid file fails later in the run."""
    from frp_assess.config.schema import MIN_ARTIFICIAL_DURATION
    from frp_assess.motions import preset_spectrum
    from frp_assess.motions.simqke import DEFAULT_RISE, generate_artificial

    assert MIN_ARTIFICIAL_DURATION == DEFAULT_RISE + 10.0 + 1.0
    records = generate_artificial(
        preset_spectrum("A2"), count=1, seed=1, duration=MIN_ARTIFICIAL_DURATION, dt=0.02
    )
    assert records[0].duration >= MIN_ARTIFICIAL_DURATION - 0.02
