"""An unchanged rerun recomputes nothing (frp_assess/app/rerun.py, `frp-assess run`): the digest
of the inputs, the sidecar beside results.json, and the fast path's light imports."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from frp_assess.app.rerun import SIDECAR, inputs_digest, unchanged_run, write_sidecar
from frp_assess.cli import main
from frp_assess.results.json_io import from_json

ROOT = Path(__file__).resolve().parents[2]
RECORD = ROOT / "projects" / "records" / "synthetic-01.AT2"

TINY = """\
project: {name: Tiny, engineer: Test}
wall: {thickness: 0.3, height: 3.0, length: 5.0, unit_weight: 18.0, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 1, seed: 7, duration: 14.0, dt: 0.02}
costs: {currency: EUR, installation_per_metre: 100.0}
"""


def _inputs(tmp_path: Path) -> tuple[Path, list[str]]:
    """A project file and a record file it references (bytes copied, path relative)."""
    (tmp_path / "rec").mkdir(parents=True)
    (tmp_path / "rec" / "a.AT2").write_bytes(RECORD.read_bytes())
    project = tmp_path / "p.yaml"
    project.write_text("project: {name: x}\n", encoding="utf-8")
    return project, ["rec/a.AT2"]


def test_same_inputs_same_digest_and_no_absolute_path(tmp_path: Path) -> None:
    """The digest depends on bytes and relative paths only: a copy of the folder elsewhere
    has the same digest (golden bytes reproducible across machines)."""
    project, files = _inputs(tmp_path / "one")
    copy, _ = _inputs(tmp_path / "two")
    d = inputs_digest(project, files)
    assert d.startswith("sha256:") and len(d) == len("sha256:") + 64
    assert d == inputs_digest(project, files) == inputs_digest(copy, files)


def test_a_changed_byte_or_option_changes_the_digest(tmp_path: Path) -> None:
    project, files = _inputs(tmp_path)
    base = inputs_digest(project, files)
    record = tmp_path / "rec" / "a.AT2"
    data = bytearray(record.read_bytes())
    data[-2] = ord("7") if data[-2] != ord("7") else ord("3")
    record.write_bytes(bytes(data))
    changed = inputs_digest(project, files)
    assert changed != base
    assert inputs_digest(project, files, rtol=1e-7) != changed
    assert inputs_digest(project, files, verify=True) != changed
    record.unlink()
    assert inputs_digest(project, files) not in (base, changed)  # "missing" counts too


def _fake_set(out: Path, *, pdf: bool) -> None:
    out.mkdir()
    reports = ("report.pdf", "report.docx") if pdf else ()
    for name in ("results.json", "results.csv", "spectra.csv", *reports):
        (out / name).write_text("x", encoding="utf-8")
    (out / "records").mkdir()


def test_unchanged_needs_a_complete_set_and_the_same_digest(tmp_path: Path) -> None:
    project, files = _inputs(tmp_path)
    out = tmp_path / "out"
    _fake_set(out, pdf=False)
    assert unchanged_run(project, out) is None  # no sidecar
    write_sidecar(out, inputs_digest(project, files), "2025-01-01", files, pdf=False)
    assert unchanged_run(project, out, pdf=False) is not None
    assert unchanged_run(project, out) is None  # the reports missing: not "unchanged"
    (out / "report.pdf").write_text("x", encoding="utf-8")
    assert unchanged_run(project, out) is None  # report.docx missing: not "unchanged"
    (out / "report.docx").write_text("x", encoding="utf-8")
    same = unchanged_run(project, out)
    assert same is not None and same.created == "2025-01-01"
    assert unchanged_run(project, out, rtol=1e-7) is None  # --rtol: rerun
    (out / "results.json").write_text("y", encoding="utf-8")
    assert unchanged_run(project, out) is None  # the sidecar belongs to another results.json
    (out / "results.json").write_text("x", encoding="utf-8")
    assert unchanged_run(project, out) is not None
    (tmp_path / "rec" / "a.AT2").write_text("1 2 3\n", encoding="utf-8")
    assert unchanged_run(project, out) is None  # a record changed: rerun
    (out / SIDECAR).write_text("{broken", encoding="utf-8")
    assert unchanged_run(project, out) is None


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One real run of a tiny project (no PDF); returns the project file."""
    folder = tmp_path_factory.mktemp("rerun")
    project = folder / "tiny.yaml"
    project.write_text(TINY, encoding="utf-8")
    assert main(["run", str(project), "--no-pdf", "--jobs", "1"]) == 0
    return project


def test_the_run_records_its_digest(tiny_run: Path) -> None:
    out = tiny_run.with_name("tiny-results")
    side = json.loads((out / SIDECAR).read_text(encoding="utf-8"))
    results = from_json((out / "results.json").read_text(encoding="utf-8"))
    assert results.inputs_digest == side["digest"] == inputs_digest(tiny_run, [])
    assert side["created"] == results.created and side["files"] == []


def test_unchanged_rerun_is_light(tiny_run: Path) -> None:
    """The fast path imports none of numba, scipy, reportlab, textual (a fresh interpreter)."""
    code = (
        "import sys, frp_assess.cli as c; "
        f"assert c.main(['run', {str(tiny_run)!r}, '--no-pdf']) == 0; "
        "print(sorted(m for m in sys.modules if m.split('.')[0] in "
        "{'numba', 'scipy', 'reportlab', 'textual', 'pydantic'}))"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True
    )
    lines = proc.stdout.splitlines()
    assert any(line.startswith("unchanged since ") for line in lines)
    assert "nothing to recompute" in proc.stdout
    assert lines[-1] == "[]"


def test_a_changed_project_runs_again(tiny_run: Path, capsys: pytest.CaptureFixture[str]) -> None:
    capsys.readouterr()
    tiny_run.write_text(TINY.replace("name: Tiny", "name: Tiny 2"), encoding="utf-8")
    assert main(["run", str(tiny_run), "--no-pdf", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "unchanged since" not in out and "IDAs computed" in out
    results = from_json(
        (tiny_run.with_name("tiny-results") / "results.json").read_text(encoding="utf-8")
    )
    assert results.project.name == "Tiny 2"


def test_the_word_template_is_one_of_the_inputs() -> None:
    """A project with a firm's Word template lists it after its record files, so a changed
    template makes the rerun a real one (the DOCX is drawn with it)."""
    from frp_assess.app.rerun import referenced_paths
    from frp_assess.config import load_project_text

    with_template = TINY + "report: {language: it, template: styles/firm.docx}\n"
    assert referenced_paths(load_project_text(TINY, "p.yaml").project) == []
    assert referenced_paths(load_project_text(with_template, "p.yaml").project) == [
        "styles/firm.docx"
    ]
