"""The missing-parent rule (issue 25, class 7), the same for every command with an output
path: the output itself (a results folder or a file) may be new, the folder holding it must
exist; otherwise exit 2, one line naming the missing folder, nothing created."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from frp_assess.cli import main
from tests.cli.outputs_helpers import tiny_project, tree
from tests.conftest import synthetic_record

REPORT_DATA = Path(__file__).resolve().parents[1] / "report" / "data" / "results.json"
STUDY = Path(__file__).resolve().parents[2] / "projects" / "paper-study-small.yaml"
WALL = ["--thickness", "0.4", "--height", "3", "--mechanism", "one-sided"]


def _record(tmp: Path) -> Path:
    from frp_assess.motions.record import Record
    from frp_assess.motions.writers import write_at2

    path = tmp / "r1.AT2"
    write_at2(Record("r1", 0.01, synthetic_record(3, duration=6.0, pga_g=0.3)), path)
    return path


def _args(command: str, tmp: Path, out: Path) -> list[str]:
    if command == "run":
        return ["run", str(tiny_project(tmp)), "--out", str(out), "--no-pdf"]
    if command == "study":
        return ["study", str(STUDY), "--out", str(out)]
    if command == "records":
        return ["records", "generate", "--spectrum", "A2", "--count", "1", "--out", str(out)]
    if command == "simulate":
        return ["simulate", *WALL, "--record", str(_record(tmp)), "--out", str(out / "x.csv")]
    if command == "report":
        res = tmp / "res"
        res.mkdir()
        shutil.copy(REPORT_DATA, res / "results.json")
        return ["report", str(res), "--out", str(out / "r.pdf")]
    assert command == "new"
    return ["new", str(out / "p.yaml")]


@pytest.mark.parametrize("command", ["run", "study", "records", "simulate", "report", "new"])
def test_missing_parent_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str
) -> None:
    out = tmp_path / "missing" / "deeper" / "out"
    args = _args(command, tmp_path, out)
    before = tree(tmp_path)
    code = main(args)
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.count("\n") == 1 and "Traceback" not in err
    missing = out if command in ("simulate", "report", "new") else out.parent
    assert f"the folder {missing} does not exist" in err
    assert tree(tmp_path) == before
    assert not (tmp_path / "missing").exists()


def test_a_new_output_in_an_existing_folder_is_created(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The other half of the rule: the last part of the path is created."""
    out = tmp_path / "x.csv"
    args = ["simulate", *WALL, "--record", str(_record(tmp_path)), "--out", str(out)]
    assert main(args) == 0, capsys.readouterr().err
    assert out.is_file()
