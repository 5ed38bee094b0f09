"""results.json to and from :class:`~frp_assess.results.model.AssessmentResult`.

One generic pair driven by the dataclasses' type hints: a new dataclass or field in
:mod:`frp_assess.results.model` needs no change here.  Supported annotations: dataclasses,
``tuple[X, ...]``, fixed ``tuple[X, Y]``, ``list[X]``, ``dict[str, X]``, unions (``X | None``,
``str | float``: the first alternative that fits),
``float``/``int``/``str``/``bool`` and ``object`` (any JSON value, kept as read).  Every
number is finite (Python's json reads 1e999 as inf), and a field with a value check in
:mod:`frp_assess.results.read_checks` (PGA > 0, the wall's ranges, a case's name) has it
run.  A field with a default may be missing from the file (one whose metadata has
``omit_if_none`` is not written when None); an unknown key, a value of the wrong type or one
out of its range is an :class:`~frp_assess.errors.InputError` naming the file and the key
path.  Reading builds one converter per annotation, once (:func:`_converter`), so a value
costs no look-up of its annotation's origin, arguments or fields.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import json
import math
import types
import typing
from collections.abc import Callable
from typing import Any

from frp_assess.errors import InputError
from frp_assess.results.model import SCHEMA_VERSION, AssessmentResult
from frp_assess.results.read_checks import FIELD_CHECKS, OBJECT_CHECKS, FieldCheck


def to_json(obj: object) -> str:
    """``obj`` (a results dataclass) as JSON text: keys in field order, one-space indent,
    UTF-8 text kept, NaN/inf refused, a final newline."""
    return json.dumps(to_data(obj), indent=1, ensure_ascii=False, allow_nan=False) + "\n"


def to_data(obj: object) -> Any:
    """``obj`` as plain JSON values (dicts, lists, numbers, text, None)."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {
            f.name: to_data(getattr(obj, f.name))
            for f in dataclasses.fields(obj)
            if not (f.metadata.get("omit_if_none") and getattr(obj, f.name) is None)
        }
    if isinstance(obj, (tuple, list)):
        return [to_data(x) for x in obj]
    if isinstance(obj, dict):
        return {str(k): to_data(v) for k, v in obj.items()}
    return obj


def from_json(text: str, *, file: str | None = None) -> AssessmentResult:
    """Read results.json text; ``file`` names it in errors.  A ``schema_version`` other than
    :data:`~frp_assess.results.model.SCHEMA_VERSION` is refused (written by another version
    of frp-assess: run the project again)."""
    try:
        data = json.loads(text, parse_constant=_no_constant)
    except json.JSONDecodeError as exc:
        raise InputError(f"invalid JSON: {exc.msg}", file=file, line=exc.lineno) from None
    except RecursionError:
        raise InputError("invalid JSON: nested too deeply", file=file) from None
    except ValueError as exc:  # NaN, Infinity
        raise InputError(f"invalid JSON: {exc}", file=file) from None
    if not isinstance(data, dict):
        raise InputError("not a results object", file=file)
    if data.get("kind") == "building":  # results/building_summary.py: not a wall's results
        raise InputError(
            "is a building's summary (several walls); each wall's results are in its folder "
            "walls/<name>/ beside it (frp-assess report <folder>/walls/<name>)",
            file=file,
            key="kind",
        )
    version = data.get("schema_version")
    if version != SCHEMA_VERSION:
        raise InputError(
            f"unsupported schema_version {version!r} (this frp-assess reads "
            f"{SCHEMA_VERSION}); run the project again to rewrite it",
            file=file,
            key="schema_version",
        )
    result = from_data(AssessmentResult, data, file=file)
    assert isinstance(result, AssessmentResult)
    return result


def from_data(tp: Any, value: Any, *, file: str | None = None, key: str = "") -> Any:
    """``value`` (plain JSON) as the type ``tp``; raises InputError at ``key``."""
    return _converter(tp)(value, file, key)


#: converts a plain JSON value to one annotation: (value, file, key path) -> value
Converter = Callable[[Any, "str | None", str], Any]


@functools.cache
def _hints(cls: type) -> dict[str, Any]:
    return typing.get_type_hints(cls)


def _fail(file: str | None, key: str, message: str) -> InputError:
    return InputError(message, file=file, key=key or None)


def _identity(value: Any, file: str | None, key: str) -> Any:
    """Any JSON value, kept as read; a number in it finite (json reads 1e999 as inf)."""
    if isinstance(value, dict):
        for k, v in value.items():
            _identity(v, file, _join(key, k))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            _identity(v, file, f"{key}[{i}]")
    elif isinstance(value, float | int) and not _finite(value):
        raise _fail(file, key, f"expected a finite number, found {value!r}")
    return value


def _finite(value: float) -> bool:
    """Whether a JSON number is finite as a float (an integer too large for one is not)."""
    try:
        return math.isfinite(value)
    except OverflowError:
        return False


@functools.cache
def _converter(tp: Any) -> Converter:
    """The converter of the annotation ``tp``, built once per annotation: what the
    annotation asks (its origin, arguments, fields) is read here, not at every value."""
    origin = typing.get_origin(tp)
    args = typing.get_args(tp)
    if tp is object or tp is Any:
        return _identity
    if origin in (types.UnionType, typing.Union):
        return _union(args)
    if dataclasses.is_dataclass(tp):
        return _dataclass(tp)
    if origin is tuple or origin is list:
        if origin is tuple and not (len(args) == 2 and args[1] is Ellipsis):
            return _fixed_tuple(args)
        return _array(args[0], as_tuple=origin is tuple)
    if origin is dict:
        return _mapping(args[1])
    return functools.partial(_scalar, tp)


def _union(args: tuple[Any, ...]) -> Converter:
    """``X | Y | None``: None where allowed, else the first alternative that fits."""
    none_ok = type(None) in args
    inner = [a for a in args if a is not type(None)]

    def convert(value: Any, file: str | None, key: str) -> Any:
        if value is None and none_ok:
            return None
        for alternative in inner[:-1]:
            try:
                return _converter(alternative)(value, file, key)
            except InputError:
                continue
        return _converter(inner[-1])(value, file, key)

    return convert


def _fixed_tuple(args: tuple[Any, ...]) -> Converter:
    def convert(value: Any, file: str | None, key: str) -> Any:
        if not isinstance(value, list):
            raise _fail(file, key, f"expected an array, found {_kind(value)}")
        if len(value) != len(args):
            raise _fail(file, key, f"expected {len(args)} items, found {len(value)}")
        return tuple(
            _converter(a)(v, file, f"{key}[{i}]")
            for i, (a, v) in enumerate(zip(args, value, strict=True))
        )

    return convert


def _array(item: Any, *, as_tuple: bool) -> Converter:
    """``list[X]`` or ``tuple[X, ...]``."""

    def convert(value: Any, file: str | None, key: str) -> Any:
        if not isinstance(value, list):
            raise _fail(file, key, f"expected an array, found {_kind(value)}")
        fast = _plain_items(item, value)
        if fast is not None:
            return tuple(fast) if as_tuple else fast
        each = _converter(item)
        items = [each(v, file, f"{key}[{i}]") for i, v in enumerate(value)]
        return tuple(items) if as_tuple else items

    return convert


def _mapping(item: Any) -> Converter:
    """``dict[str, X]``."""

    def convert(value: Any, file: str | None, key: str) -> Any:
        if not isinstance(value, dict):
            raise _fail(file, key, f"expected an object, found {_kind(value)}")
        each = _converter(item)
        return {k: each(v, file, _join(key, k)) for k, v in value.items()}

    return convert


@functools.cache
def _field_converters(cls: Any) -> tuple[tuple[str, Converter], ...]:
    """(name, converter) of every field of the dataclass ``cls``, in field order; a field
    with a value check (:data:`~frp_assess.results.read_checks.FIELD_CHECKS`) has it run on
    the converted value."""
    hints = _hints(cls)
    converters = []
    for f in dataclasses.fields(cls):
        convert = _converter(hints[f.name])
        check = FIELD_CHECKS.get((cls, f.name))
        converters.append((f.name, convert if check is None else _checked(convert, check)))
    return tuple(converters)


def _checked(convert: Converter, check: FieldCheck) -> Converter:
    """``convert``, then the value check: its expectation and what was found, at the key."""

    def checked(value: Any, file: str | None, key: str) -> Any:
        result = convert(value, file, key)
        expected = check(result)
        if expected is not None:
            raise _fail(file, key, f"{expected}, found {_found(value)}")
        return result

    return checked


def _dataclass(cls: Any) -> Converter:
    """A results dataclass from its JSON object: every key known, every field without a
    default present.  Its fields' converters are looked up when first needed (a dataclass
    may name itself)."""
    known = frozenset(f.name for f in dataclasses.fields(cls))
    required = frozenset(
        f.name
        for f in dataclasses.fields(cls)
        if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING
    )
    object_check = OBJECT_CHECKS.get(cls)

    def convert(value: Any, file: str | None, key: str) -> Any:
        if not isinstance(value, dict):
            raise _fail(file, key, f"expected an object, found {_kind(value)}")
        unknown = [k for k in value if k not in known]
        if unknown:
            raise _fail(file, _join(key, unknown[0]), "unknown key")
        kwargs = {}
        for name, field_converter in _field_converters(cls):
            if name in value:
                kwargs[name] = field_converter(value[name], file, _join(key, name))
            elif name in required:
                raise _fail(file, _join(key, name), "missing")
        obj = cls(**kwargs)
        if object_check is not None and (wrong := object_check(obj)) is not None:
            raise _fail(
                file, _join(key, wrong[0]), f"{wrong[1]}, found {_found(value.get(wrong[0]))}"
            )
        return obj

    return convert


#: The exact JSON types each scalar annotation accepts (bool is not a number here)
_EXACT: dict[Any, tuple[type, ...]] = {bool: (bool,), int: (int,), float: (int, float), str: (str,)}


@functools.cache
def _plain_types(tp: Any) -> frozenset[Any] | None:
    """For a scalar annotation, the exact types it accepts; for a fixed tuple of scalars
    (``tuple[float, bool, float]``), every accepted tuple of the items' exact types; else
    None."""
    if tp in _EXACT:
        return frozenset(_EXACT[tp])
    args = typing.get_args(tp)
    if typing.get_origin(tp) is tuple and args and all(a in _EXACT for a in args):
        return frozenset(itertools.product(*(_EXACT[a] for a in args)))
    return None


def _plain_items(tp: Any, value: list[Any]) -> list[Any] | None:
    """The items of ``value`` converted to ``tp`` when ``tp`` is a scalar or a fixed tuple of
    scalars and every item fits (the bulk of results.json: the IDA curves), checked by their
    exact types (and every float finite) without the generic per-item walk; None otherwise
    (then the generic walk converts, or words the error with its key path).  The same values
    as the generic walk."""
    allowed = _plain_types(tp)
    if allowed is None:
        return None
    if typing.get_origin(tp) is not tuple:
        if not set(map(type, value)) <= allowed:
            return None
        return list(value) if tp is not float or _all_finite(value) else None
    items = [tuple(v) for v in value if type(v) is list]
    if len(items) != len(value) or not {tuple(map(type, v)) for v in items} <= allowed:
        return None
    floats = [i for i, a in enumerate(typing.get_args(tp)) if a is float]
    if floats and not all(_all_finite([v[i] for v in items]) for i in floats):
        return None
    return items


def _all_finite(numbers: list[Any]) -> bool:
    """Whether every number (ints and floats) is finite as a float."""
    try:
        return all(map(math.isfinite, numbers))
    except OverflowError:  # an integer too large for a float
        return False


def _scalar(tp: Any, value: Any, file: str | None, key: str) -> Any:
    if tp is bool:
        ok = isinstance(value, bool)
    elif tp is int:
        ok = isinstance(value, int) and not isinstance(value, bool)
    elif tp is float:
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        if ok and not _finite(value):
            raise _fail(file, key, f"expected a finite number, found {value!r}")
    elif tp is str:
        ok = isinstance(value, str)
    else:
        raise TypeError(f"unsupported annotation {tp!r}")
    if not ok:
        raise _fail(file, key, f"expected {tp.__name__}, found {_kind(value)}")
    return value


def _no_constant(name: str) -> None:
    raise ValueError(f"{name} is not a JSON number")


def _join(key: str, name: str) -> str:
    return f"{key}.{name}" if key else name


def _found(value: Any) -> str:
    """``value`` as an error shows it: its repr, at most 80 characters."""
    text = repr(value)
    return text if len(text) <= 80 else text[:79] + "…"


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    return {dict: "an object", list: "an array", str: "text", bool: "true/false"}.get(
        type(value), "a number"
    )
