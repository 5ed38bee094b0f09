"""A closed output pipe (`frp-assess schema | head -1`) ends every printing command quietly."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from tests.cli.outputs_helpers import ROOT, cli_command, tiny_project


def piped_into_head(argv: list[str]) -> tuple[int, str, str]:
    """Run the CLI with stdout piped into `head -1`; (exit code, head's line, stderr)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), COLUMNS="100")
    proc = subprocess.Popen(
        cli_command(*argv), stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=ROOT
    )
    head = subprocess.run(["head", "-1"], stdin=proc.stdout, capture_output=True, timeout=300)
    proc.stdout.close()  # type: ignore[union-attr]  # head has it now; it closes after 1 line
    err = proc.stderr.read().decode()  # type: ignore[union-attr]
    proc.stderr.close()  # type: ignore[union-attr]
    return proc.wait(timeout=300), head.stdout.decode(), err


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [["schema"], ["--help"], ["run", "PROJECT", "--no-pdf", "--jobs", "1"]],
    ids=["schema", "help", "run"],
)
def test_closed_pipe_exits_quietly(argv: list[str], tmp_path: Path) -> None:
    argv = [str(tiny_project(tmp_path)) if a == "PROJECT" else a for a in argv]
    code, line, err = piped_into_head(argv)
    assert line.strip()  # head got its line
    assert code in (0, 141), (code, err)
    assert "Traceback" not in err and "BrokenPipe" not in err and "Exception ignored" not in err
