"""Fuzzing the inputs (issue 25): for any project file drawn from the project's JSON Schema
and any record file in the readers' formats, ``validate`` and ``run`` either succeed or exit
2 with located lines naming the file — never a traceback, never a write outside ``--out``,
never a leftover temporary file.

The CLI runs in-process (``frp_assess.cli.main``): an exception that escapes it is a
traceback for the user, and fails the test with its example.
"""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from frp_assess.cli import main
from tests.cli.outputs_helpers import tree
from tests.fuzz.strategies import RECORD_NAME, budget, project_text, record_file

#: the record file a clean project names: 3 s at 0.01 s, peak 0.2 g
RECORD = "".join(f"{0.01 * i:.2f} {0.2 * (-1) ** i * (i % 7) / 6:.4f}\n" for i in range(301))

ERROR = "frp-assess: error: "
#: a numpy warning (overflow, invalid value) is a line the user was not meant to see
pytestmark = pytest.mark.filterwarnings("error::RuntimeWarning")


def cli(*args: str) -> tuple[int, str]:
    """Exit code and stderr of one in-process command (stdout dropped)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return code, err.getvalue()


def check_answer(code: int, err: str, files: list[Path], ok: tuple[int, ...] = (0,)) -> None:
    """Success, or exit 2 with every line an error naming one of ``files``."""
    assert "Traceback" not in err
    assert code in (*ok, 2), err
    if code == 2:
        lines = err.splitlines()
        assert lines, "exit 2 without a message"
        errors = [line for line in lines if not line.startswith("frp-assess: warning: ")]
        assert errors and all(line.startswith(ERROR) for line in errors), err
        named = errors[0][len(ERROR) :]
        assert any(named.startswith(str(f)) for f in files), err


def leftovers(directory: Path) -> list[str]:
    """Temporary files and staging folders left under ``directory``."""
    return sorted(
        str(p.relative_to(directory))
        for p in directory.rglob("*")
        if p.name.endswith(".tmp") or ".staging-" in p.name
    )


@settings(max_examples=budget(150, 3000))
@given(text=project_text())
def test_validate_any_project(tmp_path_factory: pytest.TempPathFactory, text: str) -> None:
    d = tmp_path_factory.mktemp("p")
    path, rec = d / "p.yaml", d / RECORD_NAME
    path.write_text(text, encoding="utf-8")
    rec.write_text(RECORD, encoding="utf-8")
    before = tree(d)
    code, err = cli("validate", str(path))
    check_answer(code, err, [path, rec])
    assert tree(d) == before


@st.composite
def project_with_record(draw: st.DrawFn) -> tuple[str, str]:
    fmt, text = draw(record_file())
    units = draw(st.sampled_from(["g", "m/s2", "cm/s2", "gal"]))
    entry: dict[str, object] = {"path": "r.txt", "format": fmt, "units": units}
    if fmt == "one-column" or draw(st.booleans()):
        entry["dt"] = draw(st.sampled_from([0.01, 0.005, 1e-4, 0.05]))
    project = {
        "wall": {"thickness": 0.3, "height": 3.0, "unit_weight": 18.0, "mechanism": "one-sided"},
        "seismic": {
            "spectrum": {"type": "preset", "name": "A2"},
            "records": {"files": [entry], "scale_to_spectrum": draw(st.booleans())},
        },
    }
    return json.dumps(project), text


@settings(max_examples=budget(120, 2500))
@given(case=project_with_record())
def test_validate_any_record_file(
    tmp_path_factory: pytest.TempPathFactory, case: tuple[str, str]
) -> None:
    project, record = case
    d = tmp_path_factory.mktemp("r")
    path, rec = d / "p.yaml", d / "r.txt"
    path.write_text(project, encoding="utf-8")
    rec.write_text(record, encoding="utf-8")
    before = tree(d)
    code, err = cli("validate", str(path))
    check_answer(code, err, [path, rec])
    assert tree(d) == before


@st.composite
def tiny_run(draw: st.DrawFn) -> tuple[str, str]:
    """A project that runs in a second or two: one short record (a few seconds, coarse dt)
    of any amplitude, a wall and at most one option from anywhere in their ranges."""
    dt = draw(st.sampled_from([0.02, 0.05]))
    n = draw(st.integers(20, 120))
    amp = draw(st.sampled_from([1e-6, 1e-3, 0.1, 0.5, 3.0, 50.0]))
    values = draw(st.lists(st.floats(-1, 1), min_size=n, max_size=n))
    if not any(values):
        values[0] = 1.0
    record = "".join(f"{i * dt!r} {amp * v!r}\n" for i, v in enumerate(values))
    thickness = draw(st.floats(0.05, 1.5))
    height = draw(st.floats(max(0.5, thickness * 1.01), 20.0))
    wall = {
        "thickness": thickness,
        "height": height,
        "mechanism": draw(st.sampled_from(["one-sided", "two-sided"])),
        "masonry": "rubble-stone",
    }
    project: dict[str, object] = {
        "wall": wall,
        "seismic": {
            "spectrum": {"type": "preset", "name": "A2"},
            "records": {"files": [{"path": "r.txt"}], "scale_to_spectrum": draw(st.booleans())},
        },
        "analysis": {"ida": {"step_ratio": 1.5, "tolerance": 0.05, "max_multiplier": 20}},
    }
    if draw(st.booleans()):
        ratio = draw(st.sampled_from([0.001, 0.5, 1.0, 5.0, 20.0]))
        project["interventions"] = [
            {
                "material": draw(st.sampled_from(["GFRP", "CFRP"])),
                "position": "external",
                "ratio": ratio,
            }
        ]
        project["bars"] = {"whole_bars": draw(st.booleans())}
    return json.dumps(project), record


@settings(max_examples=budget(6, 40))
@given(case=tiny_run())
def test_run_any_tiny_project(
    tmp_path_factory: pytest.TempPathFactory, case: tuple[str, str]
) -> None:
    project, record = case
    d = tmp_path_factory.mktemp("run")
    work, out = d / "work", d / "out"
    work.mkdir()
    path, rec = work / "p.yaml", work / "r.txt"
    path.write_text(project, encoding="utf-8")
    rec.write_text(record, encoding="utf-8")
    before = tree(work)
    code, err = cli("run", str(path), "--out", str(out), "--no-pdf", "--jobs", "1")
    check_answer(code, err, [path, rec], ok=(0, 1))
    assert tree(work) == before  # nothing written beside the input
    assert sorted(p.name for p in d.iterdir()) in (["out", "work"], ["work"])
    if out.exists():
        assert leftovers(out) == []
        if code in (0, 1):
            assert (out / "results.json").is_file()
