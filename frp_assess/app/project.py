"""A project file: read, check, create and save it.

:func:`check_file` loads a project or a study file (told apart by their keys) with every
problem as one located line and the warnings of a valid file; :func:`new_project_text` is
the commented template named after a file; :func:`save_project` writes an edited project
keeping the comments of the file it was opened from.  The loader's functions the TUI's form
validates its fields with are re-exported here, so that the interfaces import only this
package (and the schema's form metadata).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from frp_assess.assess.from_project import layout_problems, read_record_files
from frp_assess.config import (
    LoadedProject,
    Project,
    dump_project,
    load_project,
    load_project_text,
    project_data,
    validate_data,
)
from frp_assess.config.loader import check_record_files, load_parsed
from frp_assess.config.problems import problems_of, raise_all
from frp_assess.config.walls_file import (
    LoadedBuilding,
    LoadedWall,
    check_wall_list,
    is_building,
    load_building_parsed,
)
from frp_assess.config.yaml_source import parse_yaml, read_text_file
from frp_assess.config.yaml_update import update_project_text
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.motions.pga_plausibility import plausibility_warnings
from frp_assess.study.schema import StudyFile, looks_like_study, parse_study

__all__ = [
    "TEMPLATE_NAME",
    "CheckedBuilding",
    "CheckedProject",
    "CheckedStudy",
    "LoadedProject",
    "Project",
    "check_file",
    "check_record_files",
    "dump_project",
    "ensure_project_file",
    "load_project",
    "load_project_text",
    "new_project_text",
    "parse_yaml",
    "problems_of",
    "project_data",
    "project_name_from_path",
    "save_project",
    "template_text",
    "validate_data",
    "yaml_path_problem",
]


@dataclass(frozen=True)
class CheckedProject:
    """A valid project file, its record files read and checked."""

    loaded: LoadedProject  #: the validated project, its file, folder and lines
    warnings: tuple[str, ...]  #: one line each (placeholders left, an implausible PGA...)


@dataclass(frozen=True)
class CheckedBuilding:
    """A valid building file (``walls:``): every wall's project checked as a one-wall file."""

    building: LoadedBuilding
    warnings: tuple[str, ...]


@dataclass(frozen=True)
class CheckedStudy:
    """A valid study file."""

    study: StudyFile
    file: str  #: its name as given


def check_file(path: Path) -> CheckedProject | CheckedStudy | CheckedBuilding:
    """Validate a project or a study file (told apart by their keys); a project's record
    files are read too (their problems are errors, an implausible PGA a warning).

    Raises:
        InputError: every problem of the file (:class:`~frp_assess.config.problems.
        InputErrors`), in file order.
    """
    from frp_assess.app.study import study_problems

    name = str(path)
    text = read_text_file(path, "project file")
    data, lines = parse_yaml(text, name)
    if looks_like_study(data):
        study = parse_study(data, file=name, lines=lines)
        raise_all(study_problems(study, name, lines))
        return CheckedStudy(study, name)
    if is_building(data):
        return check_building(load_building_parsed(data, lines, name, base_dir=path.parent))
    loaded = load_parsed(data, lines, name, base_dir=path.parent)
    records, problems = read_record_files(loaded.project, loaded.base_dir)
    layout_errors, as_built = layout_problems(loaded)
    raise_all(problems + layout_errors)
    return CheckedProject(loaded, (*loaded.warnings, *as_built, *plausibility_warnings(records)))


def check_building(building: LoadedBuilding) -> CheckedBuilding:
    """A building's walls checked as :func:`check_file` checks a one-wall file (the records
    once: they are the building's), every problem located in the building file."""
    first = building.walls[0].loaded
    records, problems = read_record_files(first.project, first.base_dir)
    warnings = [*building.warnings]
    for wall in building.walls:
        layout_errors, as_built = layout_problems(wall.loaded)
        problems += [wall.entry.relocated(e) for e in layout_errors]
        warnings += [_relocated_line(wall, w) for w in as_built]
    raise_all(problems)
    return CheckedBuilding(building, (*warnings, *plausibility_warnings(records)))


def _relocated_line(wall: LoadedWall, line: str) -> str:
    """A located warning line ``file:line: key: message`` of a wall's one-wall project with
    the building file's key (``interventions[0].ratio`` -> ``walls[1].interventions[0]...``)."""
    head, sep, rest = line.partition(": ")
    key, sep2, message = rest.partition(": ")
    if not sep or not sep2:
        return line
    return f"{head}: {wall.entry.file_key(key)}: {message}"


def ensure_project_file(path: Path) -> None:
    """Refuse, as one line, a file that is not a readable YAML project file: a folder, FIFO,
    device or oversized file, a YAML syntax error, a study file (which names the command
    that runs it), or a building file whose list of walls is not valid (no list, a name
    missing or repeated: the validation's message).  A valid project is not checked further here."""
    text = read_text_file(path, "project file")
    data, _lines = parse_yaml(text, str(path))
    if looks_like_study(data):
        raise InputError(
            "is a study file: the terminal UI edits project files; run it with "
            f"`frp-assess study {path}` (check it with `frp-assess validate`)",
            file=str(path),
        )
    if is_building(data):  # the TUI edits it wall by wall: the list of walls must hold
        check_wall_list(data, _lines, str(path))


#: the project name in the packaged template, replaced by one taken from the file name
TEMPLATE_NAME = "Example wall"


def template_text() -> str:
    """The text of the packaged, commented template ``frp_assess/templates/wall.yaml``."""
    return resources.files("frp_assess").joinpath("templates/wall.yaml").read_text("utf-8")


def project_name_from_path(path: Path) -> str:
    """A project name from a file name, as a YAML scalar: ``north_wall.yaml`` ->
    ``north wall`` (none left: the template's); a name YAML would read otherwise is quoted
    (as a JSON string)."""
    name = path.stem.replace("_", " ").replace("-", " ").strip() or TEMPLATE_NAME
    if not re.fullmatch(r"[A-Za-z0-9][\w .()-]*", name):
        name = json.dumps(name, ensure_ascii=False)  # a JSON string is a quoted YAML scalar
    return name


def new_project_text(path: Path | None, template: str | None = None) -> str:
    """The text of a new project (`frp-assess new`, the TUI's new project): ``template``
    (default: the packaged one) with the project named after ``path`` (None: unchanged)."""
    text = template or template_text()
    if path is None:
        return text
    return text.replace(f"name: {TEMPLATE_NAME}", f"name: {project_name_from_path(path)}", 1)


def yaml_path_problem(path: Path) -> str | None:
    """Why a project cannot be saved as ``path`` (None: it can)."""
    if path.suffix.lower() not in (".yaml", ".yml"):
        return f"expected a .yaml file name, found {path.name!r}"
    if path.is_dir():
        return f"{path} is a directory"
    if not path.parent.is_dir():
        return f"no such directory: {path.parent}"
    return None


def save_project(project: Project, path: Path, *, opened_from: Path | None = None) -> bool:
    """Write the project as YAML (atomically); loading it gives an equal :class:`Project`.

    When ``opened_from`` is a valid project file (the one being edited), its text is kept,
    comments and layout included, and only what changed is rewritten; otherwise (or if that
    fails) the whole project is dumped.  Returns whether the comments were kept.
    """
    path = Path(path)
    problem = yaml_path_problem(path)
    if problem is not None:
        raise InputError(problem)
    text = _updated_text(opened_from, project, str(path))
    kept = text is not None
    if text is None:
        text = (
            "# frp-assess project file, saved by `frp-assess tui` (units: see `frp-assess new`)\n"
            + dump_project(project)
        )
    try:
        atomic_write_text(path, text)
    except OSError as exc:
        raise InputError(f"cannot write {path}: {exc.strerror or exc}") from None
    return kept


def _updated_text(opened_from: Path | None, project: Project, name: str) -> str | None:
    """The text of ``opened_from`` changed to hold ``project``, or None (see save_project)."""
    if opened_from is None:
        return None
    try:
        original_text = Path(opened_from).read_text(encoding="utf-8")
        original = load_project_text(original_text, name, check_files=False).project
    except (OSError, UnicodeDecodeError, InputError):
        return None
    return update_project_text(original_text, original, project, name)
