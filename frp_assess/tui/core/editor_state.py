"""The editing state of the TUI as plain data, without Textual.

The editor holds the project as the same nested ``dict`` the YAML loader produces; every value
typed in a field is read as a YAML scalar (so ``0.4`` is a number and ``abc`` is text, as in
the file) and the whole dict is validated by the loader's own models and messages
(:func:`frp_assess.config.validate_data`).  Everything here is pure and unit-tested.
"""

from __future__ import annotations

import copy
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import TypeAdapter, ValidationError

from frp_assess.app.preview import (
    WallDerived,
    elastic_spectrum,
    frp_mass_per_metre,
    site_warning,
)
from frp_assess.app.preview import wall_derived as wall_preview
from frp_assess.app.project import check_record_files, parse_yaml, validate_data
from frp_assess.config.library import FRP_MATERIALS, FrpMaterial
from frp_assess.config.messages import Loc, describe, format_path, locate
from frp_assess.config.schema import (
    FrpMaterialSpec,
    Project,
    Spectrum,
    WallSpec,
)
from frp_assess.dynamics.options import PIVOT
from frp_assess.errors import InputError


class _Missing:
    """An empty field: its key is left out of the data (the schema's default applies)."""

    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()


# ------------------------------------------------------------------------ values <-> text
def format_value(value: Any) -> str:
    """How a data value is shown in a field: YAML-like, floats without a trailing ``.0``.

    Floats use Python's shortest round-trip ``repr`` so that reading the text back gives
    exactly the same number (the save round trip depends on it).
    """
    if value is None or value is MISSING:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        text = repr(value)
        return text[:-2] if text.endswith(".0") else text
    if isinstance(value, int):
        return str(value)
    if isinstance(value, list | tuple):
        return ", ".join(format_value(v) for v in value)
    return str(value)


def parse_scalar(text: str) -> Any:
    """A field's text as the YAML loader would read it; ``MISSING`` when empty.

    ``"0.4"`` -> 0.4, ``"7"`` -> 7, ``"1e-3"`` -> 0.001, ``"abc"`` -> ``"abc"``; text that
    is not valid YAML is kept as text (validation then reports it as the wrong type).
    """
    stripped = text.strip()
    if not stripped:
        return MISSING
    try:
        value, _ = parse_yaml(stripped, "<field>")
    except InputError:
        return stripped
    return value


def parse_list(text: str) -> Any:
    """A comma-separated list field (``GFRP, CFRP`` or ``[1, 2]``) as a YAML flow sequence.

    Empty text is an empty list; text that does not read as a list is returned as text.
    """
    stripped = text.strip()
    if not stripped:
        return []
    flow = stripped if stripped.startswith("[") else f"[{stripped}]"
    try:
        value, _ = parse_yaml(flow, "<field>")
    except InputError:
        return stripped
    return value if isinstance(value, list) else stripped


def get_path(data: Any, path: Loc, default: Any = MISSING) -> Any:
    """The value at a key path of nested dicts/lists, or ``default``."""
    node = data
    for key in path:
        try:
            node = node[key]
        except (KeyError, IndexError, TypeError):
            return default
    return node


def delete_path(data: dict[str, Any], path: Loc) -> None:
    """Remove the key at ``path`` if present."""
    parent = get_path(data, path[:-1], None)
    if isinstance(parent, dict):
        parent.pop(path[-1], None)


def set_path(data: dict[str, Any], path: Loc, value: Any) -> None:
    """Set the value at a key path, creating mappings; ``MISSING`` removes the key (an empty
    field leaves it out: the schema's default applies)."""
    if value is MISSING:
        delete_path(data, path)
        return
    node: Any = data
    for key in path[:-1]:
        nxt = node.get(key) if isinstance(node, dict) else None
        if not isinstance(nxt, dict):
            nxt = {}
            node[key] = nxt
        node = nxt
    node[path[-1]] = value


def without_paths(data: Any, paths: Iterable[Loc]) -> dict[str, Any]:
    """A deep copy of the mapping ``data`` without the keys at ``paths``; a mapping emptied
    by a removal goes too (``{"analysis": {"pivot": "edge"}}`` less ``analysis.pivot`` is
    ``{}``).  Not a mapping: ``{}``.

    The editor starts from what the file held less what its fields and tables own, so that
    a block it has no field for (``bars:``) is carried into the data unchanged.
    """
    out: dict[str, Any] = copy.deepcopy(data) if isinstance(data, dict) else {}
    for path in paths:
        if not path:
            continue
        parent = get_path(out, path[:-1], None)
        if not isinstance(parent, dict) or path[-1] not in parent:
            continue
        del parent[path[-1]]
        for n in range(len(path) - 1, 0, -1):  # drop the mappings left empty
            node = get_path(out, path[:n], None)
            if not (isinstance(node, dict) and not node):
                break
            holder = get_path(out, path[: n - 1], None)
            if isinstance(holder, dict):
                del holder[path[n - 1]]
    return out


def parse_key(key: str) -> Loc:
    """``seismic.records.files[0].path`` -> ``("seismic", "records", "files", 0, "path")``."""
    out: list[str | int] = []
    for part in key.split("."):
        m = re.fullmatch(r"([^\[]*)((?:\[\d+\])*)", part)
        if m is None:  # pragma: no cover - format_path never gives this
            out.append(part)
            continue
        if m.group(1):
            out.append(m.group(1))
        out.extend(int(i) for i in re.findall(r"\[(\d+)\]", m.group(2)))
    return tuple(out)


# ---------------------------------------------------------------------------- validation
@dataclass(frozen=True)
class Problem:
    """One validation problem, with the loader's wording.

    Attributes:
        path: key path the loader reports (``wall`` for a missing ``wall.thickness``).
        message: the loader's one-line message.
        target: key path of the field to show it next to (``wall.thickness``).
    """

    path: Loc
    message: str
    target: Loc

    @property
    def key(self) -> str:
        """The key path as the loader prints it (``interventions[2].ratio``)."""
        return format_path(self.path)

    def __str__(self) -> str:
        return f"{self.key}: {self.message}" if self.path else self.message


def validate_edit(data: Any) -> tuple[Project | None, list[Problem]]:
    """The project of valid data, else None and every problem, in the loader's order.

    The first problem is exactly what :func:`frp_assess.config.validate_data` raises (a test
    checks it); the others let the editor mark every faulty field at once.
    """
    try:
        return validate_data(data), []
    except InputError as exc:
        first = exc
    try:
        Project.model_validate(data)
    except ValidationError as err:
        errors = err.errors(include_url=False)
    except Exception:  # pragma: no cover - validate_data already raised a clean error
        errors = []
    else:  # pragma: no cover - validate_data raised for a non-mapping
        errors = []
    if not errors:  # not a mapping, or empty
        return None, [Problem((), first.message, ())]
    unknown = [e for e in errors if e["type"] == "extra_forbidden"]
    ordered = unknown + [e for e in errors if e["type"] != "extra_forbidden"]
    out: list[Problem] = []
    for detail in ordered:
        path, message = describe(Project, detail)
        ctx = dict(detail.get("ctx") or {})
        full = locate(Project, tuple(detail["loc"]) + tuple(ctx.get("loc", ()))).path
        missing = detail["type"] == "missing"
        out.append(Problem(tuple(path), message, tuple(full) if missing else path))
    return None, out


def record_file_problem(project: Project, base_dir: Path) -> Problem | None:
    """The loader's message for the first record file that does not exist, if any."""
    try:
        check_record_files(project, base_dir, "<project>", {})
    except InputError as exc:
        path = parse_key(exc.key or "")
        return Problem(path, exc.message, path)
    return None


# ------------------------------------------------------------------------ derived values
def wall_derived(wall: Any, analysis: Any = None, code_check: Any = None) -> WallDerived | str:
    """The derived constants of the unreinforced wall's model, or the loader's message if the
    ``wall`` block is invalid.

    The model is the one ``run`` builds: ``analysis.pivot`` and the masonry's f_d
    (``wall.masonry`` or ``wall.compressive_strength`` over the FC of
    ``code_check.knowledge_level``); a value of those two blocks that is not valid yet counts
    as its default.
    """
    try:
        spec = WallSpec.model_validate(wall)
    except ValidationError as err:
        path, message = describe(WallSpec, err.errors(include_url=False)[0])
        return f"{format_path(('wall', *path))}: {message}"
    pivot = analysis.get("pivot") if isinstance(analysis, Mapping) else None
    pivot = pivot if pivot in PIVOT.choices else PIVOT.default
    level = code_check.get("knowledge_level") if isinstance(code_check, Mapping) else None
    level = level if level in ("LC1", "LC2", "LC3") else "LC1"
    try:
        return wall_preview(spec, pivot, level)
    except InputError as exc:
        return f"wall.thickness: {exc.message}"


_SPECTRUM: TypeAdapter[Any] = TypeAdapter(Spectrum)


def spectrum_preview(spec: Any) -> Any:
    """The :class:`~frp_assess.motions.ElasticSpectrum` of a ``seismic.spectrum`` block, or
    a message (text) if the block is invalid."""
    try:
        model = _SPECTRUM.validate_python(spec)
    except ValidationError as err:
        e = err.errors(include_url=False)[0]
        return f"spectrum: {e['msg']}"
    try:
        return elastic_spectrum(model)
    except (InputError, ValueError) as exc:
        return f"spectrum: {exc}"


def spectrum_site_warning(spec: Any) -> str:
    """The warning of a site near Italy's land border for a ``seismic.spectrum`` block given
    by coordinates ("" otherwise, or if the block is invalid: its error shows elsewhere)."""
    try:
        return site_warning(_SPECTRUM.validate_python(spec))
    except (ValidationError, InputError, ValueError):
        return ""


def material_table(materials: Any) -> dict[str, FrpMaterial]:
    """The FRP library merged with the project's valid material entries (by name).

    Invalid entries are skipped, so that derived quantities still show while one is typed.
    """
    valid: dict[str, FrpMaterialSpec] = {}
    if isinstance(materials, Mapping):
        for name, spec in materials.items():
            try:
                ok = FrpMaterialSpec.model_validate(spec)
            except ValidationError:
                continue
            if str(name) in FRP_MATERIALS or all(
                getattr(ok, f) is not None
                for f in ("elastic_modulus", "ultimate_strain", "density", "price")
            ):
                valid[str(name)] = ok
    # model_construct skips validation: only the materials are read back
    return Project.model_construct(materials=valid).material_table()  # type: ignore[call-arg]


def frp_mass_per_m(
    wall: WallDerived | str,
    wall_data: Any,
    material: FrpMaterial | None,
    position: Any,
    ratio: Any,
) -> float | None:
    """Installed FRP [kg per metre of wall] of one option (both faces when external), or None
    when the wall, the material or the ratio is not valid yet."""
    if isinstance(wall, str) or material is None or position not in ("centred", "external"):
        return None
    if isinstance(ratio, bool) or not isinstance(ratio, int | float) or not 0 < ratio <= 20:
        return None
    return frp_mass_per_metre(
        float(wall_data["thickness"]), float(wall_data["height"]), material, position, float(ratio)
    )


def expand_item(item: Any) -> list[tuple[str, str, Any]]:
    """The (material, position, ratio) combinations of one ``interventions`` item."""
    if not isinstance(item, Mapping):
        return []
    if "sweep" in item:
        ax = item["sweep"] if isinstance(item["sweep"], Mapping) else {}
        mats, poss, rats = (
            value if isinstance(value := ax.get(key), list) else []
            for key in ("material", "position", "ratio")
        )
        return [(str(m), str(p), r) for m in mats for p in poss for r in rats]
    return [(str(item.get("material")), str(item.get("position")), item.get("ratio"))]
