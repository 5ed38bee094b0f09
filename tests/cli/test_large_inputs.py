"""Large but legal inputs (issue 25, classes 2-4): many records, long text, a table spectrum
at its largest — they run (or are refused up front with a reason), never a traceback, and
leave no temporary files behind."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.config.schema import MAX_TABLE_POINTS

WALL = "wall: {thickness: 0.3, height: 3.0, masonry: rubble-stone, mechanism: one-sided}\n"


def _record_text(k: int, n: int = 40, dt: float = 0.05) -> str:
    """A short two-column record, different for each k (peak 0.1 g)."""
    return "".join(f"{i * dt:.2f} {0.1 * math.sin(0.7 * i + k):.5f}\n" for i in range(n))


def _leftovers(directory: Path) -> list[Path]:
    return [p for p in directory.rglob("*") if p.name.endswith(".tmp") or ".staging-" in p.name]


def test_a_hundred_record_files_run(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """100 files (the most the schema's artificial count allows, too): the run finishes, the
    PDF included (the table with a column per record is cut into tables of 10 records)."""
    listing = ""
    for k in range(100):
        (tmp_path / f"r{k:03d}.txt").write_text(_record_text(k), encoding="utf-8")
        listing += f"      - {{path: r{k:03d}.txt}}\n"
    project = tmp_path / "p.yaml"
    project.write_text(
        "project: {name: Many records}\n"
        + WALL
        + "seismic:\n  spectrum: {type: preset, name: A2}\n  records:\n    files:\n"
        + listing
        + "analysis: {ida: {step_ratio: 2.0, tolerance: 0.1, max_multiplier: 10}}\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    code = main(["run", str(project), "--out", str(out), "--jobs", "1"])
    err = capsys.readouterr().err
    assert code in (0, 1), err
    assert "Traceback" not in err
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert len(results["records"]) == 100
    assert len(list((out / "records").iterdir())) == 100
    assert (out / "report.pdf").is_file(), err
    assert _leftovers(out) == []


def test_long_text_runs_and_is_kept_whole(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A 600-character material name, a 200-character project name and a 12-character
    currency on a 40-column console: the run answers, results.json keeps every character."""
    monkeypatch.setenv("COLUMNS", "40")
    material = "M" * 600
    project = tmp_path / "p.yaml"
    project.write_text(
        f"project: {{name: {'N' * 200}}}\n"
        + WALL
        + "seismic:\n  spectrum: {type: preset, name: A2}\n  records:\n"
        + "    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}\n"
        + f"interventions:\n  - {{material: {material}, position: centred, ratio: 1}}\n"
        + f"materials:\n  {material}: {{elastic_modulus: 50, ultimate_strain: 0.02, "
        + "density: 2000, price: 5}\n"
        + f"costs: {{currency: {'€' * 12}}}\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    code = main(["run", str(project), "--out", str(out)])
    err = capsys.readouterr().err
    assert code in (0, 1), err
    assert "Traceback" not in err
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert results["project"]["name"] == "N" * 200
    assert results["costs"]["currency"] == "€" * 12
    assert any(c["name"].startswith(material) for c in results["cases"])
    assert _leftovers(out) == []


def test_a_table_spectrum_beyond_the_limit_is_refused_up_front(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """30,000 points: one line per list, the limit named, no output folder made."""
    n = 30_000
    periods = ", ".join(f"{0.001 * i:.3f}" for i in range(n))
    accelerations = ", ".join("0.3" for _ in range(n))
    project = tmp_path / "p.yaml"
    project.write_text(
        WALL
        + f"seismic:\n  spectrum: {{type: table, periods: [{periods}], "
        + f"accelerations: [{accelerations}]}}\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 2
    assert f"expected at most {MAX_TABLE_POINTS} item(s), found {n}" in err[0]
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.yaml"]


def test_a_table_spectrum_at_the_limit_runs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    n = MAX_TABLE_POINTS
    periods = ", ".join(f"{0.004 * i:.3f}" for i in range(n))
    accelerations = ", ".join(f"{0.3 if i < 150 else 0.3 * 150 / i:.5f}" for i in range(n))
    project = tmp_path / "p.yaml"
    project.write_text(
        WALL
        + f"seismic:\n  spectrum: {{type: table, periods: [{periods}], "
        + f"accelerations: [{accelerations}]}}\n"
        + "  records:\n    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    code = main(["run", str(project), "--out", str(out)])
    err = capsys.readouterr().err
    assert code in (0, 1), err
    assert (out / "results.json").is_file()
    assert _leftovers(out) == []
