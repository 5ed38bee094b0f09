"""A damaged cache entry is computed again with one warning, never used, never a crash."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from dataclasses import asdict, fields
from pathlib import Path

import pytest

from frp_assess.app.rerun import SIDECAR
from frp_assess.assess.cache import FIELD_CHECKS, MAX_ENTRY_BYTES, IdaCache, cache_file, entry_text
from frp_assess.cli import main
from frp_assess.dynamics import IdaPoint, IdaResult
from tests.cli.outputs_helpers import tiny_project

#: a_dyn = C·PGA, as every IDA result (frp_assess.assess.cache._consistent)
GOOD = IdaResult(
    pga=1.5, c0=0.8, collapse_multiplier=4.0, a_dyn=6.0, q=5.0, runs=23, survivor_multiplier=3.8
)
HAS_CURVE = "curve" in {f.name for f in fields(IdaResult)}
KEY = "k" * 64


def _entry(**change: object) -> str:
    data = {**asdict(GOOD), **change}
    return json.dumps(data)


def _write(text: str) -> Callable[[Path], None]:
    return lambda p: p.write_text(text, encoding="utf-8")


DAMAGE: list[tuple[str, Callable[[Path], None]]] = [
    ("bool for a number", _write(_entry(pga=True))),
    ("bool for the count", _write(_entry(runs=False))),
    ("string for a number", _write(_entry(c0="0.8"))),
    ("null for a required number", _write(_entry(pga=None))),
    ("NaN", _write(_entry().replace("6.0", "NaN"))),
    ("Infinity", _write(_entry().replace("6.0", "Infinity"))),
    ("negative", _write(_entry(a_dyn=-6.0))),
    ("half collapsed", _write(_entry(a_dyn=None))),
    ("float count", _write(_entry(runs=23.0))),
    ("missing key", _write(json.dumps({"pga": 1.2}))),
    ("extra key", _write(_entry(extra=1))),
    ("list", _write("[1, 2, 3]")),
    ("deep JSON", _write("[" * 3000 + "]" * 3000)),
    ("truncated", _write(_entry()[:40])),
    ("not UTF-8", lambda p: p.write_bytes(b"\xff\xfe{}")),
    ("huge", _write(" " * (MAX_ENTRY_BYTES + 1) + _entry())),
    ("a folder", lambda p: p.mkdir()),
    ("symlink to /dev/zero", lambda p: p.symlink_to("/dev/zero")),
    ("a FIFO", lambda p: os.mkfifo(p)),
]


@pytest.mark.parametrize("damage", [d[1] for d in DAMAGE], ids=[d[0] for d in DAMAGE])
def test_damaged_entry_is_a_miss_with_one_warning(
    tmp_path: Path, damage: Callable[[Path], None]
) -> None:
    warnings: list[str] = []
    cache = IdaCache(tmp_path / ".cache", warn=warnings.append)
    damage(cache_file(tmp_path / ".cache", KEY))
    assert cache.get(KEY) is None
    assert len(warnings) == 1 and "damaged cache entry" in warnings[0]
    assert "\n" not in warnings[0]
    cache.put(KEY, GOOD)  # the damaged entry is replaced
    assert cache.get(KEY) == GOOD and len(warnings) == 1


def test_valid_entries_and_misses_are_silent(tmp_path: Path) -> None:
    warnings: list[str] = []
    cache = IdaCache(tmp_path / ".cache", warn=warnings.append)
    assert cache.get(KEY) is None
    cache.put(KEY, GOOD)
    none = IdaResult(1.2, 0.8, None, None, None, 40, 80.0)
    cache.put("n" * 64, none)
    assert cache.get(KEY) == GOOD and cache.get("n" * 64) == none
    assert warnings == []


def test_cache_that_is_a_file_is_replaced(tmp_path: Path) -> None:
    warnings: list[str] = []
    (tmp_path / ".cache").write_text("junk", encoding="utf-8")
    cache = IdaCache(tmp_path / ".cache", warn=warnings.append)
    assert (tmp_path / ".cache").is_dir() and len(warnings) == 1
    cache.put(KEY, GOOD)
    assert cache.get(KEY) == GOOD


def test_run_recomputes_damaged_entries(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Booleans in every entry used to be taken silently and changed the results."""
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    first = (out / "results.json").read_bytes()
    entries = sorted((out / ".cache").glob("*.json"))
    for p in entries:
        data = json.loads(p.read_text(encoding="utf-8"))
        data["collapse_multiplier"] = True
        p.write_text(json.dumps(data), encoding="utf-8")
    capsys.readouterr()
    (out / SIDECAR).unlink()  # the inputs are unchanged: without this the run would stop there
    assert main(["run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    cap = capsys.readouterr()
    warnings = [line for line in cap.err.splitlines() if "damaged cache entry" in line]
    assert len(warnings) == len(entries)
    assert "Traceback" not in cap.err
    # the assessment's IDAs are reported (the cache also holds the sensitivity variants')
    res = json.loads(first)
    pairs = len(res["cases"]) * len(res["records"])
    assert len(entries) > pairs
    assert f"{pairs} IDAs computed, 0 reused" in " ".join(cap.out.split())
    assert (out / "results.json").read_bytes() == first


def test_every_field_of_an_ida_result_is_checked() -> None:
    """A field added to IdaResult needs its check here, or every entry reads as damaged."""
    assert {f.name for f in fields(IdaResult)} <= set(FIELD_CHECKS)


@pytest.mark.skipif(not HAS_CURVE, reason="IdaResult has no IDA curve in this version")
@pytest.mark.parametrize(
    "point",
    [
        {"multiplier": True, "collapsed": False, "peak_ratio": 0.5},
        {"multiplier": 1.0, "collapsed": 1, "peak_ratio": 0.5},
        {"multiplier": 1.0, "collapsed": False},
        {"multiplier": 1.0, "collapsed": False, "peak_ratio": -1.0},
        [1.0, False, 0.5],
    ],
)
def test_damaged_curve_point(tmp_path: Path, point: object) -> None:
    warnings: list[str] = []
    cache = IdaCache(tmp_path / ".cache", warn=warnings.append)
    cache_file(tmp_path / ".cache", KEY).write_text(_entry(curve=[point]), encoding="utf-8")
    assert cache.get(KEY) is None and len(warnings) == 1


@pytest.mark.parametrize(
    "result",
    [
        GOOD,
        IdaResult(
            pga=0.9,
            c0=1.1,
            collapse_multiplier=None,
            a_dyn=None,
            q=None,
            runs=3,
            survivor_multiplier=1.21,
            curve=(IdaPoint(1.1, False, 0.25), IdaPoint(1.21, False, 1.0e300)),
            failure_mode=None,
        ),
        IdaResult(
            pga=2.0,
            c0=0.5,
            collapse_multiplier=0.55,
            a_dyn=1.1,
            q=1.1,
            runs=2,
            survivor_multiplier=0.5,
            curve=(IdaPoint(0.5, False, 0.1 + 0.2), IdaPoint(0.55, True, 1.0)),
            failure_mode="rupture then overturning",
        ),
    ],
    ids=["no curve", "no collapse", "collapsed"],
)
def test_entry_text_is_the_json_of_asdict(result: IdaResult, tmp_path: Path) -> None:
    """The fast writer gives the bytes ``json.dumps(dataclasses.asdict(...))`` gave (the
    reference: the standard library), and the reader takes them back to the same result."""
    text = entry_text(result)
    assert text == json.dumps(asdict(result))
    cache = IdaCache(tmp_path)
    cache.put(KEY, result)
    assert cache_file(tmp_path, KEY).read_text(encoding="utf-8") == text
    assert cache.get(KEY) == result


@pytest.mark.slow
def test_entries_edited_consistently_by_hand_are_recomputed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Issue 36 item 6: C, a_dyn and q of every entry multiplied by 3 (each still a positive
    number, a_dyn still C·PGA) were reused without a word once the inputs sidecar was gone.
    The IDA curve says what C is (the effective collapse intensity of its samples, the
    default capacity, docs/model.md §11): such an entry is damaged, named, and
    computed again; the results are the first run's bytes.  Untouched entries of the same run
    are all reused (what a run writes passes the same checks)."""
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    first = (out / "results.json").read_bytes()
    (out / SIDECAR).unlink()
    capsys.readouterr()
    assert main(["run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    assert " 0 IDAs computed" in " " + " ".join(capsys.readouterr().out.split())
    tampered = []
    for p in sorted((out / ".cache").glob("*.json")):
        data = json.loads(p.read_text(encoding="utf-8"))
        if data["collapse_multiplier"] is None:
            continue
        for key in ("collapse_multiplier", "a_dyn", "q"):
            data[key] *= 3
        p.write_text(json.dumps(data), encoding="utf-8")
        tampered.append(p.name)
    assert tampered
    (out / SIDECAR).unlink()
    assert main(["run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    err = capsys.readouterr().err
    warned = [line for line in err.splitlines() if "damaged cache entry" in line]
    named = all("is not the effective intensity of the curve" in w for w in warned)
    assert len(warned) == len(tampered) and named, err
    assert all(any(name in w for w in warned) for name in tampered)
    assert (out / "results.json").read_bytes() == first
