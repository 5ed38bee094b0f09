"""Inputs that `run` refused but other commands crashed on (issue 36 item 5): a YAML whole number
beyond int()'s 4,300 digits (validate, run, study: the one YAML reader, config/yaml_source.py)
and a malformed SOURCE_DATE_EPOCH, which numpy.f2py reads while scipy is imported (checked
first by cli.main for every command, io_utils.source_date).  One line, exit 2."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from frp_assess.cli import main
from tests.cli.outputs_helpers import ROOT, TINY, cli_command

HUGE = "9" * 5000


@pytest.mark.parametrize("command", ["validate", "run", "study"])
def test_a_whole_number_of_5000_digits(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(TINY.replace("count: 2", f"count: {HUGE}"), encoding="utf-8")
    capsys.readouterr()
    assert main([command, str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "5000 digits" in err and ":6:" in err, err
    assert not (tmp_path / "p-results").exists()


@pytest.mark.parametrize(
    "epoch", ["abc", "1e99", "99999999999999999999", pytest.param(HUGE, id="5000-digits")]
)
def test_a_malformed_source_date_epoch_is_one_line_for_every_command(
    tmp_path: Path, epoch: str
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(TINY, encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=str(ROOT), SOURCE_DATE_EPOCH=epoch)
    for args in (["validate", str(path)], ["run", str(path), "--jobs", "1"]):
        done = subprocess.run(
            cli_command(*args), env=env, capture_output=True, text=True, timeout=300
        )
        assert done.returncode == 2, done.stderr[-3000:]
        assert done.stderr.count("\n") == 1 and "SOURCE_DATE_EPOCH: expected whole" in done.stderr
    assert not (tmp_path / "p-results").exists()


STUDY = (ROOT / "projects" / "paper-study-small.yaml").read_text(encoding="utf-8")


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("height: [1.0e-300]", "expected a number in [0.5, 50]"),
        ("alpha_deg: [1e-300]", "a wall is 0.05-5 m thick"),
        ("thickness: [1e-300]", "expected a number in [0.05, 5]"),
        ("building: {height: 10, storeys: 3, wall_base: [3.0], period: 1e-300}", "0.02"),
        ("building: {height: 10, storeys: 3, wall_base: [3.0], period: 1.0e-9}", "0.02"),
        ("building: {height: 1.0e-300, storeys: 1, wall_base: [0.0]}", "2"),
    ],
)
def test_a_study_refuses_what_a_project_refuses(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], line: str, expected: str
) -> None:
    """The ranges of a project's wall and building blocks, in a study (it crashed with a
    ZeroDivisionError, or ran a period of 1e-9 s, leaving parts-*/ behind)."""
    key = line.split(":")[0]
    text = "\n".join(
        ln for ln in STUDY.splitlines() if not ln.startswith(key) and not ln.startswith("alpha")
    )
    if key != "alpha_deg" and key != "thickness":
        text += "\nalpha_deg: [7.5]"
    path = tmp_path / "s.yaml"
    path.write_text(f"{text}\n{line}\n", encoding="utf-8")
    capsys.readouterr()
    assert main(["study", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and expected in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("command", ["records", "study"])
def test_a_table_spectrum_of_1e300_g(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str
) -> None:
    """A project's table refuses Se > 20 g; `records generate` wrote a record of zeros with
    exit 1, and a study ran it: the same range in the one reader of 'table:...' texts."""
    table = "table:0/1e300,1/1e300,4/1e300"
    out = tmp_path / "out"
    if command == "records":
        argv = ["records", "generate", "--spectrum", table, "--count", "1", "--out", str(out)]
    else:
        path = tmp_path / "s.yaml"
        path.write_text(STUDY.replace("spectrum: [A2]", f"spectrum: ['{table}']"), "utf-8")
        argv = ["study", str(path), "--out", str(out)]
    capsys.readouterr()
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "at most 20 g" in err, err
    assert not out.exists()


def test_report_of_results_it_cannot_lay_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A results.json with a currency of 100,000 characters (a run writes at most 12): the
    PDF cannot be laid out (reportlab's LayoutError crashed `report`); one line naming
    results.json, exit 2, no report.pdf."""
    import json
    import shutil

    d = tmp_path / "d"
    d.mkdir()
    shutil.copy(ROOT / "tests" / "report" / "data" / "results.json", d / "results.json")
    data = json.loads((d / "results.json").read_text(encoding="utf-8"))
    data["costs"]["currency"] = "E" * 100_000
    (d / "results.json").write_text(json.dumps(data), encoding="utf-8")
    capsys.readouterr()
    assert main(["report", str(d)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "results.json: report.pdf not written" in err, err
    assert not (d / "report.pdf").exists()
    assert not [p for p in d.iterdir() if p.name.startswith(".report.pdf")]  # no temporary


def test_report_names_what_is_wrong(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`report nope` names the missing results folder (it said "--out: the folder nope does
    not exist"); `report --docx --out r.pdf` wrote a Word file named r.pdf (issue 36 item 8)."""
    capsys.readouterr()
    assert main(["report", str(tmp_path / "nope")]) == 2
    err = capsys.readouterr().err
    assert "nope: not a results directory" in err and "--out" not in err, err
    data = ROOT / "tests" / "report" / "data"
    assert main(["report", str(data), "--docx", "--out", str(tmp_path / "r.pdf")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "ending in .docx" in err, err
    assert not (tmp_path / "r.pdf").exists()
