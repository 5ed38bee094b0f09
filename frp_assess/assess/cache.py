"""On-disk cache of finished IDAs, keyed by everything that determines the result.

One small JSON file per (case, record), written atomically as soon as its IDA finishes, so an
interrupted run loses nothing and an unchanged rerun computes nothing.  An entry is trusted
only after a strict check of every field (:func:`parse_entry`); a damaged one is computed
again, with one warning line.
"""

from __future__ import annotations

import hashlib
import importlib
import json
import math
import os
import shutil
import stat
import sys
from collections.abc import Callable
from dataclasses import fields
from pathlib import Path
from typing import Any

import numpy as np

from frp_assess import __version__
from frp_assess.assess.inputs import BuildingSettings
from frp_assess.dynamics import FAILURE_MODES, IdaPoint, IdaResult, IdaSettings, RockingModel
from frp_assess.dynamics.effective import effective_capacity
from frp_assess.dynamics.loads import Loads
from frp_assess.dynamics.options import CAPACITY_RULES
from frp_assess.io_utils import atomic_write_text
from frp_assess.text_safety import plain

#: Bump when the numerics change in a way that changes results.
#: 4: the base reaction of docs/model.md §1.1 and IdaResult.failure_mode
#: 5: the effective collapse intensity (docs/model.md §11): IdaSettings.capacity and .offset,
#: IdaResult.capacity, first_collapse, windows_below and bound_multiplier
#: 6: the ties in the time histories (docs/model.md §12): a wall with ties ran without them
#: 7: no step on a round-off sliver before a sample (the peaks move by 1e-7, a yielding tie's
#: capacity by up to 2 %) and the failure mode "rupture and tie lost then overturning"
CACHE_VERSION = 7  # 2: IdaResult.survivor_multiplier; 3: keyed on every ModelOptions field


def record_digest(acc: np.ndarray, dt: float) -> str:
    h = hashlib.sha256(np.ascontiguousarray(acc, dtype=np.float64).tobytes())
    h.update(repr(float(dt)).encode())
    return h.hexdigest()


def loads_payload(loads: Loads) -> dict[str, list[list[float | bool | None]]]:
    """Every number of the loads the dynamics read (SI), for the cache key: the top loads
    (P, d, carried), the thrusts (F, h), the ties (h_t, k_t, F_y, F_a/i_t; None: infinite)."""
    return {
        "top": [[p.force, p.distance, p.carried] for p in loads.top],
        "thrusts": [[f.force, f.height] for f in loads.thrusts],
        "ties": [
            [
                t.height,
                t.stiffness,
                t.yield_force,
                t.anchorage_force if math.isfinite(t.anchorage_force) else None,
            ]
            for t in loads.ties
        ],
    }


def task_key(
    model: RockingModel,
    record_hash: str,
    settings: IdaSettings,
    building: BuildingSettings | None = None,
) -> str:
    """The cache key of one IDA: the model, the ground record's digest, the IDA rule and,
    for a wall above the ground floor, the building (its floor motion is what the IDA runs;
    a wall at ground level keeps the key it had before buildings existed)."""
    bars = model.rebars
    o = model.options
    payload = {
        "cache": CACHE_VERSION,
        "version": __version__,
        "wall": [model.wall.thickness, model.wall.height, model.wall.unit_weight],
        # the masonry's strength enters only through the base reaction (docs/model.md §1.1)
        "weight_depth": model.base_reaction.weight_depth,
        "mechanism": model.mechanism,
        "bars": None
        if bars is None
        else [
            bars.elastic_modulus,
            bars.ultimate_strain,
            bars.position,
            bars.ratio,
            bars.strain_factor,
        ],
        # every field of the model options, whatever they are (integrator settings included)
        "model": {f.name: getattr(o, f.name) for f in fields(o)},
        # every field of the IDA settings (the capacity rule and the ladder's offset included)
        "ida": {f.name: getattr(settings, f.name) for f in fields(settings)},
        "record": record_hash,
    }
    if model.loads:  # docs/model.md §12; without loads the key it had before loads existed
        payload["loads"] = loads_payload(model.loads)
    if building is not None:
        payload["building"] = [
            building.height,
            building.storeys,
            building.wall_base,
            building.period,
            building.damping,
        ]
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


def cache_file(directory: Path, key: str) -> Path:
    """Where the IDA result of ``key`` is stored in a cache directory."""
    return directory / f"{key}.json"


#: largest cache entry read [bytes]; a valid one is well under 10 kB
MAX_ENTRY_BYTES = 256 * 1024
#: most points of a stored IDA curve (a search runs a few dozen time histories)
MAX_CURVE_POINTS = 10_000

_FIELD_ORDER = tuple(f.name for f in fields(IdaResult))
_POINT_FIELDS = tuple(f.name for f in fields(IdaPoint))
_FIELDS = frozenset(_FIELD_ORDER)


class DamagedEntry(ValueError):
    """A cache entry that is not a valid IDA result (the message says why)."""


def _warn_stderr(message: str) -> None:
    print(f"frp-assess: warning: {plain(message)}", file=sys.stderr)


def _positive(key: str, v: object, *, optional: bool = False, zero: bool = False) -> object:
    if v is None and optional:
        return v
    # bool is an int to Python, but never a number here
    if isinstance(v, bool) or not isinstance(v, int | float):
        raise DamagedEntry(f"{key} is {type(v).__name__}, not a number")
    if not (math.isfinite(v) and (v >= 0 if zero else v > 0)):
        raise DamagedEntry(f"{key} = {v!r} is not a finite number {'>=' if zero else '>'} 0")
    return v


def _count(key: str, v: object) -> object:
    if isinstance(v, bool) or not isinstance(v, int) or v < 0:
        raise DamagedEntry(f"{key} = {v!r} is not a count")
    return v


def _curve(key: str, v: object) -> tuple[object, ...]:
    """The IDA curve (a list of {multiplier, collapsed, peak_ratio}) as IdaPoint objects."""
    point_type = getattr(importlib.import_module("frp_assess.dynamics.ida"), "IdaPoint", None)
    if point_type is None or not isinstance(v, list) or len(v) > MAX_CURVE_POINTS:
        raise DamagedEntry(f"{key} is not a list of at most {MAX_CURVE_POINTS} points")
    names = {f.name for f in fields(point_type)}
    points = []
    for p in v:
        if not isinstance(p, dict) or set(p) != names:
            raise DamagedEntry(f"a point of {key} is not an object with keys {sorted(names)}")
        if not isinstance(p["collapsed"], bool):
            raise DamagedEntry(f"{key}: collapsed is {type(p['collapsed']).__name__}, not a bool")
        _positive(f"{key}: multiplier", p["multiplier"])
        _positive(f"{key}: peak_ratio", p["peak_ratio"], zero=True)
        points.append(point_type(**p))
    return tuple(points)


def _failure_mode(key: str, v: object) -> object:
    """One of :data:`~frp_assess.dynamics.FAILURE_MODES`, or None."""
    if v is not None and v not in FAILURE_MODES:
        raise DamagedEntry(f"{key} = {v!r} is not a failure mode")
    return v


def _capacity(key: str, v: object) -> object:
    """One of :data:`~frp_assess.dynamics.options.CAPACITY_RULES`."""
    if v not in CAPACITY_RULES:
        raise DamagedEntry(f"{key} = {v!r} is not a capacity rule")
    return v


#: how each field of an IdaResult is checked (every field must have one: see the tests)
FIELD_CHECKS: dict[str, Callable[[str, Any], object]] = {
    "pga": _positive,
    "c0": _positive,
    "collapse_multiplier": lambda k, v: _positive(k, v, optional=True),
    "a_dyn": lambda k, v: _positive(k, v, optional=True),
    "q": lambda k, v: _positive(k, v, optional=True),
    "runs": _count,
    "survivor_multiplier": lambda k, v: _positive(k, v, optional=True),
    "curve": _curve,
    "failure_mode": _failure_mode,
    "capacity": _capacity,
    "first_collapse": lambda k, v: _positive(k, v, optional=True),
    "windows_below": _count,
    "bound_multiplier": lambda k, v: _positive(k, v, optional=True),
}


def parse_entry(text: str) -> IdaResult:
    """The :class:`IdaResult` stored in ``text``; :class:`DamagedEntry` unless every field is
    present with its exact type (numbers finite and > 0, ``runs`` a non-negative int, no
    booleans for numbers, no NaN or Infinity, no extra keys)."""

    def no_constants(name: str) -> None:
        raise DamagedEntry(f"{name} is not a number")

    try:
        data = json.loads(text, parse_constant=no_constants)
    except RecursionError:
        raise DamagedEntry("nested too deeply") from None
    except json.JSONDecodeError as exc:
        raise DamagedEntry(f"invalid JSON ({exc.msg})") from None
    if not isinstance(data, dict):
        raise DamagedEntry(f"a JSON {type(data).__name__}, not an object")
    if set(data) != _FIELDS:
        missing = sorted(_FIELDS - set(data))
        extra = sorted(set(data) - _FIELDS)
        raise DamagedEntry(f"keys missing {missing}, unexpected {extra}")
    values = {}
    for key in sorted(_FIELDS):
        check = FIELD_CHECKS.get(key)
        if check is None:
            raise DamagedEntry(f"no check for the field {key}")
        values[key] = check(key, data[key])
    collapsed = [data[k] is not None for k in ("collapse_multiplier", "a_dyn", "q")]
    if any(collapsed) and not all(collapsed):
        raise DamagedEntry("collapse_multiplier, a_dyn and q are not all set or all null")
    result = IdaResult(**values)  # type: ignore[arg-type]  # each value checked above
    _consistent(result)
    return result


def _consistent(r: IdaResult) -> None:
    """What :func:`frp_assess.dynamics.ida` makes true of every result, checked as strictly
    as an input (an entry edited by hand, C, a_dyn and q scaled together, is damaged):
    a_dyn = C·PGA; on the IDA curve, the first collapse is the least multiplier that collapsed;
    C is that first collapse (``first-collapse``) or the effective collapse intensity of the
    curve's samples (``effective``, docs/model.md §11), and the survivor the largest C that
    stood (at or below the capacity with ``effective``).  q is not checked: above the ground
    floor it is of the floor motion's a_RM."""
    c = r.collapse_multiplier
    if c is not None and r.a_dyn is not None and not math.isclose(r.a_dyn, c * r.pga, rel_tol=1e-9):
        raise DamagedEntry(f"a_dyn = {r.a_dyn!r} is not C·PGA = {c * r.pga!r}")
    if not r.curve:
        return
    fell = [p.multiplier for p in r.curve if p.collapsed]
    first = min(fell) if fell else None
    if r.capacity == "effective":
        _consistent_effective(r, first)
        return
    stood = [p.multiplier for p in r.curve if not p.collapsed]
    if first != c:
        raise DamagedEntry(
            f"collapse_multiplier = {c!r} is not the curve's first collapse {first!r}"
        )
    if (max(stood) if stood else None) != r.survivor_multiplier:
        raise DamagedEntry(
            f"survivor_multiplier = {r.survivor_multiplier!r} is not the curve's last survivor"
        )


def _consistent_effective(r: IdaResult, first: float | None) -> None:
    """:func:`_consistent` for the effective collapse intensity: recomputed from the curve."""
    if r.first_collapse != first:
        raise DamagedEntry(f"first_collapse = {r.first_collapse!r} is not the curve's {first!r}")
    c = r.collapse_multiplier
    if c is None:  # a lower bound: the wall stood at the last sample
        return
    eff = effective_capacity(
        [(p.multiplier, p.collapsed) for p in r.curve], r.c0, max(p.multiplier for p in r.curve)
    )
    if not math.isclose(eff.multiplier, c, rel_tol=1e-12):
        raise DamagedEntry(
            f"collapse_multiplier = {c!r} is not the effective intensity of the curve "
            f"{eff.multiplier!r}"
        )
    below = [p.multiplier for p in r.curve if not p.collapsed and p.multiplier <= c]
    if (max(below) if below else None) != r.survivor_multiplier:
        raise DamagedEntry(
            f"survivor_multiplier = {r.survivor_multiplier!r} is not the curve's last survivor "
            "below the capacity"
        )


class IdaCache:
    """A directory of ``<key>.json`` files; ``None`` directory disables caching.

    An entry is used only if it is a regular file (not a folder, symlink or device) of at
    most :data:`MAX_ENTRY_BYTES` that :func:`parse_entry` accepts; anything else is removed
    with one warning line (``warn``, default stderr) and the IDA is computed again.  A
    ``.cache`` that is not a folder, or is a symbolic link (never followed), is replaced by
    an empty folder, with a warning.
    """

    def __init__(self, directory: Path | None, warn: Callable[[str], None] | None = None) -> None:
        self.directory = directory
        self.warn = warn or _warn_stderr
        if directory is not None:
            if directory.is_symlink():  # never follow it: the cache would be written elsewhere
                self.warn(f"{directory} is a symbolic link; replacing it with an empty cache")
                _remove(directory)
            elif os.path.lexists(directory) and not directory.is_dir():
                self.warn(f"{directory} is not a folder; replacing it with an empty cache")
                _remove(directory)
            directory.mkdir(parents=True, exist_ok=True)

    def get(self, key: str) -> IdaResult | None:
        if self.directory is None:
            return None
        path = cache_file(self.directory, key)
        try:
            return _read_entry(path)
        except FileNotFoundError:
            return None
        except (DamagedEntry, OSError, UnicodeDecodeError) as exc:
            reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
            self.warn(f"damaged cache entry {path.name} ({reason}); computing it again")
            _remove(path)
            return None

    def put(self, key: str, result: IdaResult) -> None:
        if self.directory is not None:
            path = cache_file(self.directory, key)
            if os.path.lexists(path) and (path.is_symlink() or not path.is_file()):
                _remove(path)
            atomic_write_text(path, entry_text(result))


def entry_text(result: IdaResult) -> str:
    """The JSON of a cache entry: ``dataclasses.asdict`` of the result, built field by field
    (asdict deep-copies every point of the IDA curve: a millisecond per IDA, 14 CPU-s of the
    paper grid's 14,364 IDAs).  The same text as ``json.dumps(asdict(result))``."""
    data: dict[str, Any] = {name: getattr(result, name) for name in _FIELD_ORDER}
    data["curve"] = [{name: getattr(p, name) for name in _POINT_FIELDS} for p in result.curve]
    return json.dumps(data)


def _read_entry(path: Path) -> IdaResult:
    st = os.lstat(path)  # FileNotFoundError: a miss
    if stat.S_ISLNK(st.st_mode):
        raise DamagedEntry("a symbolic link, not a file")
    if not stat.S_ISREG(st.st_mode):
        raise DamagedEntry("not a regular file")
    if st.st_size > MAX_ENTRY_BYTES:
        raise DamagedEntry(f"{st.st_size} bytes, more than {MAX_ENTRY_BYTES}")
    fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    with os.fdopen(fd, "rb") as fh:
        raw = fh.read(MAX_ENTRY_BYTES + 1)
    if len(raw) > MAX_ENTRY_BYTES:
        raise DamagedEntry(f"more than {MAX_ENTRY_BYTES} bytes")
    return parse_entry(raw.decode("utf-8"))


def _remove(path: Path) -> None:
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        else:
            path.unlink(missing_ok=True)
    except OSError:
        pass
