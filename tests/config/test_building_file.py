"""A building file (``walls:``): expanded into one one-wall project per wall, every problem
located in the file (``walls[2].height`` at its line in the walls list)."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.config import load_project_text
from frp_assess.config.problems import problems_of
from frp_assess.config.walls_file import (
    LoadedBuilding,
    load_building,
    load_building_text,
    wall_slug,
)
from frp_assess.errors import InputError

FIXTURE = Path(__file__).parents[1] / "fixtures" / "building-small.yaml"


def _text() -> str:
    return FIXTURE.read_text(encoding="utf-8")


def _line_of(text: str, needle: str, after: str = "") -> int:
    """1-based line of the first ``needle`` after the first ``after``."""
    lines = text.splitlines()
    start = next(i for i, ln in enumerate(lines) if after in ln) if after else 0
    return next(i for i, ln in enumerate(lines) if i >= start and needle in ln) + 1


def _problems(text: str) -> list[InputError]:
    with pytest.raises(InputError) as info:
        load_building_text(text, "b.yaml", check_files=False)
    return list(problems_of(info.value))


def test_each_wall_is_a_one_wall_project_sharing_the_other_blocks() -> None:
    b = load_building(FIXTURE)
    assert isinstance(b, LoadedBuilding)
    assert b.names() == ["Facciata sud, piano terra", "Timpano est", "Parapetto"]
    assert [w.entry.slug for w in b.walls] == [
        "facciata-sud-piano-terra",
        "timpano-est",
        "parapetto",
    ]
    facade, gable, parapet = (w.loaded.project for w in b.walls)
    assert facade.project.name == "Casa di prova — Facciata sud, piano terra"
    assert facade.project.location == "Norcia (PG)"  # the shared project block
    assert facade.wall.height == 3.5 and facade.wall.loads is not None
    assert facade.building is None and gable.building is not None
    assert gable.building.wall_base == 9.0
    assert facade.seismic == gable.seismic == parapet.seismic
    # the shared options for the walls that give none; the gable's own replace them
    assert [o.name for o in facade.expand_interventions()] == ["GFRP centred 1"]
    assert [o.name for o in parapet.expand_interventions()] == ["GFRP centred 1"]
    assert [o.name for o in gable.expand_interventions()] == ["CFRP esterno 1"]


def test_a_wall_s_problem_names_the_wall_and_its_line_in_the_list() -> None:
    text = _text().replace("    height: 1.0\n", "    height: -1.0\n")
    (problem,) = _problems(text)
    assert problem.key == "walls[2].height"
    assert problem.line == _line_of(text, "height: -1.0")
    assert str(problem).startswith(f"b.yaml:{problem.line}: walls[2].height: expected a number")


def test_own_blocks_are_located_in_the_wall_s_item() -> None:
    text = (
        _text()
        .replace("wall_base: 9.0", "wall_base: 12.0")
        .replace("material: CFRP, position: external", "material: XFRP, position: external")
    )
    problems = _problems(text)
    keys = [p.key for p in problems]
    assert "walls[1].building.wall_base" in keys
    base = problems[keys.index("walls[1].building.wall_base")]
    assert base.line == _line_of(text, "wall_base: 12.0")
    text = _text().replace(
        "material: CFRP, position: external", "material: XFRP, position: external"
    )
    (material,) = _problems(text)
    assert material.key == "walls[1].interventions[0].material"
    assert material.line == _line_of(text, "XFRP")


def test_a_shared_block_s_problem_is_reported_once_at_its_own_key() -> None:
    text = _text().replace("ag: 0.261", "ag: -0.261")
    (problem,) = _problems(text)  # three walls, one problem
    assert problem.key is not None and problem.key.startswith("seismic.spectrum")
    assert problem.line == _line_of(text, "ag: -0.261")


def test_missing_and_unknown_keys_of_a_wall() -> None:
    text = _text().replace("    thickness: 0.30\n", "    thicknes: 0.30\n")
    problems = _problems(text)
    assert [p.key for p in problems] == ["walls[2].thicknes"]
    assert "did you mean 'thickness'" in problems[0].message
    text = _text().replace("    thickness: 0.30\n", "")
    (missing,) = _problems(text)
    assert missing.key == "walls[2]" and "missing required key 'thickness'" in missing.message
    assert missing.line == _line_of(text, "- name: Parapetto")


def test_names_are_required_and_unique() -> None:
    text = _text().replace("- name: Timpano est", "- name: Parapetto")
    (dup,) = _problems(text)
    assert dup.key == "walls[2].name" and "already the name of walls[1]" in dup.message
    text = _text().replace("- name: Timpano est\n    thickness", "- thickness")
    (missing,) = _problems(text)
    assert missing.key == "walls[1]" and "missing required key 'name'" in missing.message
    text = _text().replace("- name: Timpano est", "- name: Facciata SUD piano terra")
    (slug,) = _problems(text)  # another name, the same folder
    assert "walls/facciata-sud-piano-terra/" in slug.message


def test_exactly_one_of_wall_and_walls() -> None:
    both = _text().replace(
        "walls:\n", "wall: {thickness: 0.4, height: 3.0, masonry: soft-stone}\nwalls:\n"
    )
    problems = _problems(both)
    assert [p.key for p in problems] == ["walls"]
    assert "exactly one of wall: (one wall) or walls:" in problems[0].message
    assert problems[0].line == _line_of(both, "walls:")
    (empty,) = _problems(_text().split("walls:")[0] + "walls: []\n")
    assert empty.key == "walls" and "at least one" in empty.message
    # a one-wall command given a building file: one line that says what to do
    with pytest.raises(InputError) as info:
        load_project_text(_text(), "b.yaml", check_files=False)
    assert "is a building file" in str(info.value) and info.value.key == "walls"


def test_slugs() -> None:
    assert wall_slug("Facciata sud, piano terra") == "facciata-sud-piano-terra"
    assert wall_slug("Città — è ") == "citta-e"
    assert wall_slug("???") == "wall"


def test_validate_summarises_a_building_and_locates_its_problems(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from frp_assess.cli import main

    assert main(["validate", str(FIXTURE)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == f"{FIXTURE}: OK — building 'Casa di prova': 3 walls"
    assert sum(line.startswith("  spectrum:") for line in out) == 1  # shared: once
    assert "  walls[1] 'Timpano est' (results in walls/timpano-est/):" in out
    assert any(line.startswith("    building: H_b = 10 m") for line in out)
    bad = tmp_path / "b.yaml"
    bad.write_text(_text().replace("    height: 2.5\n", "    height: 0.2\n"), encoding="utf-8")
    assert main(["validate", str(bad)]) == 2
    err = capsys.readouterr().err.splitlines()
    line = _line_of(bad.read_text(encoding="utf-8"), "height: 0.2")
    assert len(err) == 1
    assert err[0].startswith(f"frp-assess: error: {bad}:{line}: walls[1].height: expected")


def test_the_template_s_walls_example_uncommented_is_a_valid_building(tmp_path: Path) -> None:
    """templates/wall.yaml's commented `walls:` block, uncommented in place of `wall:`, is a
    building of two walls (the gable with its own floor and options)."""
    import frp_assess

    template = Path(frp_assess.__file__).parent / "templates" / "wall.yaml"
    lines = template.read_text(encoding="utf-8").splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("# walls:"))
    out = list(lines)
    i = start
    while lines[i].startswith("#") and not lines[i].startswith("#   frp-assess run"):
        out[i] = lines[i][2:]
        i += 1
    wall = out.index("wall:")  # the one wall: replaced by the building's walls
    end = next(j for j in range(wall + 1, len(out)) if out[j] and not out[j].startswith(" "))
    del out[wall:end]
    path = tmp_path / "b.yaml"
    path.write_text("\n".join(out) + "\n", encoding="utf-8")
    b = load_building(path)
    assert b.names() == ["south facade, ground floor", "gable, top storey"]
    gable = b.walls[1].loaded.project
    assert gable.building is not None and gable.building.wall_base == 9.0
    assert len(gable.expand_interventions()) == 1
    assert len(b.walls[0].loaded.project.expand_interventions()) > 1  # the file's options
