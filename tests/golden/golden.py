"""The golden set: what tests/golden/test_golden.py checks and scripts/update_golden.py writes.

Both go through this module and the real command line (:func:`frp_assess.cli.main`, in
process): ``frp-assess run PROJECT --no-pdf --created DATE`` for the three projects and
``frp-assess study STUDY --no-figures`` for the study, each into its own results folder.
The files compared byte for byte are :data:`RUN_FILES` of a run and :data:`STUDY_FILES` of a
study, stored as ``expected/<name>/<file>``.

Nothing is normalised: every byte of these files is reproducible (the date of the run is
fixed by ``--created``; results.json names its input by file name only, never by an absolute
path).  If an environment-dependent field ever appears, normalise it in :func:`normalise`,
the one place for it, and say why there.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from frp_assess.cli import main

GOLDEN = Path(__file__).resolve().parent
PROJECTS_DIR = GOLDEN / "projects"
EXPECTED = GOLDEN / "expected"

#: the fixed date of the golden runs (results.json ``created``)
CREATED = "2025-01-01"
#: assessment projects (tests/golden/projects/<name>.yaml), see each file's header
PROJECTS = ("small", "paper-reduced", "building-crushing")
#: study files (tests/golden/projects/<name>.yaml)
STUDIES = ("tiny-study",)
RUN_FILES = ("results.json", "results.csv", "spectra.csv")
STUDY_FILES = ("long.csv", "summary.csv")
#: how the expected files are rewritten (the only way)
UPDATE_COMMAND = "python3 scripts/update_golden.py"

#: (out_dir, jobs) -> {relative expected path: bytes}
Producer = Callable[[Path, int], dict[str, bytes]]


def normalise(name: str, data: bytes) -> bytes:
    """The one place where environment-dependent bytes would be normalised (none today)."""
    return data


def _call(argv: list[str]) -> None:
    code = main(argv)
    if code != 0:
        raise RuntimeError(f"frp-assess {' '.join(argv)} exited with {code}")


def _collect(name: str, out_dir: Path, files: tuple[str, ...]) -> dict[str, bytes]:
    found = {}
    for f in files:
        key = f"{name}/{f}"
        found[key] = normalise(key, (out_dir / f).read_bytes())
    return found


def run_project(name: str, out_dir: Path, jobs: int) -> dict[str, bytes]:
    """``frp-assess run`` of golden project ``name`` into ``out_dir`` with ``jobs`` workers
    (an existing ``out_dir`` reuses its .cache); returns its golden files."""
    _call(
        [
            "run",
            str(PROJECTS_DIR / f"{name}.yaml"),
            "--out",
            str(out_dir),
            "--jobs",
            str(jobs),
            "--no-pdf",
            "--created",
            CREATED,
        ]
    )
    return _collect(name, out_dir, RUN_FILES)


def run_study(name: str, out_dir: Path, jobs: int) -> dict[str, bytes]:
    """``frp-assess study`` of golden study ``name`` into ``out_dir`` with ``jobs`` workers
    (an existing ``out_dir`` resumes from its chunks and .cache); returns its golden files."""
    _call(
        [
            "study",
            str(PROJECTS_DIR / f"{name}.yaml"),
            "--out",
            str(out_dir),
            "--jobs",
            str(jobs),
            "--no-figures",
        ]
    )
    return _collect(name, out_dir, STUDY_FILES)


def producers() -> dict[str, Producer]:
    """Every golden item by name: its producer."""
    items: dict[str, Producer] = {}
    for p in PROJECTS:
        items[p] = lambda out, jobs, p=p: run_project(p, out, jobs)
    for s in STUDIES:
        items[s] = lambda out, jobs, s=s: run_study(s, out, jobs)
    return items


def expected_files() -> dict[str, bytes]:
    """The committed golden files, by path relative to ``expected/``."""
    return {
        p.relative_to(EXPECTED).as_posix(): p.read_bytes()
        for p in sorted(EXPECTED.rglob("*"))
        if p.is_file()
    }


def first_difference(expected: bytes, found: bytes) -> str:
    """Where two files first differ: the line number and both lines (shortened)."""
    exp_lines = expected.decode("utf-8", "replace").splitlines(keepends=True)
    got_lines = found.decode("utf-8", "replace").splitlines(keepends=True)
    for k, (e, g) in enumerate(zip(exp_lines, got_lines, strict=False), start=1):
        if e != g:
            return f"line {k}:\n  expected: {_short(e)}\n  found:    {_short(g)}"
    k = min(len(exp_lines), len(got_lines)) + 1
    if len(exp_lines) != len(got_lines):
        return f"line {k}: expected {len(exp_lines)} lines, found {len(got_lines)}"
    return "the same lines, different bytes (line endings?)"


def _short(line: str, width: int = 160) -> str:
    text = repr(line)
    return text if len(text) <= width else text[: width - 3] + "..."
