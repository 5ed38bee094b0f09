"""What the editor shows when a project is opened (or a new one started)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from frp_assess.app.project import load_project_text, new_project_text, parse_yaml, project_data
from frp_assess.errors import InputError


def opening_data(
    path: Path | None, initial_text: str | None, base_dir: Path
) -> tuple[dict[str, Any], str]:
    """The project data to show, and a one-line message if the file has a problem.

    ``path``: the project file (it may not exist yet: then the template, named after it);
    ``initial_text``: the text of a new project (default: the packaged template);
    ``base_dir``: where relative record paths are read.  A valid project is shown as the
    loader normalises it; an invalid one as its YAML reads, so that each problem shows next
    to its field; a file that is not YAML opens empty.
    """
    if path is not None and path.exists():
        text = path.read_text(encoding="utf-8")
        name = str(path)
    else:
        text = new_project_text(path, initial_text)
        name = str(path) if path else "new project"
    try:
        data, _ = parse_yaml(text, name)
    except InputError as exc:  # the CLI reports this before starting; here just say it
        return {}, str(exc)
    try:
        loaded = load_project_text(text, name, base_dir=base_dir, check_files=False)
    except InputError as exc:
        return (data if isinstance(data, dict) else {}), str(exc)
    return project_data(loaded.project), ""
