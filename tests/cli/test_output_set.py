"""A run's outputs are one set: interrupted, failed, concurrent or repeated runs never leave
files of two runs side by side."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import time
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.output_set import STAGING_PREFIX
from tests.cli.outputs_helpers import ROOT, cli_command, tiny_project, tree


def assert_valid_set(out: Path, *, pdf: bool) -> dict:
    """results.json parses, and the other members belong to it."""
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    names = sorted(f"{r['name']}.AT2" for r in results["records"])
    assert sorted(p.name for p in (out / "records").iterdir()) == names
    csv = (out / "results.csv").read_text(encoding="utf-8")
    for case in results["cases"]:
        assert case["name"] in csv
    assert (out / "spectra.csv").is_file()
    assert (out / "report.pdf").is_file() == pdf
    assert (out / "report.docx").is_file() == pdf
    assert not [p for p in out.iterdir() if p.name.startswith(STAGING_PREFIX)]
    return results


@pytest.mark.slow
def test_kill_9_mid_run_then_rerun_gives_the_same_results(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Only the killed run is a process of its own (SIGKILL needs one); the reference run
    and the rerun call the CLI's main() in the test's process (the same command, exit code,
    output and files, without two more interpreter start-ups)."""
    project = tiny_project(tmp_path)
    assert main(["run", str(project), "--out", str(tmp_path / "ref"), "--jobs", "1"]) == 0
    out = tmp_path / "killed"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen(
        cli_command("run", str(project), "--out", str(out), "--jobs", "1"),
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    cache = out / ".cache"
    try:
        # wait for a state, not for a time: the first finished IDA is in the cache
        while proc.poll() is None and not (cache.is_dir() and any(cache.glob("*.json"))):
            time.sleep(0.01)
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    assert proc.returncode == -signal.SIGKILL, "the run finished before it could be killed"
    assert not (out / "results.json").exists()
    capsys.readouterr()
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    assert "reused from the cache" in capsys.readouterr().out
    assert (out / "results.json").read_bytes() == (tmp_path / "ref" / "results.json").read_bytes()
    for report in ("report.pdf", "report.docx"):
        assert (out / report).read_bytes() == (tmp_path / "ref" / report).read_bytes()
    assert_valid_set(out, pdf=True)


@pytest.mark.slow
def test_two_runs_into_one_folder_at_once(tmp_path: Path) -> None:
    project = tiny_project(tmp_path)
    out = tmp_path / "shared"
    env = dict(os.environ, PYTHONPATH=str(ROOT), COLUMNS="100")
    procs = [
        subprocess.Popen(
            cli_command("run", str(project), "--out", str(out), "--jobs", "1", "--no-pdf"),
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for _ in range(2)
    ]
    outcomes = [(p.wait(timeout=300), p.stderr.read()) for p in procs]  # type: ignore[union-attr]
    for p in procs:
        p.stdout.close()  # type: ignore[union-attr]
        p.stderr.close()  # type: ignore[union-attr]
    codes = sorted(code for code, _ in outcomes)
    assert codes in ([0, 0], [0, 2]), outcomes
    for code, err in outcomes:
        if code == 2:
            assert err.count("\n") == 1 and "another frp-assess process" in err, err
            assert "Traceback" not in err
    assert_valid_set(out, pdf=False)


def test_failed_pdf_keeps_the_previous_set(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    before = tree(out)

    import frp_assess.app.report as api

    def broken(results: dict, path: Path) -> bool:
        path.write_bytes(b"%PDF half")
        raise OSError(28, "No space left on device", str(path))

    monkeypatch.setattr(api, "build_pdf", broken)
    other = tiny_project(tmp_path, "other", project.read_text().replace("Tiny", "Other"))
    capsys.readouterr()
    assert main(["run", str(other), "--out", str(out), "--jobs", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "No space left on device" in err
    after = tree(out)
    for t in (before, after):
        t.pop(".lock", None)
    assert after == before


def test_a_set_without_pdf_replaces_the_old_pdf(tmp_path: Path) -> None:
    """Two projects into one folder: nothing of the first stays beside the second."""
    first = tiny_project(tmp_path)
    second = tiny_project(
        tmp_path, "second", first.read_text().replace("count: 2", "count: 1").replace("Tiny", "B")
    )
    out = tmp_path / "out"
    assert main(["run", str(first), "--out", str(out), "--jobs", "1"]) == 0
    assert (out / "report.pdf").exists()
    assert main(["run", str(second), "--out", str(out), "--jobs", "1", "--no-pdf"]) == 0
    results = assert_valid_set(out, pdf=False)
    assert results["project"]["name"] == "B wall"


def test_leftovers_of_a_killed_run_are_removed(tmp_path: Path) -> None:
    project = tiny_project(tmp_path)
    out = tmp_path / "out"
    stale_dir = out / f"{STAGING_PREFIX}999-deadbeef"
    (stale_dir / "records").mkdir(parents=True)
    (stale_dir / "results.json").write_text("{}", encoding="utf-8")
    stale_pdf = out / ".report.pdf.abc123.tmp"  # what atomic_path leaves on kill -9
    stale_pdf.write_bytes(b"%PDF partial")
    keep = out / "notes.txt"  # not ours: left alone
    keep.write_text("mine", encoding="utf-8")
    assert main(["run", str(project), "--out", str(out), "--jobs", "1"]) == 0
    assert not stale_dir.exists() and not stale_pdf.exists()
    assert keep.read_text(encoding="utf-8") == "mine"
    assert_valid_set(out, pdf=True)


def test_the_lock_is_reentrant_in_a_thread_and_exclusive_between_threads(tmp_path: Path) -> None:
    import threading

    from frp_assess.errors import InputError
    from frp_assess.output_set import FolderLock

    d = tmp_path / "out"
    errors: list[str] = []

    def other_thread() -> None:
        try:
            with FolderLock(d):
                pass
        except InputError as exc:
            errors.append(str(exc))

    with FolderLock(d), FolderLock(d):  # the same thread: re-entrant
        t = threading.Thread(target=other_thread)
        t.start()
        t.join()
    assert len(errors) == 1 and "is writing" in errors[0]
    with FolderLock(d):  # released: free again
        pass
