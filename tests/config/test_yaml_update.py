"""Saving an edited project into its file keeps the file's comments and layout."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from frp_assess.api import template_text
from frp_assess.config import Project, load_project_text, project_data
from frp_assess.config.yaml_update import update_project_text
from frp_assess.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
FILES = {
    "template": template_text(),
    **{p.name: p.read_text(encoding="utf-8") for p in sorted((ROOT / "projects").glob("*.yaml"))},
}


def _is_project(text: str) -> bool:
    try:
        load_project_text(text, "p.yaml", check_files=False)
    except InputError:
        return False  # a study file
    return True


FILES = {k: v for k, v in FILES.items() if _is_project(v)}
assert {"template", "facade-laquila.yaml", "paper-case.yaml"} <= set(FILES)


def loaded(text: str) -> Project:
    return load_project_text(text, "p.yaml", check_files=False).project


def edited(project: Project, change: Any) -> Project:
    data = project_data(project)
    change(data)
    return Project.model_validate(data)


def comment_lines(text: str) -> list[str]:
    return [line.strip() for line in text.splitlines() if line.strip().startswith("#")]


@pytest.mark.parametrize("name", sorted(FILES))
def test_an_unchanged_project_keeps_its_file_byte_for_byte(name: str):
    text = FILES[name]
    project = loaded(text)
    assert update_project_text(text, project, project) == text
    # and a change made and undone goes through the round trip without touching a byte
    other = edited(project, lambda d: d["wall"].update(height=9.0))
    there = update_project_text(text, project, other)
    assert there is not None
    assert update_project_text(there, other, project) == text


@pytest.mark.parametrize("name", sorted(FILES))
def test_changes_are_written_in_place_and_comments_kept(name: str):
    """A value changed, a default overridden, an option added: the file loads as the edited
    project, every full-line comment is still there, and unchanged lines are untouched."""
    text = FILES[name]
    project = loaded(text)

    def change(d: dict[str, Any]) -> None:
        d["wall"]["height"] = 4.7  # above every example's loads and ties (a tie at 4.4 m)
        d["analysis"]["strain_factor"] = 0.45
        d["interventions"].append({"material": "CFRP", "position": "centred", "ratio": 2.5})

    new = edited(project, change)
    out = update_project_text(text, project, new)
    assert out is not None
    assert loaded(out) == new
    assert set(comment_lines(text)) <= set(comment_lines(out))
    assert "- {material: CFRP, position: centred, ratio: 2.5}" in out  # the template's style
    old_lines, new_lines = text.splitlines(), out.splitlines()
    changed = [line for line in old_lines if line not in new_lines]
    assert len(changed) <= 2  # the height line, and the strain factor if the file had it
    assert any(line.strip().startswith(f"height: {project.wall.height:g}") for line in changed)


def test_a_new_spectrum_type_replaces_the_block_and_drops_the_stale_comment():
    text = template_text()
    project = loaded(text)

    def change(d: dict[str, Any]) -> None:
        d["seismic"]["spectrum"] = {"type": "ec8", "ag": 0.25, "ground": "C", "spectrum_type": 1}

    new = edited(project, change)
    out = update_project_text(text, project, new)
    assert out is not None and loaded(out) == new
    type_line = next(line for line in out.splitlines() if line.strip().startswith("type:"))
    assert type_line.strip() == "type: ec8"  # its comment described the NTC 2018 spectrum
    assert "F0:" not in out and "Tc_star:" not in out


def test_removed_options_and_keys_leave_the_file():
    text = FILES["facade-laquila.yaml"]
    project = loaded(text)

    def change(d: dict[str, Any]) -> None:
        d["interventions"] = [{"material": "GFRP", "position": "external", "ratio": 1.0}]
        d.pop("design")

    new = edited(project, change)
    out = update_project_text(text, project, new)
    assert out is not None and loaded(out) == new
    assert "- sweep:" not in out and "\ndesign:" not in out


def test_text_that_is_not_a_mapping_is_not_updated():
    project = loaded(template_text())
    other = edited(project, lambda d: d["wall"].update(height=9.0))
    assert update_project_text("- just a list\n", project, other) is None
    assert update_project_text("a: [unclosed\n", project, other) is None
