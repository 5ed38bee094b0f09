"""A building file (``walls:``) as an editor changes it (the TUI's, wall by wall).

The editor shows one wall at a time as the one-wall project the run builds for it
(:func:`frp_assess.config.walls_file.wall_data`); what the tabs change in it is written back
into the building's data at the place the key comes from: the ``wall`` block and the
wall's own ``building`` / ``interventions`` / ``design`` into its item of ``walls:``, every
other block (site, records, materials, analysis, costs...) into the shared top level.  The
``interventions`` / ``design`` of a wall that gives none are the building's: editing them
changes them for every such wall.  Only the values that changed are written (the
difference with the wall's project as shown), so that a save rewrites only them
(:meth:`BuildingDoc.text`, with :func:`frp_assess.config.yaml_update.update_data_text`).
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

from frp_assess.config.loader import load_parsed, project_data
from frp_assess.config.messages import Loc
from frp_assess.config.walls_file import (
    BUILDING_KEY,
    NAME_SEPARATOR,
    PER_WALL_BLOCKS,
    WallEntry,
    building_name,
    check_wall_list,
    is_building,
    load_building_text,
    wall_data,
    wall_slug,
)
from frp_assess.config.yaml_source import parse_yaml
from frp_assess.config.yaml_update import update_data_text
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text

_ABSENT = object()


def _set(data: dict[str, Any], path: Loc, value: Any) -> None:
    """Set the value at a key path of nested mappings (``_ABSENT``: remove the key),
    making the mappings missing on the way."""
    node: Any = data
    for key in path[:-1]:
        if not isinstance(node.get(key), dict):
            if value is _ABSENT:
                return
            node[key] = {}
        node = node[key]
    if value is _ABSENT:
        node.pop(path[-1], None)
    else:
        node[path[-1]] = copy.deepcopy(value)


def _changes(old: Any, new: Any, path: Loc = ()) -> list[tuple[Loc, Any]]:
    """The key paths whose value differs between two nested mappings, with the new value
    (``_ABSENT`` for a key removed); lists and scalars compare as a whole."""
    if isinstance(old, dict) and isinstance(new, dict):
        out: list[tuple[Loc, Any]] = []
        for key in [*old, *(k for k in new if k not in old)]:
            out += _changes(old.get(key, _ABSENT), new.get(key, _ABSENT), (*path, key))
        return out
    return [] if old == new else [(path, new)]


class BuildingDoc:
    """The data of a building file, the wall shown, and what was last saved."""

    def __init__(self, data: dict[str, Any], name: str = "<building>") -> None:
        self.name = name
        self.data: dict[str, Any] = copy.deepcopy(data)
        self.saved: dict[str, Any] = copy.deepcopy(data)
        self.current = 0
        #: the one-wall project data shown for the current wall (what edits are compared to)
        self.shown: dict[str, Any] = {}

    @classmethod
    def from_text(cls, text: str, name: str = "<building>") -> BuildingDoc:
        data, _ = parse_yaml(text, name)
        return cls(data, name)

    # ----------------------------------------------------------------------- the walls
    @property
    def items(self) -> list[Any]:
        items = self.data.get(BUILDING_KEY)
        return items if isinstance(items, list) else []

    def names(self) -> list[str]:
        return [str(i.get("name", "")) if isinstance(i, dict) else "" for i in self.items]

    def entry(self, index: int) -> WallEntry:
        item = self.items[index]
        name = str(item.get("name", "")) if isinstance(item, dict) else ""
        own = frozenset(k for k in PER_WALL_BLOCKS if isinstance(item, dict) and k in item)
        return WallEntry(index, name, wall_slug(name), own)

    def wall_project(self, index: int, base_dir: Any = None) -> tuple[dict[str, Any], str]:
        """The one-wall project data of wall ``index`` as the editor shows it (normalised as
        the loader reads it when valid, else as its YAML reads), and its first problem."""
        raw = wall_data(self.data, self.entry(index), building_name(self.data))
        try:
            loaded = load_parsed(raw, {}, self.name, base_dir=base_dir, check_files=False)
        except InputError as exc:
            return raw, str(exc)
        return project_data(loaded.project), ""

    def show(self, index: int, base_dir: Any = None) -> tuple[dict[str, Any], str]:
        """Make wall ``index`` the current one: its project data (and first problem)."""
        self.current = index
        shown, problem = self.wall_project(index, base_dir)
        self.shown = copy.deepcopy(shown)
        return shown, problem

    # ---------------------------------------------------------------------- the edits
    def _target(self, path: Loc) -> Loc:
        """Where a key path of the current wall's project is in the building's data."""
        entry = self.entry(self.current)
        item: Loc = (BUILDING_KEY, self.current)
        if path[0] == "wall":
            return (*item, *path[1:])
        if path[0] in entry.own or path[0] == "building":
            return (*item, *path)
        return path

    def edited(self, data: dict[str, Any]) -> dict[str, Any]:
        """The building's data with the current wall's project as typed (``data``)."""
        out = copy.deepcopy(self.data)
        for path, value in _changes(self.shown, data):
            if not path:
                continue
            if path == ("project", "name"):  # the wall's project is "<building> — <wall>"
                suffix = f"{NAME_SEPARATOR}{self.entry(self.current).name}"
                if isinstance(value, str) and value.endswith(suffix):
                    value = value[: -len(suffix)]
            target = self._target(path)
            if target[0] == BUILDING_KEY:  # into the wall's item of walls:
                _set(out[BUILDING_KEY][target[1]], target[2:], value)
            else:
                _set(out, target, value)
        return out

    def store(self, data: dict[str, Any]) -> None:
        """Keep the current wall's edits (``data``, its project as typed)."""
        self.data = self.edited(data)
        self.shown = copy.deepcopy(data)

    def modified(self, data: dict[str, Any]) -> bool:
        """Whether the building with the current wall as typed differs from the file saved."""
        return self.edited(data) != self.saved

    # ---------------------------------------------------------- add, duplicate, rename...
    def _checked(self, items: list[Any]) -> str:
        """The first problem of the list of walls ``items`` as the file's validation words
        it (names unique...), "" when none."""
        try:
            check_wall_list({**self.data, BUILDING_KEY: items}, {}, self.name)
        except InputError as exc:
            return str(exc)
        return ""

    def rename(self, index: int, name: str) -> str:
        """Rename wall ``index``; the problem (the validation's message) if refused."""
        items = copy.deepcopy(self.items)
        items[index]["name"] = name.strip()
        return self._apply(items)

    def duplicate(self, index: int, name: str) -> str:
        """A copy of wall ``index`` named ``name``, after it."""
        items = copy.deepcopy(self.items)
        copied = copy.deepcopy(items[index])
        copied["name"] = name.strip()
        items.insert(index + 1, copied)
        return self._apply(items)

    def add(self, name: str) -> str:
        """A new wall (a copy of the current one's wall block, named ``name``) at the end."""
        items = copy.deepcopy(self.items)
        source = items[self.current] if items else {}
        wall = {k: v for k, v in source.items() if k not in PER_WALL_BLOCKS}
        items.append({**copy.deepcopy(wall), "name": name.strip()})
        return self._apply(items)

    def remove(self, index: int) -> str:
        """Remove wall ``index`` (never the last one: a building has at least one wall)."""
        items = copy.deepcopy(self.items)
        del items[index]
        return self._apply(items)

    def _apply(self, items: list[Any]) -> str:
        problem = self._checked(items)
        if not problem:
            self.data[BUILDING_KEY] = items
        return problem

    # --------------------------------------------------------------------------- save
    def text(self, original_text: str) -> str:
        """The file's text holding the building's data: ``original_text`` (which reads as
        the data last saved) changed only where the data changed, comments kept.  An
        InputError when the text cannot be updated so (it then does not read back as the
        data): nothing is written rather than a file that is not the building edited."""
        text = update_data_text(original_text, self.saved, self.data)
        if text is None or parse_yaml(text, self.name)[0] != self.data:
            raise InputError(
                "the file's text could not be updated in place to hold the edits (save "
                "refused: nothing written)",
                file=self.name,
            )
        return text

    def save(self, path: Path, original_text: str) -> str:
        """Write the building into ``path`` (its text from ``original_text``, the file as
        last saved, see :meth:`text`) once it reads back as a valid building; the text
        written.  An InputError (nothing written) otherwise."""
        text = self.text(original_text)
        load_building_text(text, str(path), check_files=False)
        try:
            atomic_write_text(path, text)
        except OSError as exc:
            raise InputError(f"cannot write {path}: {exc.strerror or exc}") from None
        self.saved = copy.deepcopy(self.data)
        return text


__all__ = ["BuildingDoc", "is_building"]
