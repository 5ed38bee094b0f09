"""A new project in the TUI and ``frp-assess new`` start from one text, api.new_project_text."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.api import TEMPLATE_NAME, new_project_text, template_text
from frp_assess.cli import main
from frp_assess.config import load_project_text


@pytest.mark.parametrize(
    "file_name", ["north_wall.yaml", "façade: 2°.yaml", "wall (b).yml", "_.yaml"]
)
def test_the_text_is_that_of_frp_assess_new(tmp_path: Path, file_name: str, capsys):
    path = tmp_path / file_name
    assert main(["new", str(path)]) == 0
    capsys.readouterr()
    assert new_project_text(path) == path.read_text(encoding="utf-8")


def test_without_a_file_the_template_keeps_its_name():
    text = new_project_text(None)
    assert text == template_text()
    assert load_project_text(text, "t.yaml").project.project.name == TEMPLATE_NAME


def test_the_name_comes_from_the_file_name():
    text = new_project_text(Path("/x/south-wall_2.yaml"))
    assert load_project_text(text, "t.yaml").project.project.name == "south wall 2"
