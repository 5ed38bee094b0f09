"""Read a project file: YAML with line numbers, validation, one-line errors.

Every problem is an :class:`~frp_assess.errors.InputError` whose ``str()`` is
``file:line: key.path: message``; when a file has several, they are raised together as
:class:`~frp_assess.config.problems.InputErrors` (YAML-level problems first and alone, then the
schema's, in file order).  Nothing is written.  The YAML reading itself (limits, line numbers)
is :mod:`frp_assess.config.yaml_source`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from frp_assess.config.messages import Loc, format_path, line_of, schema_problems
from frp_assess.config.plausibility import project_warnings
from frp_assess.config.problems import raise_all
from frp_assess.config.schema import Project
from frp_assess.config.yaml_source import parse_yaml, read_text_file
from frp_assess.errors import InputError


@dataclass(frozen=True)
class LoadedProject:
    """A validated project and where it came from.

    Attributes:
        project: the validated model.
        path: the project file (or the name given to :func:`load_project_text`).
        base_dir: directory that relative record paths are resolved against.
        lines: 1-based line of each key path of the YAML data.
        warnings: one line each (``file:line: key: message``) for what is valid but probably
            not meant: the template's placeholders left unchanged, values outside the range of
            practice (:mod:`frp_assess.config.plausibility`).
    """

    project: Project
    path: Path
    base_dir: Path
    lines: dict[Loc, int] = field(default_factory=dict, compare=False, repr=False)
    warnings: tuple[str, ...] = field(default=(), compare=False)

    def line_of(self, *path: str | int) -> int | None:
        """Line of a key path (``"wall", "height"``), or of its nearest present ancestor."""
        return line_of(self.lines, tuple(path))

    def record_paths(self) -> list[Path]:
        """Absolute paths of the record files (empty for artificial records)."""
        files = self.project.seismic.records.files or []
        return [(self.base_dir / f.path).resolve() for f in files]


def validate_data(
    data: Any, *, file: str = "<data>", lines: Mapping[Loc, int] | None = None
) -> Project:
    """Validate parsed data; every problem as one-line InputError (line if ``lines``).

    Raises :class:`~frp_assess.config.problems.InputErrors` (an InputError: its first
    problem) when there are several.  With ``lines`` the problems are in file order; without,
    an unknown key comes first (a misspelt key is the likelier cause of a "missing" one).
    """
    if data is None:
        raise InputError(
            "the project file is empty; start from 'frp-assess new NAME.yaml'",
            file=file,
            line=1 if lines is not None else None,
        )
    if not isinstance(data, dict):
        raise InputError(
            f"expected a mapping of keys (project, wall, seismic, ...), found "
            f"{type(data).__name__}",
            file=file,
            line=1 if lines is not None else None,
        )
    if "walls" in data:  # a building (config/walls_file.py): one project per wall
        raise InputError(
            "is a building file (walls:); this takes a one-wall project (wall:): assess the "
            "building with 'frp-assess run' (one wall: 'frp-assess run --wall NAME')",
            file=file,
            line=lines.get(("walls",)) if lines is not None else None,
            key="walls",
        )
    try:
        return Project.model_validate(data)
    except ValidationError as exc:
        raise_all(schema_problems(Project, exc, file=file, lines=lines))
        raise  # pragma: no cover - schema_problems never returns an empty list


def check_record_files(
    project: Project, base_dir: Path, file: str, lines: Mapping[Loc, int]
) -> None:
    """Every record file exists (relative paths against ``base_dir``), else InputError."""
    for i, rec in enumerate(project.seismic.records.files or []):
        target = base_dir / rec.path
        if not target.is_file():
            path: Loc = ("seismic", "records", "files", i, "path")
            if target.is_dir():
                problem = f"record file {rec.path!r} is a folder ({target})"
            elif target.exists():
                problem = (
                    f"record file {rec.path!r} is not a regular file (a device, pipe or socket: "
                    f"{target})"
                )
            else:
                problem = f"record file {rec.path!r} not found (looked for {target})"
            raise InputError(problem, file=file, line=line_of(lines, path), key=format_path(path))


def load_project_text(
    text: str,
    name: str = "<project>",
    *,
    base_dir: Path | str | None = None,
    check_files: bool = True,
) -> LoadedProject:
    """Parse and validate project YAML held in memory (the TUI's editor).

    Args:
        text: the YAML text.
        name: shown as the file name in error messages.
        base_dir: where relative record paths are resolved (default: the directory of
            ``name``).
        check_files: whether to check that the record files exist.
    """
    data, lines = parse_yaml(text, name)
    return load_parsed(data, lines, name, base_dir=base_dir, check_files=check_files)


def load_parsed(
    data: Any,
    lines: dict[Loc, int],
    name: str,
    *,
    base_dir: Path | str | None = None,
    check_files: bool = True,
) -> LoadedProject:
    """Validate YAML data already parsed by :func:`parse_yaml` (arguments as
    :func:`load_project_text`, ``lines`` as it returns them)."""
    project = validate_data(data, file=name, lines=lines)
    base = Path(base_dir) if base_dir is not None else Path(name).parent
    if check_files:
        check_record_files(project, base, name, lines)
    return LoadedProject(
        project=project,
        path=Path(name),
        base_dir=base,
        lines=lines,
        warnings=(
            *placeholder_warnings(project, name, lines),
            *(w.located(name, lines) for w in project_warnings(project)),
        ),
    )


#: a template placeholder: the whole text in angle brackets, e.g. ``<site address>``
PLACEHOLDER_RE = re.compile(r"^\s*<[^<>]*>\s*$")


def placeholder_warnings(project: Project, file: str, lines: Mapping[Loc, int]) -> tuple[str, ...]:
    """One line if identification fields still hold a template placeholder (``<...>``).

    The template (``frp-assess new``) fills ``project.location``, ``engineer`` and ``notes``
    with placeholders such as ``<site address>``; they are valid text but would be printed in
    a client's report.  The line is at the first such field and names them all.
    """
    info = project.project
    keys = [
        key
        for key in ("name", "location", "engineer", "notes")
        if PLACEHOLDER_RE.match(str(getattr(info, key)))
    ]
    if not keys:
        return ()
    first: Loc = ("project", keys[0])
    listed = ", ".join(f"{k} {str(getattr(info, k)).strip()!r}" for k in keys)
    warning = InputError(
        f"the template's placeholders are unchanged ({listed}); replace them: they are printed "
        "in the report",
        file=file,
        line=line_of(lines, first),
        key="project",
    )
    return (str(warning),)


def load_project(path: str | Path) -> LoadedProject:
    """Read, parse and validate a project file; InputError (one line each) on any problem.

    The file must be a regular file of at most 2 MB
    (:data:`~frp_assess.config.yaml_source.MAX_FILE_BYTES`), UTF-8.
    """
    path = Path(path)
    text = read_text_file(path, "project file")
    return load_project_text(text, str(path), base_dir=path.parent)


def project_data(project: Project) -> dict[str, Any]:
    """The project as the nested dict the YAML loader reads (every value, defaults included);
    :func:`validate_data` of it gives an equal model."""
    return project.model_dump(mode="json", exclude_none=True)


def dump_project(project: Project) -> str:
    """The project as YAML, keys in schema order; loading it gives an equal model."""
    data = project_data(project)
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True, default_flow_style=False)
