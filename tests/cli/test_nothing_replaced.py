"""The output folder never replaces nor deletes a file the tool did not write (issue 36 item 1;
frp_assess/output_record.py): a project's own ``records/`` when ``--out`` is the project's
folder, a user's report.pdf or results.csv, a report signed or edited after the run.  Each is
refused with one line (exit 2) before any work, and the user's bytes stay as they were."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.output_record import MANIFEST_NAME
from tests.cli.outputs_helpers import ROOT, TINY, tiny_project, tree

RECORDS = ROOT / "projects" / "records"


def _refused(capsys: pytest.CaptureFixture[str], argv: list[str], *names: str) -> str:
    capsys.readouterr()
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert "not a file frp-assess wrote" in err or "an input of the project" in err, err
    assert all(n in err for n in names), err
    return err


def test_out_dot_in_a_copy_of_projects_keeps_the_users_records(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The issue's case: `run boundary-wall-records.yaml --out .` in a copy of projects/
    replaced records/ (the project's inputs) by the exported records."""
    copy = tmp_path / "p"
    shutil.copytree(ROOT / "projects", copy)
    before = tree(copy)
    monkeypatch.chdir(copy)
    _refused(capsys, ["run", "boundary-wall-records.yaml", "--out", ".", "--no-pdf"], "records")
    assert tree(copy) == before  # not even a .lock


@pytest.mark.parametrize("name", ["report.pdf", "results.csv", "records/mine.AT2"])
def test_a_users_file_named_like_an_output_is_never_replaced(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], name: str
) -> None:
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    (out / name).parent.mkdir(parents=True, exist_ok=True)
    (out / name).write_bytes(b"the user's own file")
    before = tree(out)
    _refused(capsys, ["run", str(project), "--out", str(out), "--jobs", "1"], name)
    assert tree(out) == before


def test_an_input_inside_a_member_of_the_set_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A record file the project reads from the results folder's records/ (which a run
    replaces), even one the tool wrote there."""
    (tmp_path / "records").mkdir()
    shutil.copy(RECORDS / "synthetic-01.AT2", tmp_path / "records" / "a.AT2")
    text = TINY.replace(
        "artificial: {count: 2, seed: 7, duration: 15.0, dt: 0.01}",
        "files: [{path: records/a.AT2}]",
    )
    project = tiny_project(tmp_path, text=text)
    _refused(capsys, ["run", str(project), "--out", str(tmp_path)], "records/a.AT2")


@pytest.mark.slow
def test_a_report_changed_after_the_run_is_kept_and_the_tools_own_are_replaced(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A run's own set is replaced by the next run; a report signed (changed) since is not,
    nor by `frp-assess report`; a folder of an older version (no record, but the sidecar
    that holds the SHA-256 of its results.json) is taken as the tool's."""
    project = tiny_project(tmp_path)
    other = tiny_project(tmp_path, "other", project.read_text().replace("Tiny", "Other"))
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    assert (out / MANIFEST_NAME).is_file()
    os.unlink(out / MANIFEST_NAME)  # as an older version left it
    assert main(["run", str(other), "--out", str(out), "--jobs", "1"]) == 0
    assert (out / MANIFEST_NAME).is_file()
    assert main(["report", str(out), "--docx"]) == 0  # its own report: replaced
    with (out / "report.pdf").open("ab") as fh:
        fh.write(b"% signed\n")
    signed = tree(out)["report.pdf"]
    _refused(capsys, ["run", str(project), "--out", str(out), "--jobs", "1"], "report.pdf")
    _refused(capsys, ["report", str(out)], "report.pdf")
    assert tree(out)["report.pdf"] == signed


def test_report_takes_the_folder_lock_of_run(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """`report DIR --docx` (and the PDF) while a run holds the folder: refused, so a Word
    report is never made from the results a run is replacing (issue 36 item 2)."""
    import threading

    from frp_assess.output_set import FolderLock

    out = tmp_path / "out"
    shutil.copytree(ROOT / "tests" / "report" / "data", out)
    held, done = threading.Event(), threading.Event()

    def hold() -> None:
        with FolderLock(out):
            held.set()
            done.wait()

    holder = threading.Thread(target=hold)
    holder.start()
    try:
        assert held.wait(timeout=60)
        for argv in (["report", str(out), "--docx"], ["report", str(out)]):
            capsys.readouterr()
            assert main(argv) == 2
            err = capsys.readouterr().err
            assert "is writing" in err and err.count("\n") == 1, err
    finally:
        done.set()
        holder.join()
    assert not (out / "report.docx").exists() and not (out / "report.pdf").exists()
    assert main(["report", str(out), "--docx"]) == 0  # free again


@pytest.mark.slow
def test_a_report_not_made_from_the_results_beside_it_is_not_kept(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A report.docx on the record as made from other results (what a `report --docx` that
    raced a run left before it took the lock) is made again, not called unchanged."""
    import json

    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    fresh = (out / "report.docx").read_bytes()
    record = json.loads((out / MANIFEST_NAME).read_text(encoding="utf-8"))
    record["reports_of"]["report.docx"] = "1:" + "0" * 64  # made from other results
    (out / MANIFEST_NAME).write_text(json.dumps(record), encoding="utf-8")
    capsys.readouterr()
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    assert "unchanged since" not in capsys.readouterr().out
    assert (out / "report.docx").read_bytes() == fresh
    record = json.loads((out / MANIFEST_NAME).read_text(encoding="utf-8"))
    assert record["reports_of"]["report.docx"] == record["files"]["results.json"][0]
