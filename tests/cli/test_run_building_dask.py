"""`frp-assess run BUILDING.yaml --executor dask` (issue 41 item 6): the walls' IDAs on the
study's Dask executor give each wall's output files byte for byte as the local threads do
(the same :func:`frp_assess.dynamics.ida` on the same inputs: only the scheduling differs);
without dask, or for a one-wall project, one line and exit 2."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest

from frp_assess.cli import main
from tests.cli.test_run_building import CREATED, FIXTURE, SLUGS


def _run(tmp_path: Path, name: str, *extra: str) -> Path:
    project = tmp_path / "building.yaml"
    if not project.exists():
        shutil.copyfile(FIXTURE, project)
    out = tmp_path / name
    argv = ["run", str(project), "--out", str(out), "--no-pdf", "--created", CREATED, *extra]
    assert main(argv) == 0
    return out


@pytest.mark.slow
def test_dask_and_local_give_each_wall_the_same_bytes(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The small building (three walls: ground, an upper floor with its own option, a
    parapet) run on local threads and on a LocalCluster of 2 workers: every wall's
    results.json, results.csv and spectra.csv, and the building's results.json and
    results.csv, equal byte for byte; every IDA computed on Dask."""
    pytest.importorskip("dask")
    pytest.importorskip("distributed")
    local = _run(tmp_path, "local", "--jobs", "2")
    capsys.readouterr()
    dask = _run(tmp_path, "dask", "--executor", "dask", "--jobs", "2")
    printed = capsys.readouterr().out
    assert "walls' IDAs on Dask LocalCluster, 2 workers" in printed
    assert "reused from the cache" in printed and "0 reused" in printed
    for slug in SLUGS:
        for name in ("results.json", "results.csv", "spectra.csv"):
            here, there = local / "walls" / slug / name, dask / "walls" / slug / name
            assert there.read_bytes() == here.read_bytes(), f"{slug}/{name}"
    for name in ("results.json", "results.csv"):
        assert (dask / name).read_bytes() == (local / name).read_bytes()


def test_without_dask_one_line_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """dask not importable (``sys.modules`` entry None makes the import fail, as when the
    extra is not installed): one line naming --executor and the extra, exit 2, no folder."""
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    project = tmp_path / "building.yaml"
    shutil.copyfile(FIXTURE, project)
    out = tmp_path / "out"
    argv = ["run", str(project), "--out", str(out), "--executor", "dask"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "--executor" in err and "frp-assess[dask]" in err
    assert not (out / "walls").exists()


def test_a_one_wall_project_refuses_the_executor(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``--executor dask`` runs a building's walls; a one-wall project: one line, exit 2."""
    project = Path(__file__).parents[1] / "fixtures" / "facade-loads.yaml"
    assert main(["run", str(project), "--out", str(tmp_path / "o"), "--executor", "dask"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "one-wall project" in err and "--executor" in err
