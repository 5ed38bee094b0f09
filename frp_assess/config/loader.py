"""Read a project file: YAML with line numbers, validation, one-line errors.

Every problem is an :class:`~frp_assess.errors.InputError` whose ``str()`` is
``file:line: key.path: message``, the first problem found.  Nothing is written.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from frp_assess.config.messages import Loc, describe, format_path
from frp_assess.config.schema import Project
from frp_assess.errors import InputError


class DuplicateKeyError(yaml.YAMLError):
    """A mapping defines the same key twice."""

    def __init__(self, key: str, path: Loc, line: int, first_line: int) -> None:
        super().__init__(f"duplicate key {key!r} (first defined on line {first_line})")
        self.key, self.path, self.line, self.first_line = key, path, line, first_line


class ProjectYamlLoader(yaml.SafeLoader):
    """A SafeLoader that rejects duplicate keys and records the line of every key and item.

    After :meth:`load`, :attr:`lines` maps each key path -- ``("wall", "height")``,
    ``("interventions", 1)`` -- to its 1-based line.
    """

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self.lines: dict[Loc, int] = {}

    def load(self) -> Any:
        """The document's data (``None`` for an empty document)."""
        try:
            node = self.get_single_node()
            if node is None:
                return None
            self._record(node, ())
            return self.construct_document(node)
        finally:
            self.dispose()

    def _record(self, node: yaml.Node, path: Loc) -> None:
        if isinstance(node, yaml.MappingNode):
            first: dict[str, int] = {}
            for key_node, value_node in node.value:
                key = str(key_node.value)
                line = key_node.start_mark.line + 1
                if key in first and key != "<<":
                    raise DuplicateKeyError(key, (*path, key), line, first[key])
                first[key] = line
                self.lines[(*path, key)] = line
                self._record(value_node, (*path, key))
        elif isinstance(node, yaml.SequenceNode):
            for i, item in enumerate(node.value):
                self.lines[(*path, i)] = item.start_mark.line + 1
                self._record(item, (*path, i))


# YAML 1.1 (PyYAML) reads 1e-3 as text; accept it as a number, as YAML 1.2 and people do
ProjectYamlLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?[0-9][0-9_]*(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"),
)


@dataclass(frozen=True)
class LoadedProject:
    """A validated project and where it came from.

    Attributes:
        project: the validated model.
        path: the project file (or the name given to :func:`load_project_text`).
        base_dir: directory that relative record paths are resolved against.
        lines: 1-based line of each key path of the YAML data.
    """

    project: Project
    path: Path
    base_dir: Path
    lines: dict[Loc, int] = field(default_factory=dict, compare=False, repr=False)

    def line_of(self, *path: str | int) -> int | None:
        """Line of a key path (``"wall", "height"``), or of its nearest present ancestor."""
        return line_of(self.lines, tuple(path))

    def record_paths(self) -> list[Path]:
        """Absolute paths of the record files (empty for artificial records)."""
        files = self.project.seismic.records.files or []
        return [(self.base_dir / f.path).resolve() for f in files]


def line_of(lines: Mapping[Loc, int], path: Loc) -> int | None:
    """Line of ``path`` or of its longest prefix present in ``lines``; None if none is."""
    for n in range(len(path), 0, -1):
        if path[:n] in lines:
            return lines[path[:n]]
    return None


def parse_yaml(text: str, name: str) -> tuple[Any, dict[Loc, int]]:
    """YAML text -> (data, key-path lines); syntax errors and duplicate keys as InputError."""
    loader = ProjectYamlLoader(text)
    try:
        data = loader.load()
    except DuplicateKeyError as exc:
        raise InputError(str(exc), file=name, line=exc.line, key=format_path(exc.path)) from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        problem = exc.problem or exc.context or "invalid YAML"
        context = ""
        if exc.context and exc.problem:
            where = exc.context_mark
            started = f" started on line {where.line + 1}" if where is not None else ""
            context = f" ({exc.context}{started})"
        if "\\t" in problem or "\t" in problem:
            context += "; indent with spaces, not tabs"
        raise InputError(
            f"YAML syntax error: {problem}{context}",
            file=name,
            line=None if mark is None else mark.line + 1,
        ) from None
    except yaml.YAMLError as exc:
        raise InputError(f"YAML error: {exc}", file=name) from None
    return data, loader.lines


def validate_data(
    data: Any, *, file: str = "<data>", lines: Mapping[Loc, int] | None = None
) -> Project:
    """Validate parsed data; the first problem as one-line InputError (line if ``lines``)."""
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
    try:
        return Project.model_validate(data)
    except ValidationError as exc:
        errors = exc.errors(include_url=False)
        # a misspelt key also makes the right one "missing": report the unknown key first
        unknown = [e for e in errors if e["type"] == "extra_forbidden"]
        err = (unknown or errors)[0]
        path, message = describe(Project, err)
        line = None
        if lines is not None:
            line = line_of(lines, path) or 1  # a missing top-level key: the file's start
        raise InputError(message, file=file, line=line, key=format_path(path) or None) from None


def check_record_files(
    project: Project, base_dir: Path, file: str, lines: Mapping[Loc, int]
) -> None:
    """Every record file exists (relative paths against ``base_dir``), else InputError."""
    for i, rec in enumerate(project.seismic.records.files or []):
        target = base_dir / rec.path
        if not target.is_file():
            path: Loc = ("seismic", "records", "files", i, "path")
            raise InputError(
                f"record file {rec.path!r} not found (looked for {target})",
                file=file,
                line=line_of(lines, path),
                key=format_path(path),
            )


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
    project = validate_data(data, file=name, lines=lines)
    base = Path(base_dir) if base_dir is not None else Path(name).parent
    if check_files:
        check_record_files(project, base, name, lines)
    return LoadedProject(project=project, path=Path(name), base_dir=base, lines=lines)


def load_project(path: str | Path) -> LoadedProject:
    """Read, parse and validate a project file; InputError (one line) on any problem."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError("no such project file", file=str(path)) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read the project file: {exc}", file=str(path)) from None
    return load_project_text(text, str(path), base_dir=path.parent)


def project_data(project: Project) -> dict[str, Any]:
    """The project as the nested dict the YAML loader reads (every value, defaults included);
    :func:`validate_data` of it gives an equal model."""
    return project.model_dump(mode="json", exclude_none=True)


def dump_project(project: Project) -> str:
    """The project as YAML, keys in schema order; loading it gives an equal model."""
    data = project_data(project)
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True, default_flow_style=False)
