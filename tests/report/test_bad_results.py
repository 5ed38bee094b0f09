"""`frp-assess report` on a hand-edited results.json: one line, exit 2, no traceback, no PDF."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from frp_assess.cli import main
from tests.cli.outputs_helpers import tree

DATA = Path(__file__).with_name("data") / "results.json"

Edit = Callable[[dict[str, Any]], Any]


def _set(path: str, value: object) -> Edit:
    keys = path.split(".")

    def edit(r: dict[str, Any]) -> dict[str, Any]:
        node: Any = r
        for k in keys[:-1]:
            node = node[int(k)] if isinstance(node, list) else node[k]
        last = keys[-1]
        if value is _DELETE:
            del node[last]
        elif isinstance(node, list):
            node[int(last)] = value
        else:
            node[last] = value
        return r

    return edit


_DELETE = object()

ROWS: list[tuple[str, Edit | str, str]] = [
    ("missing top key", _set("wall", _DELETE), "wall: missing"),
    ("null project", _set("project", None), "project: expected an object, found null"),
    ("cases not an array", _set("cases", {"a": 1}), "cases: expected an array"),
    (
        "missing case key",
        _set("cases.0.capacity_demand", _DELETE),
        "cases[0].capacity_demand: missing",
    ),
    ("wrong type in a case", _set("cases.0.mean_q", "high"), "cases[0].mean_q: expected float"),
    ("null number", _set("wall.alpha_deg", None), "wall.alpha_deg: expected float, found null"),
    ("record not an object", _set("records.0", 3), "records[0]: expected an object"),
    ("unknown key", _set("wall.colour", "red"), "wall.colour: unknown key"),
    ("NaN", '{"schema_version": 1, "x": NaN}', "NaN is not a JSON number"),
    ("deep nesting", "[" * 100_000 + "]" * 100_000, "nested too deeply"),
    ("not JSON", "{'a': 1}", "invalid JSON"),
    ("wrong version", '{"schema_version": 99}', "unsupported schema_version"),
    # issue 36 item 6: values read back as strictly as the project file's
    (
        "PGA -1",
        _set("cases.3.records.0.pga", -1),
        "cases[3].records[0].pga: expected a finite number > 0, found -1",
    ),
    ("H -3", _set("wall.height", -3), "wall.height: expected 0.5 <= value <= 50 m, found -3"),
    ("alpha 90", _set("wall.alpha_deg", 90), "wall.alpha_deg: expected 0 < alpha_deg < 45"),
    (
        "three-sided",
        _set("wall.mechanism", "three-sided"),
        "wall.mechanism: expected one of one-sided, two-sided, found 'three-sided'",
    ),
    (
        "recommended not a case",
        _set("recommended", "GFRP centred 9‰"),
        "recommended: expected the name of one of the",
    ),
    ("language fr", _set("report", {"language": "fr"}), "report.language: expected one of en, it"),
    (
        "1e999",  # Python's json reads it as inf
        json.dumps(_set("demand.pga", 12345.678)(json.loads(DATA.read_text("utf-8")))).replace(
            "12345.678", "1e999"
        ),
        "demand.pga: expected a finite number, found inf",
    ),
]


@pytest.mark.parametrize(("edit", "fragment"), [r[1:] for r in ROWS], ids=[r[0] for r in ROWS])
def test_bad_results_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], edit: Edit | str, fragment: str
) -> None:
    d = tmp_path / "res"
    d.mkdir()
    if isinstance(edit, str):
        text = edit
    else:
        text = json.dumps(edit(json.loads(DATA.read_text(encoding="utf-8"))))
    (d / "results.json").write_text(text, encoding="utf-8")
    before = tree(tmp_path)
    assert main(["report", str(d)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("frp-assess: error: "), err
    assert fragment in err and "results.json" in err
    after = tree(tmp_path)
    after.pop("res/.lock", None)  # the lock of the results folder, taken to write report.pdf
    assert after == before


def test_a_2mb_name_is_capped(tmp_path: Path) -> None:
    d = tmp_path / "res"
    d.mkdir()
    r = json.loads(DATA.read_text(encoding="utf-8"))
    r["project"]["name"] = "N" * 2_000_000
    (d / "results.json").write_text(json.dumps(r), encoding="utf-8")
    assert main(["report", str(d)]) == 0
    assert (d / "report.pdf").stat().st_size < 2_000_000
