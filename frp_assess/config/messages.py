"""Pydantic validation errors as one line a user can act on.

``wall.thickness: expected a number > 0, found -0.4`` -- the key path in YAML terms
(``interventions[2].sweep.ratio[0]``), what was expected and what was found.  The locations
pydantic reports contain the tags of discriminated unions (``ntc2018``, ``sweep``...); they are
removed by walking the schema's annotations alongside the location.
"""

from __future__ import annotations

import types
import typing
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal, Union, get_args, get_origin

import annotated_types as at
from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from frp_assess.config.library import did_you_mean
from frp_assess.errors import InputError

Loc = tuple[str | int, ...]

#: error types whose message is complete as raised (the schema's own cross-checks)
OWN_MESSAGES = frozenset(
    {"value_error", "assertion_error", "cross_check", "unknown_masonry", "restitution"}
)


@dataclass(frozen=True)
class Located:
    """Where an error is: the key path in the data and the field there, if resolved."""

    path: Loc  #: key path in the YAML data (union tags removed)
    annotation: Any = None  #: annotation at the end of the path, or None
    field: FieldInfo | None = None  #: the model field at the end of the path, if any
    parent: type[BaseModel] | None = None  #: the model holding the last key, if any


def format_path(path: Sequence[str | int]) -> str:
    """``('interventions', 2, 'sweep')`` -> ``interventions[2].sweep``."""
    out = ""
    for elem in path:
        if isinstance(elem, int):
            out += f"[{elem}]"
        else:
            out += ("." if out else "") + str(elem)
    return out


def _strip(ann: Any) -> tuple[Any, list[Any]]:
    """Remove ``Annotated`` layers; return the bare type and the collected metadata."""
    meta: list[Any] = []
    while get_origin(ann) is typing.Annotated:
        args = get_args(ann)
        ann, meta = args[0], [*meta, *args[1:]]
    return ann, meta


def _is_union(ann: Any) -> bool:
    return get_origin(ann) in (Union, types.UnionType)


def _tag_of(member: Any) -> str | None:
    bare, meta = _strip(member)
    for m in meta:
        tag = getattr(m, "tag", None)
        if isinstance(tag, str):
            return tag
    if isinstance(bare, type) and issubclass(bare, BaseModel) and "type" in bare.model_fields:
        args = get_args(bare.model_fields["type"].annotation)
        if len(args) == 1:
            return str(args[0])
    return None


def locate(root: type[BaseModel], loc: Loc) -> Located:
    """Walk ``loc`` from the model ``root``, dropping union tags from the path."""
    ann: Any = root
    field: FieldInfo | None = None
    parent: type[BaseModel] | None = None
    path: list[str | int] = []
    for item in loc:
        elem: str | int | None = item
        bare, _ = _strip(ann)
        while _is_union(bare):
            members = [m for m in get_args(bare) if m is not type(None)]
            tagged = {_tag_of(m): m for m in members}
            if isinstance(elem, str) and elem in tagged and len(members) > 1:
                bare, _ = _strip(tagged[elem])
                elem = None  # consumed by the union
                break
            if len(members) == 1:
                bare, _ = _strip(members[0])
            else:
                return Located(tuple(path) + tuple(loc[len(path) :]), None, None, None)
        if elem is None:
            ann = bare
            continue
        path.append(elem)
        field = None
        parent = None
        if isinstance(bare, type) and issubclass(bare, BaseModel) and isinstance(elem, str):
            parent = bare
            if elem not in bare.model_fields:
                ann = None
                continue
            field = bare.model_fields[elem]
            ann = field.annotation
        elif get_origin(bare) in (list, tuple) and isinstance(elem, int):
            args = get_args(bare)
            ann = args[min(elem, len(args) - 1)] if get_origin(bare) is tuple else args[0]
        elif get_origin(bare) is dict:
            ann = get_args(bare)[1]
        else:
            ann = None
    return Located(tuple(path), ann, field, parent)


def _bounds(located: Located) -> dict[str, float]:
    """The numeric bounds (gt, ge, lt, le) of the value at the end of the path."""
    meta: list[Any] = list(located.field.metadata) if located.field is not None else []
    ann = located.annotation
    while ann is not None:
        bare, more = _strip(ann)
        meta.extend(more)
        members = [m for m in get_args(bare) if m is not type(None)] if _is_union(bare) else []
        ann = members[0] if len(members) == 1 else None
    out: dict[str, float] = {}
    meta = [x for m in meta for x in (m.metadata if isinstance(m, FieldInfo) else [m])]
    for m in meta:
        for name, cls in (("gt", at.Gt), ("ge", at.Ge), ("lt", at.Lt), ("le", at.Le)):
            if isinstance(m, cls):
                out[name] = getattr(m, name)
    return out


def _literals(located: Located) -> list[Any]:
    ann = located.annotation
    while ann is not None:
        bare, _ = _strip(ann)
        if get_origin(bare) is Literal:
            return list(get_args(bare))
        members = [m for m in get_args(bare) if m is not type(None)] if _is_union(bare) else []
        ann = members[0] if len(members) == 1 else None
    return []


def found(value: Any) -> str:
    """How a found value is shown: YAML-like scalars, or the kind of a container."""
    if value is None:
        return "nothing (null)"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return f"{value:.12g}" if isinstance(value, float) else str(value)
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list | tuple):
        return "a list"
    return repr(str(value))


def _range_text(b: dict[str, float]) -> str:
    lo = f"({b['gt']:.12g}" if "gt" in b else f"[{b['ge']:.12g}" if "ge" in b else None
    hi = f"{b['lt']:.12g})" if "lt" in b else f"{b['le']:.12g}]" if "le" in b else None
    if lo and hi:
        return f"a number in {lo}, {hi}"
    parts = [
        f"{op} {b[k]:.12g}"
        for k, op in (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<="))
        if k in b
    ]
    return "a number " + " and ".join(parts)


def describe(root: type[BaseModel], err: ErrorDetails) -> tuple[Loc, str]:
    """The key path (YAML terms) and the one-line message of one pydantic error."""
    kind = err["type"]
    ctx = dict(err.get("ctx") or {})
    loc = tuple(err["loc"]) + tuple(ctx.get("loc", ()))
    located = locate(root, loc)
    path = located.path
    value = err.get("input")
    what = found(value)
    if kind in ("greater_than", "greater_than_equal", "less_than", "less_than_equal"):
        bounds = _bounds(located) or {k: v for k, v in ctx.items() if k in ("gt", "ge", "lt", "le")}
        return path, f"expected {_range_text(bounds)}, found {what}"
    if kind == "extra_forbidden":
        key = str(path[-1]) if path else "?"
        names = list(located.parent.model_fields) if located.parent is not None else []
        hint = did_you_mean(key, names)
        if not hint and names:
            hint = f" (expected one of {', '.join(names)})"
        return path, f"unknown key {key!r}{hint}"
    if kind == "missing":
        key = str(path[-1]) if path else "?"
        desc = (
            f" ({located.field.description})" if located.field and located.field.description else ""
        )
        return path[:-1], f"missing required key {key!r}{desc}"
    if kind == "literal_error":
        options = _literals(located)
        if options:
            listed = ", ".join(str(o) for o in options)
            hint = (
                did_you_mean(str(value), [str(o) for o in options])
                if isinstance(value, str)
                else ""
            )
            return path, f"expected one of {listed}, found {what}{hint}"
        return path, f"expected {ctx.get('expected')}, found {what}"
    if kind == "union_tag_invalid":
        tags = [t.strip(" '") for t in str(ctx.get("expected_tags", "")).split(",")]
        hint = did_you_mean(str(ctx.get("tag")), tags)
        return (
            *path,
            "type",
        ), f"unknown type {found(ctx.get('tag'))}{hint}; expected one of {', '.join(tags)}"
    if kind == "union_tag_not_found":
        return (
            path,
            f"missing key {ctx.get('discriminator', 'type')} (the kind: {_tag_names(located)})",
        )
    if kind == "finite_number":
        return path, (
            f"expected a finite number, found {what} (1e400 and .inf are infinite, .nan is not "
            "a number)"
        )
    if kind in ("string_too_long", "string_too_short"):
        n = ctx.get("max_length") if kind == "string_too_long" else ctx.get("min_length")
        word = "at most" if kind == "string_too_long" else "at least"
        length = len(value) if isinstance(value, str) else "?"
        return path, f"expected text of {word} {n} characters, found {length}"
    if kind in ("float_type", "float_parsing"):
        return path, f"expected a number, found {what}"
    if kind in ("int_type", "int_parsing", "int_from_float"):
        return path, f"expected a whole number, found {what}"
    if kind in ("string_type", "string_sub_type"):
        return path, f"expected text, found {what}"
    if kind in ("bool_type", "bool_parsing"):
        return path, f"expected true or false, found {what}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return path, f"expected a mapping (key: value lines), found {what}"
    if kind in ("list_type", "tuple_type", "sequence_str"):
        return path, f"expected a list, found {what}"
    if kind in ("too_short", "too_long"):
        n = ctx.get("min_length") if kind == "too_short" else ctx.get("max_length")
        word = "at least" if kind == "too_short" else "at most"
        return path, f"expected {word} {n} item(s), found {ctx.get('actual_length')}"
    msg = str(err["msg"]).removeprefix("Value error, ").removeprefix("Assertion failed, ")
    if kind in OWN_MESSAGES or "found" in msg:
        return path, msg
    return path, f"{msg}; found {what}"


def _tag_names(located: Located) -> str:
    bare, _ = _strip(located.annotation)
    if not _is_union(bare):
        return "?"
    return ", ".join(str(_tag_of(m)) for m in get_args(bare) if _tag_of(m))


def line_of(lines: Mapping[Loc, int], path: Loc) -> int | None:
    """Line of ``path`` or of its longest prefix present in ``lines``; None if none is."""
    for n in range(len(path), 0, -1):
        if path[:n] in lines:
            return lines[path[:n]]
    return None


#: most pydantic errors described for one file (a 100,000-item list of bad values gives as
#: many errors; :func:`~frp_assess.config.problems.raise_all` shows the first 50 anyway)
MAX_DESCRIBED = 500


def schema_problems(
    root: type[BaseModel],
    exc: ValidationError,
    *,
    file: str | None,
    lines: Mapping[Loc, int] | None,
) -> list[InputError]:
    """Every problem of a validation error as a one-line InputError.

    A "missing" key that an unknown key of the same mapping is a misspelling of (``hieght``
    for ``height``) is not repeated.  With ``lines`` (key path -> line) the problems are in
    file order, a missing key at the line of its mapping; without, unknown keys first.
    """
    errors = exc.errors(include_url=False)[:MAX_DESCRIBED]
    described = [(err["type"], *describe(root, err)) for err in errors]
    unknown = [
        (path[:-1], str(path[-1]))
        for kind, path, _ in described
        if kind == "extra_forbidden" and path
    ]
    out: list[tuple[int, int, InputError]] = []
    seen: set[tuple[Loc, str]] = set()
    for index, (kind, path, message) in enumerate(described):
        if kind == "missing":
            wanted = str(errors[index]["loc"][-1])
            if any(parent == path and did_you_mean(key, [wanted]) for parent, key in unknown):
                continue
        if (path, message) in seen:
            continue
        seen.add((path, message))
        line = None
        if lines is not None:
            line = line_of(lines, path) or 1  # a missing top-level key: the file's start
        rank = 0 if kind == "extra_forbidden" else 1
        order = line if line is not None else rank
        out.append(
            (order, index, InputError(message, file=file, line=line, key=format_path(path) or None))
        )
    out.sort(key=lambda item: (item[0], item[1]))
    return [problem for _, _, problem in out]
