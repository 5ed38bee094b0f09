"""The text of a new project: the packaged, commented template, named after its file.

The same template and naming rule as ``frp-assess new`` (``cli/new.py``), read here from
the package so that the TUI does not import the command-line interface.
"""

from __future__ import annotations

import json
import re
from importlib import resources
from pathlib import Path

#: the project name in the template, replaced by one taken from the file name
TEMPLATE_NAME = "Example wall"


def template_text() -> str:
    """The text of the packaged template ``frp_assess/templates/wall.yaml``."""
    return resources.files("frp_assess").joinpath("templates/wall.yaml").read_text("utf-8")


def name_from_path(path: Path) -> str:
    """A project name from a file name, as a YAML scalar: ``north_wall.yaml`` ->
    ``north wall`` (none left: the template's); a name YAML would read otherwise is quoted
    (as a JSON string)."""
    name = path.stem.replace("_", " ").replace("-", " ").strip() or TEMPLATE_NAME
    if not re.fullmatch(r"[A-Za-z0-9][\w .()-]*", name):
        name = json.dumps(name, ensure_ascii=False)  # a JSON string is a quoted YAML scalar
    return name


def new_project_text(path: Path | None, template: str | None = None) -> str:
    """``template`` (default: the packaged one) with the project named after ``path``."""
    text = template or template_text()
    if path is None:
        return text
    return text.replace(f"name: {TEMPLATE_NAME}", f"name: {name_from_path(path)}", 1)
