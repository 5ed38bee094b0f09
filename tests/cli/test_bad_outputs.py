"""Output folders and files that cannot be written: one table, one row per class.

Every row: exit code 2, exactly one line on stderr naming the problem, no traceback, and
nothing written (the files under the test folder are the same before and after).
"""

from __future__ import annotations

import fcntl
import os
import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.motions.record import Record
from frp_assess.motions.writers import write_at2
from tests.cli.outputs_helpers import file_size_limit, run_cli, tiny_project, tree
from tests.conftest import synthetic_record

REPORT_DATA = Path(__file__).resolve().parents[1] / "report" / "data" / "results.json"
STUDY = Path(__file__).resolve().parents[2] / "projects" / "paper-study-small.yaml"
WALL = ["--thickness", "0.4", "--height", "3", "--mechanism", "one-sided"]


def _results_dir(tmp: Path) -> Path:
    d = tmp / "res"
    d.mkdir()
    shutil.copy(REPORT_DATA, d / "results.json")
    return d


def _record(tmp: Path) -> Path:
    path = tmp / "r1.AT2"
    write_at2(Record("r1", 0.01, synthetic_record(3, duration=6.0, pga_g=0.3)), path)
    return path


def _a_file(tmp: Path) -> Path:
    f = tmp / "plain.txt"
    f.write_text("not a folder\n", encoding="utf-8")
    return f


def _locked(tmp: Path) -> Path:
    """A results folder whose lock is held by someone else (another open file description)."""
    d = tmp / "busy"
    d.mkdir()
    fd = os.open(d / ".lock", os.O_RDWR | os.O_CREAT)
    os.write(fd, b"4242\n")
    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    _HELD.append(fd)
    return d


_HELD: list[int] = []

Setup = Callable[[Path], list[str]]

ROWS: list[tuple[str, Setup, str]] = [
    (
        "run --out is a file",
        lambda t: ["run", str(tiny_project(t)), "--out", str(_a_file(t))],
        "is a file, not a folder",
    ),
    (
        "run --out under a file",
        lambda t: ["run", str(tiny_project(t)), "--out", str(_a_file(t) / "out")],
        "which is a file, not a folder",
    ),
    (
        "run --out /dev/null",
        lambda t: ["run", str(tiny_project(t)), "--out", os.devnull],
        "is a device",
    ),
    (
        "run --out locked by another run",
        lambda t: ["run", str(tiny_project(t)), "--out", str(_locked(t))],
        "another frp-assess process (pid 4242)",
    ),
    (
        "study --out is a file",
        lambda t: ["study", str(STUDY), "--out", str(_a_file(t))],
        "is a file, not a folder",
    ),
    (
        "simulate --out is a folder",
        lambda t: ["simulate", *WALL, "--record", str(_record(t)), "--out", str(t)],
        "is a folder; give a file name",
    ),
    (
        "simulate --out /dev/null",
        lambda t: ["simulate", *WALL, "--record", str(_record(t)), "--out", os.devnull],
        "is not a regular file",
    ),
    (
        "simulate --out under a file",
        lambda t: ["simulate", *WALL, "--record", str(_record(t)), "--out", f"{_a_file(t)}/h.csv"],
        "which is a file, not a folder",
    ),
    (
        "report --out is a folder",
        lambda t: ["report", str(_results_dir(t)), "--out", str(t)],
        "is a folder; give a file name",
    ),
    (
        "report --out under a file",
        lambda t: ["report", str(_results_dir(t)), "--out", f"{_a_file(t)}/r.pdf"],
        "which is a file, not a folder",
    ),
    (
        "report --out /dev/null",
        lambda t: ["report", str(_results_dir(t)), "--out", os.devnull],
        "is not a regular file",
    ),
]


@pytest.mark.parametrize(("setup", "fragment"), [r[1:] for r in ROWS], ids=[r[0] for r in ROWS])
def test_bad_output_one_line_exit_2_nothing_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], setup: Setup, fragment: str
) -> None:
    argv = setup(tmp_path)
    before = tree(tmp_path)
    try:
        assert main(argv) == 2
    finally:
        while _HELD:
            os.close(_HELD.pop())
    cap = capsys.readouterr()
    assert cap.err.count("\n") == 1 and cap.err.startswith("frp-assess: error: "), cap.err
    assert fragment in cap.err
    assert "Traceback" not in cap.err + cap.out
    assert tree(tmp_path) == before


def test_read_only_out_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A folder the user may not write. The tests run as root, for whom permission bits do not
    apply, so the permission check (os.access) is made to answer as for an ordinary user."""
    ro = tmp_path / "ro"
    ro.mkdir()
    real_access = os.access
    monkeypatch.setattr(
        os, "access", lambda p, mode, **kw: False if Path(p) == ro else real_access(p, mode)
    )
    project = tiny_project(tmp_path)
    before = tree(tmp_path)
    assert main(["run", str(project), "--out", str(ro / "results")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "is not writable" in err
    assert tree(tmp_path) == before


# --- the disk fills up while writing (a file size limit makes every write beyond it fail) ----


@pytest.mark.slow
def test_full_disk_during_run_keeps_the_previous_set(tmp_path: Path) -> None:
    """The first run, on a disk with room, calls the CLI's main() in the test's process; the
    second is a process of its own, as the file size limit must not reach the test's."""
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--no-pdf", "--jobs", "1"]) == 0
    # a different project into the same folder, on a full disk
    other = tiny_project(
        tmp_path, "other", (tmp_path / "tiny.yaml").read_text().replace("seed: 7", "seed: 8")
    )
    before = tree(out)
    full = run_cli(
        "run", str(other), "--out", str(out), "--jobs", "1", preexec=file_size_limit(60_000)
    )
    assert full.returncode == 2
    assert full.stderr.count("\n") == 1 and "File too large" in full.stderr, full.stderr
    assert "Traceback" not in full.stderr
    after = tree(out)
    # the old set is untouched; only the cache has grown (finished IDAs are kept) and the
    # lock file names the last holder

    def output_set(t: dict[str, bytes | None]) -> dict[str, bytes | None]:
        return {k: v for k, v in t.items() if not k.startswith((".cache", ".lock"))}

    assert output_set(after) == output_set(before)


@pytest.mark.slow
@pytest.mark.parametrize("command", ["simulate", "report", "records generate"])
def test_full_disk_in_other_writers(tmp_path: Path, command: str) -> None:
    if command == "simulate":
        target = tmp_path / "h.csv"
        argv = ["simulate", *WALL, "--record", str(_record(tmp_path)), "--out", str(target)]
        watch = tmp_path
    elif command == "report":
        d = _results_dir(tmp_path)
        argv = ["report", str(d)]
        watch = d
    else:
        watch = tmp_path / "recs"
        argv = ["records", "generate", "--spectrum", "A2", "--count", "2", "--out", str(watch)]
    before = tree(watch)
    res = run_cli(*argv, preexec=file_size_limit(2_000))
    assert res.returncode == 2, res.stderr
    assert res.stderr.count("\n") == 1 and "File too large" in res.stderr, res.stderr
    assert "Traceback" not in res.stderr
    assert f"error: {watch}" in res.stderr, res.stderr  # which file (issue 36 item 8)
    after = tree(watch)
    after.pop(".lock", None)  # the report took the results folder's lock (a run may write it)
    assert not [k for k in after if k.endswith(".tmp")]  # no half-written file left
    assert after == before  # nothing half-written (records generate stages its set too)


def test_argument_errors_carry_no_escape_sequence(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exc:
        main(["run", "x.yaml", "--jobs", "1\x1b[2J\x07"])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "\x1b" not in err and "\x07" not in err and "--jobs" in err
