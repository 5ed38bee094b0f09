"""Hypothesis strategies for the fuzz tests: project files drawn from the project's own JSON
Schema (``frp-assess schema``), and record files in every format the readers know.

Values are mostly legal, with a share of what a careless or hostile user types: numbers at
and beyond the bounds (1e-300, subnormals, 1e308, negative zero), long and odd text, a key
of the wrong type or unknown.  The budget of examples scales with the profile
(``HYPOTHESIS_PROFILE``, see conftest.py).
"""

from __future__ import annotations

import json
import os
from typing import Any

from hypothesis import strategies as st

from frp_assess.config.library import FRP_MATERIALS, MASONRY
from frp_assess.config.schema import Project

#: the fast profile (the default) or a longer one
FAST = os.environ.get("HYPOTHESIS_PROFILE", "fast") == "fast"


def budget(fast: int, long: int) -> int:
    """max_examples of one test: ``fast`` in the default profile, ``long`` otherwise."""
    return fast if FAST else long


SCHEMA: dict[str, Any] = Project.model_json_schema()
DEFS: dict[str, Any] = SCHEMA.get("$defs", {})

#: numbers a hostile user types
EXTREME = [0.0, -0.0, 1e-300, 5e-324, 2.2250738585072014e-308, 1e-12, 1e308, -1.0, 1e6]
#: odd text: long, control characters, right-to-left marks, markup, YAML-ish
ODD_TEXT = st.sampled_from(
    [
        "x" * 600,
        "€" * 40,
        "a\tb",
        "\u202eevil",
        "[bold]x[/bold]",
        ":smile:",
        "{not: yaml}",
        "..",
        "",
        " ",
        "<placeholder>",
    ]
)


def _number(spec: dict[str, Any], integer: bool, clean: bool) -> st.SearchStrategy[Any]:
    lo = spec.get("minimum", spec.get("exclusiveMinimum"))
    hi = spec.get("maximum", spec.get("exclusiveMaximum"))
    if integer:
        lo_i = int(lo) if lo is not None else -10
        hi_i = int(hi) if hi is not None else lo_i + 100
        inside = st.integers(min_value=lo_i, max_value=min(hi_i, lo_i + 200))
        if clean:
            return inside
        edges = st.sampled_from([lo_i, hi_i, lo_i - 1, hi_i + 1, 0, 2**40])
        return st.one_of(inside, inside, edges)
    inside = st.floats(
        min_value=lo if lo is not None else -1e3,
        max_value=hi if hi is not None else 1e3,
        exclude_min="exclusiveMinimum" in spec,
        exclude_max="exclusiveMaximum" in spec,
        allow_nan=False,
        allow_infinity=False,
    )
    bounds = [b for b in (lo, hi) if b is not None]
    if clean:  # inside the range, its ends included (where they are)
        ends = [b for b in bounds if b == lo and "exclusiveMinimum" not in spec]
        ends += [b for b in bounds if b == hi and "exclusiveMaximum" not in spec]
        return st.one_of(inside, inside, st.sampled_from(ends)) if ends else inside
    edges = st.sampled_from(
        bounds + [b * (1 + 1e-12) for b in bounds] + [b * (1 - 1e-12) for b in bounds] + EXTREME
    )
    return st.one_of(inside, inside, inside, edges)


def _string(spec: dict[str, Any], clean: bool) -> st.SearchStrategy[Any]:
    if "enum" in spec:
        return st.sampled_from(spec["enum"])
    if clean:
        return st.text(alphabet="abcdefgh ÀÉ€‰-_1", min_size=1, max_size=20)
    limit = spec.get("maxLength", 40)
    plain = st.text(
        alphabet=st.characters(codec="utf-8", exclude_categories=["Cs"]),
        max_size=min(limit, 40),
    )
    return st.one_of(plain, plain, ODD_TEXT)


#: words a clean project takes for these keys (the libraries' names)
VOCAB: dict[str, list[str]] = {
    "masonry": list(MASONRY),
    "material": list(FRP_MATERIALS),
}


def from_schema(
    spec: dict[str, Any], depth: int = 0, clean: bool = False
) -> st.SearchStrategy[Any]:
    """A strategy of JSON values for the schema ``spec``: mostly valid, sometimes not; with
    ``clean``, every value inside its field's range (cross-checks: :func:`make_consistent`)."""
    if "$ref" in spec:
        name = spec["$ref"].rsplit("/", 1)[-1]
        return st.deferred(lambda: from_schema(DEFS[name], depth + 1, clean))
    if "const" in spec:
        return st.just(spec["const"])
    if "enum" in spec:
        return st.sampled_from(spec["enum"])
    for key in ("anyOf", "oneOf"):
        if key in spec:
            return st.one_of([from_schema(s, depth, clean) for s in spec[key]])
    kind = spec.get("type")
    if kind == "object":
        return _object(spec, depth, clean)
    if kind == "array":
        if "prefixItems" in spec:
            parts = (from_schema(s, depth, clean) for s in spec["prefixItems"])
            return st.tuples(*parts).map(list)
        items = spec.get("items", {})
        lo = spec.get("minItems", 0)
        hi = min(spec.get("maxItems", lo + 3), lo + 3)
        return st.lists(from_schema(items, depth + 1, clean), min_size=lo, max_size=hi)
    if kind == "number":
        return _number(spec, integer=False, clean=clean)
    if kind == "integer":
        return _number(spec, integer=True, clean=clean)
    if kind == "boolean":
        return st.booleans()
    if kind == "string":
        return _string(spec, clean)
    if kind == "null":
        return st.none()
    return st.none()


def _object(spec: dict[str, Any], depth: int, clean: bool) -> st.SearchStrategy[dict[str, Any]]:
    props: dict[str, Any] = spec.get("properties", {})
    required = set(spec.get("required", []))
    if not props:  # a mapping of names (materials)
        extra = spec.get("additionalProperties")
        if isinstance(extra, dict) and depth < 3:
            names = st.sampled_from(["GFRP", "BFRP", "CFRP", *([] if clean else ["x" * 120])])
            return st.dictionaries(names, from_schema(extra, depth + 1, clean), max_size=2)
        return st.just({})

    def field(key: str, sub: dict[str, Any]) -> st.SearchStrategy[Any]:
        if clean and key in VOCAB:
            words = st.sampled_from(VOCAB[key])
            return words if key in required else st.one_of(st.none(), words)
        if clean and key == "materials" and sub.get("type") == "array":  # design.materials
            return st.lists(st.sampled_from(VOCAB["material"]), min_size=1, max_size=2)
        strategy = from_schema(sub, depth + 1, clean)
        return strategy if key in required else st.one_of(st.none(), strategy)

    fields = {k: field(k, v) for k, v in props.items()}
    optional_keep = {k: st.booleans() for k in props if k not in required}

    @st.composite
    def build(draw: st.DrawFn) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for key, strategy in fields.items():
            if key not in required and not draw(optional_keep[key]):
                continue
            value = draw(strategy)
            if value is None and key not in required:
                continue
            out[key] = value
        return out

    return build()


#: a whole project: drawn from the schema, with now and then a mutation
PROJECT_DATA = from_schema(SCHEMA)
#: a whole project whose every value is inside its field's range
CLEAN_DATA = from_schema(SCHEMA, clean=True)
#: the record file a clean project's ``files`` entries name (written by the test)
RECORD_NAME = "r.txt"


def make_consistent(data: dict[str, Any]) -> dict[str, Any]:
    """``data`` (a clean draw) with its cross-checks met, as far as they are simple: B < H,
    a masonry or a unit weight, Z < H_b, one record source (files name :data:`RECORD_NAME`),
    an increasing table, ordered ranges and spacings, eps_fk <= eps_u, no duplicate names."""
    wall = data.get("wall", {})
    if "thickness" in wall and "height" in wall and wall["thickness"] >= wall["height"]:
        wall["thickness"] = max(0.05, wall["height"] / 10)
    if wall.get("masonry") is None and wall.get("unit_weight") is None:
        wall["masonry"] = "rubble-stone"
    building = data.get("building")
    if isinstance(building, dict) and building.get("wall_base", 0) >= building["height"]:
        building["wall_base"] = building["height"] / 2
    seismic = data.get("seismic", {})
    records = seismic.get("records")
    if isinstance(records, dict):
        if records.get("files"):
            records.pop("artificial", None)
            records["files"] = [{"path": RECORD_NAME, "format": "two-column", "units": "g"}]
        elif "artificial" not in records or records["artificial"] is None:
            records["artificial"] = {"count": 1, "duration": 13.5, "dt": 0.05}
        if isinstance(records.get("artificial"), dict):  # keep validate cheap and runs short
            records.pop("files", None)
    spectrum = seismic.get("spectrum", {})
    if spectrum.get("type") == "table":
        n = min(len(spectrum["periods"]), len(spectrum["accelerations"]))
        periods = sorted(set(spectrum["periods"][:n]))
        spectrum["periods"] = periods if len(periods) >= 2 else [0.0, 1.0]
        spectrum["accelerations"] = [
            max(a, 0.01) for a in (spectrum["accelerations"] * 2)[: len(spectrum["periods"])]
        ]
    bars = data.get("bars", {})
    if "min_spacing" in bars and "max_spacing" in bars:
        lo, hi = sorted((bars["min_spacing"], bars["max_spacing"]))
        bars["min_spacing"], bars["max_spacing"] = lo, hi
    elif "min_spacing" in bars:
        bars["max_spacing"] = max(bars["min_spacing"], 1.0)
    elif "max_spacing" in bars:
        bars["min_spacing"] = min(bars["max_spacing"], 0.1)
    if "catalogue" in bars:
        seen = {(c["material"], c["diameter"]): c for c in bars["catalogue"]}
        bars["catalogue"] = list(seen.values())
    design = data.get("design")
    if isinstance(design, dict):
        lo, hi = sorted(design.get("ratio_range", [0.5, 5.0]))
        design["ratio_range"] = [lo, hi] if lo < hi else [0.5, 5.0]
        design["resolution"] = min(design.get("resolution", 0.05), (hi - lo) or 0.05, 1.0)
        design["resolution"] = max(design["resolution"], 0.001)
    for spec in data.get("materials", {}).values():
        eps_u, eps_fk = spec.get("ultimate_strain"), spec.get("characteristic_strain")
        if eps_fk is not None and eps_u is not None and eps_fk > eps_u:
            spec["characteristic_strain"] = eps_u
        elif eps_fk is not None and eps_u is None:
            spec.pop("characteristic_strain")
    for item in data.get("interventions", []):
        if isinstance(item, dict):
            item.pop("name", None)
            item.pop("diameter", None)
    return data


@st.composite
def project_text(draw: st.DrawFn) -> str:
    """A project file's text (JSON is YAML): half of them clean (every value in range, the
    cross-checks met: they reach the mapping and the bar layout), the others raw, sometimes
    with a wrong type or an unknown key."""
    if draw(st.booleans()):
        data = make_consistent(draw(CLEAN_DATA))
        return json.dumps(data, ensure_ascii=False, allow_nan=False)
    data = draw(PROJECT_DATA)
    mutation = draw(st.sampled_from(["none"] * 6 + ["unknown", "type", "drop"]))
    if mutation != "none" and data:
        key = draw(st.sampled_from(sorted(data)))
        if mutation == "unknown":
            data["not_a_key"] = 1
        elif mutation == "type":
            data[key] = draw(st.sampled_from([[], "text", 3, None, {"x": 1}]))
        else:
            del data[key]
    return json.dumps(data, ensure_ascii=draw(st.booleans()), allow_nan=False)


# ----------------------------------------------------------------------------- record files
_SAMPLE = st.one_of(
    st.floats(min_value=-3.0, max_value=3.0, allow_nan=False, allow_infinity=False),
    st.floats(allow_nan=False, allow_infinity=False, width=64),
    st.sampled_from([0.0, 5e-324, 1e-310, -1e-300, 1e300, 1e-7, 0.5]),
)
_SAMPLES = st.lists(_SAMPLE, min_size=0, max_size=40)
_DT = st.one_of(
    st.sampled_from([0.01, 0.005, 0.02, 0.05, 1e-4, 1e-5, 0.0, -0.01, 1e-300, 1e300]),
    st.floats(min_value=1e-6, max_value=1.0),
)


def _num(x: float) -> str:
    return repr(float(x))


@st.composite
def record_file(draw: st.DrawFn) -> tuple[str, str]:
    """(format key of the project file, text of a record file) in one of the readers'
    formats, with headers and samples from sane to hostile."""
    kind = draw(st.sampled_from(["at2", "two-column", "one-column", "esm", "garbage"]))
    samples = draw(_SAMPLES)
    dt = draw(_DT)
    if kind == "at2":
        npts = draw(st.one_of(st.just(len(samples)), st.integers(-5, 10**7)))
        per_line = draw(st.integers(1, 8))
        body = "\n".join(
            " ".join(_num(v) for v in samples[i : i + per_line])
            for i in range(0, len(samples), per_line)
        )
        header = draw(
            st.sampled_from(
                [
                    f"NPTS= {npts}, DT= {dt!r} SEC",
                    f"{npts} {dt!r}",
                    f"NPTS={npts}",
                    "DT= 0.01",
                ]
            )
        )
        text = f"PEER NGA\nFUZZ\nACCELERATION TIME SERIES IN UNITS OF G\n{header}\n{body}\n"
        return "at2", text
    if kind == "two-column":
        sep = draw(st.sampled_from([" ", "\t", ";", ", "]))
        jitter = draw(st.sampled_from([0.0, 0.0, 1e-9, 1e-3]))
        rows = [
            f"{_num(i * dt + (jitter if i == 2 else 0.0))}{sep}{_num(v)}"
            for i, v in enumerate(samples)
        ]
        head = draw(st.sampled_from(["", "time acc\n", "# comment\n"]))
        return "two-column", head + "\n".join(rows) + "\n"
    if kind == "one-column":
        return "one-column", "\n".join(_num(v) for v in samples) + "\n"
    if kind == "esm":
        ndata = draw(st.one_of(st.just(len(samples)), st.integers(-1, 10**8)))
        head = (
            "EVENT_NAME: FUZZ\nNETWORK: XX\nSTATION_CODE: ST\n"
            f"NDATA: {ndata}\nSAMPLING_INTERVAL_S: {dt!r}\nUNITS: cm/s^2\n"
        )
        return "esm", head + "\n".join(_num(v) for v in samples) + "\n"
    junk = draw(st.text(max_size=200))
    return "auto", junk
