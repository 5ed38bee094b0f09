"""The generic results.json reader and writer (frp_assess.results.json_io).

References: the JSON text written by hand in each test (the stdlib ``json`` module's
reading of it), never text produced by the module under test alone.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

import pytest

from frp_assess.errors import InputError
from frp_assess.results.json_io import from_data, from_json, to_data, to_json
from frp_assess.results.model import SCHEMA_VERSION


@dataclass(frozen=True)
class Point:
    x: float
    label: str | None


@dataclass(frozen=True)
class Shape:
    name: str
    points: tuple[Point, ...]
    curve: tuple[tuple[float, bool, float], ...]
    tags: dict[str, int]
    extra: dict[str, object]
    count: int = 0  # a field added later: files without it still read


def test_a_new_dataclass_reads_and_writes_without_changes_to_json_io() -> None:
    text = (
        '{"name": "s", "points": [{"x": 1, "label": null}, {"x": 2.5, "label": "b"}], '
        '"curve": [[1.0, false, 0.5]], "tags": {"a": 1}, "extra": {"list": [1, 2]}}'
    )
    shape = from_data(Shape, json.loads(text))
    assert shape == Shape(
        "s",
        (Point(1, None), Point(2.5, "b")),
        ((1.0, False, 0.5),),
        {"a": 1},
        {"list": [1, 2]},
        0,
    )
    assert isinstance(shape.points, tuple)
    # written back: keys in field order, the integer 1 stays 1 (byte-identical files)
    assert to_data(shape) == {**json.loads(text), "count": 0}
    assert list(to_data(shape)) == ["name", "points", "curve", "tags", "extra", "count"]


@pytest.mark.parametrize(
    ("text", "key", "words"),
    [
        ('{"x": "1", "label": null}', "p.x", "expected float, found text"),
        ('{"x": true, "label": null}', "p.x", "expected float, found true/false"),
        ('{"x": 1, "label": null, "y": 2}', "p.y", "unknown key"),
        ('{"label": null}', "p.x", "missing"),
        ("[1]", "p", "expected an object, found an array"),
    ],
)
def test_a_wrong_value_names_its_key(text: str, key: str, words: str) -> None:
    with pytest.raises(InputError) as err:
        from_data(Point, json.loads(text), file="results.json", key="p")
    assert str(err.value) == f"results.json: {key}: {words}"


@pytest.mark.parametrize(
    ("curve", "key", "words"),
    [
        ("[[1.0, false, 0.5], [2.0, 1, 0.5]]", "s.curve[1][1]", "expected bool, found a number"),
        (
            "[[1.0, false, 0.5], [true, false, 0.5]]",
            "s.curve[1][0]",
            "expected float, found true/false",
        ),
        ('[[1.0, false, 0.5], [2.0, false, "x"]]', "s.curve[1][2]", "expected float, found text"),
        ("[[1.0, false, 0.5], [2.0, false]]", "s.curve[1]", "expected 3 items, found 2"),
        ("[[1.0, false, 0.5], 2.0]", "s.curve[1]", "expected an array, found a number"),
    ],
)
def test_a_wrong_item_of_a_long_array_names_its_index(curve: str, key: str, words: str) -> None:
    """The IDA curves (arrays of fixed scalar tuples) are read by their items' types at once;
    an item that does not fit is still named by its index, in the words of the generic
    reader (the expected messages are the ones that reader wrote before the shortcut)."""
    text = f'{{"name": "s", "points": [], "curve": {curve}, "tags": {{}}, "extra": {{}}}}'
    with pytest.raises(InputError) as err:
        from_data(Shape, json.loads(text), file="results.json", key="s")
    assert str(err.value) == f"results.json: {key}: {words}"


def test_long_arrays_of_scalars_keep_their_values_and_types() -> None:
    """Ints stay ints in float arrays (the file is rewritten byte for byte), bools are not
    numbers, tuples come back as tuples."""
    text = (
        '{"name": "s", "points": [], "curve": [[1, true, 2.5], [0.5, false, 3]], '
        '"tags": {}, "extra": {}}'
    )
    shape = from_data(Shape, json.loads(text))
    assert shape.curve == ((1, True, 2.5), (0.5, False, 3))
    assert [type(v) for v in shape.curve[0]] == [int, bool, float]
    assert isinstance(shape.curve, tuple) and isinstance(shape.curve[1], tuple)
    assert to_data(shape)["curve"] == json.loads(text)["curve"]


def test_another_schema_version_is_refused_in_one_line() -> None:
    text = json.dumps({"schema_version": SCHEMA_VERSION + 1})
    with pytest.raises(InputError) as err:
        from_json(text, file="out/results.json")
    line = str(err.value)
    assert line.startswith(
        f"out/results.json: schema_version: unsupported schema_version {SCHEMA_VERSION + 1} "
    )
    assert "\n" not in line


def test_text_that_is_not_json_is_refused_with_its_line() -> None:
    with pytest.raises(InputError) as err:
        from_json('{\n"schema_version": 1,\n', file="r.json")
    assert str(err.value).startswith("r.json:3: invalid JSON")


def test_to_json_refuses_nan_and_keeps_unicode() -> None:
    assert to_json(Point(1.5, "1‰")) == '{\n "x": 1.5,\n "label": "1‰"\n}\n'
    with pytest.raises(ValueError):
        to_json(Point(float("nan"), None))


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ('{"schema_version": 1, "x": NaN}', "invalid JSON: NaN is not a JSON number"),
        ("[" * 100_000 + "]" * 100_000, "invalid JSON: nested too deeply"),
    ],
)
def test_nan_and_deep_nesting_are_refused(text: str, words: str) -> None:
    with pytest.raises(InputError) as err:
        from_json(text, file="r.json")
    assert str(err.value) == f"r.json: {words}"


def test_the_results_package_needs_only_the_standard_library() -> None:
    """The contract can be read without numpy, numba or any other frp_assess package than
    the code's rules (``frp_assess.rules``, which need only the standard library too)."""
    import ast
    import sys
    from pathlib import Path

    import frp_assess.results
    import frp_assess.rules

    packages = (frp_assess.results, frp_assess.rules)
    for path in (p for m in packages for p in Path(m.__file__).parent.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                names = [node.module]
            for name in names:
                top = name.split(".")[0]
                ok = top in sys.stdlib_module_names or name.startswith(
                    ("frp_assess.errors", "frp_assess.results", "frp_assess.rules")
                )
                assert ok, (path.name, name)
