"""Special files where the tool reads a file (issue 36 item 3): a FIFO, ``/dev/zero``, a folder
or a file too large as the project file, the inputs sidecar or a file it lists, results.json in
``--out`` or of ``report``, ``.lock``.  Each is one line and exit 2, never a hang or a
MemoryError.  Every case runs the command in a process of its own under a generous timeout
(subprocess.run(timeout=...) in run_cli): without the guards (io_utils.read_regular, the
fstat of .lock) the FIFO cases block forever and the test fails on the timeout, not on a
measured time."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.cli.outputs_helpers import TINY, run_cli


def _stored_run(out: Path, files: list[str]) -> None:
    """An output folder as an unchanged-rerun check sees it (--no-pdf): the set's files and
    a sidecar listing ``files`` (the check reads the project and those before anything)."""
    (out / "records").mkdir(parents=True)
    for name in ("results.json", "results.csv", "spectra.csv"):
        (out / name).write_text("{}", encoding="utf-8")
    sidecar = {"digest": "sha256:0", "created": "2026-01-01", "files": files, "pdf": False}
    (out / ".inputs-digest.json").write_text(json.dumps(sidecar), encoding="utf-8")


def _fifo_project(tmp: Path) -> list[str]:
    os.mkfifo(tmp / "p.yaml")
    _stored_run(tmp / "out", [])
    return ["run", str(tmp / "p.yaml"), "--out", str(tmp / "out"), "--no-pdf"]


def _dev_zero_project(tmp: Path) -> list[str]:
    return ["run", "/dev/zero", "--out", str(tmp / "out"), "--no-pdf"]


def _folder_project(tmp: Path) -> list[str]:
    (tmp / "p.yaml").mkdir()
    return ["run", str(tmp / "p.yaml"), "--out", str(tmp / "out")]


def _huge_project(tmp: Path) -> list[str]:
    with (tmp / "p.yaml").open("wb") as fh:
        fh.truncate(3 << 30)  # sparse: 3 GB of nothing on disk
    return ["run", str(tmp / "p.yaml"), "--out", str(tmp / "out")]


def _project(tmp: Path) -> Path:
    (tmp / "p.yaml").write_text(TINY, encoding="utf-8")
    return tmp / "p.yaml"


def _fifo_sidecar(tmp: Path) -> list[str]:
    _stored_run(tmp / "out", [])
    (tmp / "out" / ".inputs-digest.json").unlink()
    os.mkfifo(tmp / "out" / ".inputs-digest.json")
    return ["run", str(_project(tmp)), "--out", str(tmp / "out"), "--no-pdf"]


def _dev_zero_sidecar(tmp: Path) -> list[str]:
    _stored_run(tmp / "out", [])
    (tmp / "out" / ".inputs-digest.json").unlink()
    os.symlink("/dev/zero", tmp / "out" / ".inputs-digest.json")
    return ["run", str(_project(tmp)), "--out", str(tmp / "out"), "--no-pdf"]


def _fifo_listed_in_sidecar(tmp: Path) -> list[str]:
    os.mkfifo(tmp / "listed")
    _stored_run(tmp / "out", ["listed", "/dev/zero"])
    return ["run", str(_project(tmp)), "--out", str(tmp / "out"), "--no-pdf"]


def _fifo_results_json(tmp: Path) -> list[str]:
    _stored_run(tmp / "out", [])
    (tmp / "out" / "results.json").unlink()
    os.mkfifo(tmp / "out" / "results.json")
    return ["run", str(_project(tmp)), "--out", str(tmp / "out"), "--no-pdf"]


def _fifo_results_json_of_report(tmp: Path) -> list[str]:
    (tmp / "out").mkdir()
    os.mkfifo(tmp / "out" / "results.json")
    return ["report", str(tmp / "out"), "--docx"]


def _fifo_lock(tmp: Path) -> list[str]:
    (tmp / "out").mkdir()
    os.mkfifo(tmp / "out" / ".lock")
    return ["run", str(_project(tmp)), "--out", str(tmp / "out"), "--no-pdf"]


def _fifo_record_file(tmp: Path) -> list[str]:
    os.mkfifo(tmp / "a.AT2")
    text = TINY.replace(
        "artificial: {count: 2, seed: 7, duration: 15.0, dt: 0.01}", "files: [{path: a.AT2}]"
    )
    (tmp / "p.yaml").write_text(text, encoding="utf-8")
    return ["run", str(tmp / "p.yaml"), "--out", str(tmp / "out")]


CASES: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "project file a FIFO, a previous run present": (_fifo_project, "pipe"),
    "project file /dev/zero": (_dev_zero_project, "device"),
    "project file a folder": (_folder_project, "folder"),
    "project file of 3 GB": (_huge_project, "MB"),
    "sidecar a FIFO": (_fifo_sidecar, "frp-assess wrote"),
    "sidecar a link to /dev/zero": (_dev_zero_sidecar, "symbolic link"),
    "a FIFO and /dev/zero listed in the sidecar": (_fifo_listed_in_sidecar, "frp-assess wrote"),
    "results.json a FIFO in --out": (_fifo_results_json, "frp-assess wrote"),
    "results.json a FIFO for report": (_fifo_results_json_of_report, "results.json"),
    ".lock a FIFO": (_fifo_lock, ".lock"),
    "a record file a FIFO": (_fifo_record_file, "a.AT2"),
}


@pytest.mark.parametrize("case", list(CASES))
def test_a_special_file_is_one_line_and_exit_2(tmp_path: Path, case: str) -> None:
    make, expected = CASES[case]
    proc = run_cli(*make(tmp_path), cwd=tmp_path)  # TimeoutExpired: it hung
    err = proc.stderr
    assert proc.returncode == 2, (proc.returncode, err[-2000:])
    assert err.count("\n") == 1 and "Traceback" not in err and "MemoryError" not in err, err
    assert expected in err, err
    assert "Invalid argument" not in err, err
