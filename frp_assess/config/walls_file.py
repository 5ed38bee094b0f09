"""A building: several walls (local mechanisms) in one project file, under ``walls:``.

A building file holds a ``walls:`` list instead of ``wall:``; each item is a wall as ``wall:``
holds it (its loads under ``loads``) with a ``name`` (unique), and optionally its own
``building:`` (where the wall stands), ``interventions:`` and ``design:``.  Everything else
(``project``, ``seismic``, ``materials``, ``analysis``, ``bars``, ``code_check``, ``costs``,
``report``, and ``interventions`` / ``design`` for the walls that give none) is shared.

The building is expanded into one ordinary one-wall :class:`~frp_assess.config.schema.Project`
per wall (its ``project.name`` "<building> — <wall>"), so that validation, the cross-checks,
the model and the run are those of a one-wall project.  Every problem found in a wall's
project is located in the file: its key names the wall's item (``walls[2].height``) and its
line points into the ``walls`` list (:class:`WallEntry`).
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from frp_assess.config.loader import LoadedProject, load_parsed, placeholder_warnings
from frp_assess.config.messages import Loc, format_path, found, line_of
from frp_assess.config.plausibility import project_warnings
from frp_assess.config.problems import problems_of, raise_all
from frp_assess.config.schema.building_spec import MAX_WALL_NAME, MAX_WALLS
from frp_assess.config.yaml_source import parse_yaml, read_text_file
from frp_assess.errors import InputError

__all__ = [
    "BUILDING_KEY",
    "LoadedBuilding",
    "LoadedWall",
    "WallEntry",
    "check_wall_list",
    "is_building",
    "load_building",
    "load_building_text",
    "wall_slug",
]

#: the key of a building file's list of walls
BUILDING_KEY = "walls"
#: the blocks a wall of a building may give itself (the rest is the building's)
PER_WALL_BLOCKS: tuple[str, ...] = ("building", "interventions", "design")
#: the blocks a wall may give itself that the building may also give for every wall
SHARED_DEFAULTS: tuple[str, ...] = ("interventions", "design")
#: the separator of the building's and the wall's names in each wall's project name
NAME_SEPARATOR = " — "
#: the building's name when its project block gives none
DEFAULT_BUILDING_NAME = "Untitled building"


def wall_slug(name: str) -> str:
    """A file-name form of a wall's name: ``Facciata sud, piano terra`` ->
    ``facciata-sud-piano-terra`` (ASCII letters and digits, ``-`` between words)."""
    ascii_text = unicodedata.normalize("NFKD", name).encode("ascii", "ignore").decode("ascii")
    slug = re.sub(r"[^a-z0-9]+", "-", ascii_text.lower()).strip("-")
    return slug or "wall"


@dataclass(frozen=True)
class WallEntry:
    """One item of ``walls:``: where it is in the file, and how the keys and lines of its
    one-wall project map onto the file's."""

    index: int  #: its place in ``walls:`` (0-based, as keys print it: ``walls[0]``)
    name: str
    slug: str  #: its folder under ``walls/`` in the results (:func:`wall_slug`)
    own: frozenset[str] = frozenset()  #: the blocks of PER_WALL_BLOCKS it gives itself

    def file_loc(self, loc: Loc) -> Loc:
        """The file's key path of a key path of the wall's one-wall project."""
        item: Loc = (BUILDING_KEY, self.index)
        if not loc:
            return loc
        if loc[0] == "wall":
            return (*item, *loc[1:])
        if loc[0] in self.own or loc[0] == "building":
            return (*item, *loc)
        return loc

    def file_key(self, key: str | None) -> str | None:
        """The file's dotted key of a dotted key of the wall's project (``wall.height`` ->
        ``walls[2].height``; a shared block's key as it is)."""
        if not key:
            return key
        head = re.match(r"[^.\[]+", key)
        first = head.group(0) if head else key
        item = format_path((BUILDING_KEY, self.index))
        if first == "wall":
            return item + key[len(first) :]
        if first in self.own or first == "building":
            return f"{item}.{key}"
        return key

    def relocated(self, error: InputError) -> InputError:
        """``error`` (a problem of the wall's project, its line already the file's) with the
        file's key."""
        return InputError(
            error.message, file=error.file, line=error.line, key=self.file_key(error.key)
        )


@dataclass(frozen=True)
class LoadedWall:
    """A wall of a building: its entry in the file and its one-wall project (whose ``lines``
    map the one-wall key paths to the file's lines)."""

    entry: WallEntry
    loaded: LoadedProject

    @property
    def name(self) -> str:
        return self.entry.name


@dataclass(frozen=True)
class LoadedBuilding:
    """A validated building file."""

    name: str  #: the building's name (the file's ``project.name``)
    path: Path
    base_dir: Path
    walls: tuple[LoadedWall, ...]
    lines: dict[Loc, int] = field(default_factory=dict, compare=False, repr=False)
    warnings: tuple[str, ...] = field(default=(), compare=False)

    def names(self) -> list[str]:
        return [w.name for w in self.walls]

    def wall(self, name: str) -> LoadedWall:
        """The wall named ``name``; an InputError listing the names otherwise."""
        for w in self.walls:
            if w.name == name:
                return w
        raise InputError(
            f"no wall named {name!r}; the walls are: {', '.join(repr(n) for n in self.names())}",
            file=str(self.path),
            key="--wall",
        )


def is_building(data: Any) -> bool:
    """Whether parsed project data describes a building (a ``walls:`` key)."""
    return isinstance(data, dict) and BUILDING_KEY in data


def _entries(data: dict[str, Any], lines: Mapping[Loc, int], file: str) -> list[WallEntry]:
    """The walls' entries; every problem of the list itself (not of a wall's keys) raised."""

    def problem(message: str, *loc: str | int) -> InputError:
        return InputError(message, file=file, line=line_of(lines, loc), key=format_path(loc))

    problems: list[InputError] = []
    if "wall" in data:
        problems.append(
            problem(
                "expected exactly one of wall: (one wall) or walls: (a building's walls), "
                "found both",
                BUILDING_KEY,
            )
        )
    if "building" in data:
        problems.append(
            problem(
                "a building file gives each wall its own building: block (where that wall "
                "stands), under its item of walls:",
                "building",
            )
        )
    items = data[BUILDING_KEY]
    if not isinstance(items, list) or not items:
        what = "an empty list" if isinstance(items, list) else found(items)
        problems.append(
            problem(f"expected a list of walls (at least one), found {what}", BUILDING_KEY)
        )
        raise_all(problems)
    if len(items) > MAX_WALLS:
        problems.append(
            problem(
                f"expected at most {MAX_WALLS} walls, found {len(items)}; split the building",
                BUILDING_KEY,
            )
        )
    entries: list[WallEntry] = []
    names: dict[str, int] = {}
    slugs: dict[str, int] = {}
    for i, item in enumerate(items[:MAX_WALLS]):
        if not isinstance(item, dict):
            problems.append(
                problem(
                    "expected a wall (a mapping with name, thickness, height, ...), found "
                    f"{found(item)}",
                    BUILDING_KEY,
                    i,
                )
            )
            continue
        name = item.get("name")
        if "name" not in item:
            problems.append(
                problem("missing required key 'name' (the wall's name, unique)", BUILDING_KEY, i)
            )
            continue
        if not isinstance(name, str) or not name.strip() or len(name) > MAX_WALL_NAME:
            size = f"text of {len(name)} characters" if isinstance(name, str) else found(name)
            problems.append(
                problem(
                    f"expected text of 1 to {MAX_WALL_NAME} characters, found {size}",
                    BUILDING_KEY,
                    i,
                    "name",
                )
            )
            continue
        name = name.strip()
        slug = wall_slug(name)
        if name in names:
            problems.append(
                problem(
                    f"{name!r} is already the name of walls[{names[name]}]", BUILDING_KEY, i, "name"
                )
            )
            continue
        if slug in slugs:
            problems.append(
                problem(
                    f"{name!r} gives the same results folder walls/{slug}/ as "
                    f"walls[{slugs[slug]}]; name it otherwise",
                    BUILDING_KEY,
                    i,
                    "name",
                )
            )
            continue
        names[name], slugs[slug] = i, i
        own = frozenset(k for k in PER_WALL_BLOCKS if k in item)
        entries.append(WallEntry(i, name, slug, own))
    raise_all(problems)
    return entries


def check_wall_list(data: dict[str, Any], lines: Mapping[Loc, int], file: str) -> list[WallEntry]:
    """The entries of a building file's ``walls:`` list; every problem of the list itself
    (no list, a name missing, repeated or giving another's results folder) raised, worded
    as the file's validation words it (the TUI checks its edits of the list with it)."""
    return _entries(data, lines, file)


def building_name(data: dict[str, Any]) -> str:
    """The building's name: the file's ``project.name`` as text, else the default."""
    info = data.get("project")
    name = info.get("name") if isinstance(info, dict) else None
    return DEFAULT_BUILDING_NAME if name is None else str(name)


def wall_data(data: dict[str, Any], entry: WallEntry, building: str) -> dict[str, Any]:
    """The one-wall project data of a wall of a building file."""
    item = dict(data[BUILDING_KEY][entry.index])
    item.pop("name", None)
    out = {k: v for k, v in data.items() if k != BUILDING_KEY}
    for key in PER_WALL_BLOCKS:
        if key in item:
            out[key] = item.pop(key)
    out["wall"] = item
    info = data.get("project")
    if info is None or isinstance(info, dict):
        out["project"] = {**(info or {}), "name": f"{building}{NAME_SEPARATOR}{entry.name}"}
    return out


def wall_lines(lines: Mapping[Loc, int], entry: WallEntry) -> dict[Loc, int]:
    """The file's lines of a wall's one-wall project, by its key paths: the wall's own keys
    at their lines in its item of ``walls:``, the shared blocks' at theirs."""
    out: dict[Loc, int] = {}
    for loc, line in lines.items():
        if not loc:
            continue
        if loc[0] == BUILDING_KEY:
            if loc[1:2] != (entry.index,):
                continue
            rest = loc[2:]
            if not rest:
                out[("wall",)] = line
            elif rest[0] in PER_WALL_BLOCKS:
                out[rest] = line
            elif rest[0] != "name":
                out[("wall", *rest)] = line
        elif loc[0] not in entry.own:
            out[loc] = line
    return out


def load_building_parsed(
    data: dict[str, Any],
    lines: dict[Loc, int],
    name: str,
    *,
    base_dir: Path | str | None = None,
    check_files: bool = True,
) -> LoadedBuilding:
    """Validate a building file's parsed data: every wall as a one-wall project; every
    problem of every wall located in the file, in file order (a shared block's once)."""
    entries = _entries(data, lines, name)
    building = building_name(data)
    walls: list[LoadedWall] = []
    problems: dict[str, InputError] = {}
    warnings: dict[str, None] = {}
    for entry in entries:
        own_lines = wall_lines(lines, entry)
        try:
            loaded = load_parsed(
                wall_data(data, entry, building),
                own_lines,
                name,
                base_dir=base_dir,
                check_files=check_files,
            )
        except InputError as exc:
            for p in problems_of(exc):
                moved = entry.relocated(p)
                problems.setdefault(str(moved), moved)
            continue
        for w in project_warnings(loaded.project):
            text = str(
                InputError(
                    w.message, file=name, line=line_of(own_lines, w.loc), key=entry.file_key(w.key)
                )
            )
            warnings.setdefault(text, None)
        walls.append(LoadedWall(entry, replace(loaded, warnings=())))
    if problems:
        raise_all(sorted(problems.values(), key=lambda e: e.line or 0))
    first = walls[0].loaded
    shared = placeholder_warnings(first.project, name, first.lines)  # the shared project block
    return LoadedBuilding(
        building, first.path, first.base_dir, tuple(walls), lines, (*shared, *warnings)
    )


def load_building_text(
    text: str,
    name: str = "<project>",
    *,
    base_dir: Path | str | None = None,
    check_files: bool = True,
) -> LoadedBuilding:
    """Parse and validate a building file held in memory (as
    :func:`~frp_assess.config.loader.load_project_text`)."""
    data, lines = parse_yaml(text, name)
    if not is_building(data):
        raise InputError("expected a building file (a walls: list)", file=name, line=1)
    return load_building_parsed(data, lines, name, base_dir=base_dir, check_files=check_files)


def load_building(path: str | Path) -> LoadedBuilding:
    """Read, parse and validate a building file (as :func:`~frp_assess.config.loader.
    load_project`)."""
    path = Path(path)
    text = read_text_file(path, "project file")
    return load_building_text(text, str(path), base_dir=path.parent)
