"""Shared by the output tests: a small project (2 short artificial records, one option) and
ways to run the CLI in a subprocess."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

TINY = """\
project: {name: Tiny wall}
wall: {thickness: 0.3, height: 3.0, length: 5.0, unit_weight: 18.0, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 2, seed: 7, duration: 15.0, dt: 0.01}
interventions:
  - {material: GFRP, position: external, ratio: 1.0}
costs: {currency: EUR, installation_per_metre: 100.0}
"""


def tiny_project(directory: Path, name: str = "tiny", text: str = TINY) -> Path:
    path = directory / f"{name}.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def cli_command(*args: str) -> list[str]:
    return [sys.executable, "-m", "frp_assess", *args]


def file_size_limit(n_bytes: int) -> Callable[[], None]:
    """preexec_fn: files larger than ``n_bytes`` cannot be written (EFBIG, as on a full
    disk; Python ignores SIGXFSZ, so the write fails with an OSError)."""

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (n_bytes, n_bytes))

    return limit


def run_cli(
    *args: str, cwd: Path | None = None, preexec: Callable[[], None] | None = None
) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, COLUMNS="100", PYTHONPATH=str(ROOT))
    return subprocess.run(
        cli_command(*args),
        cwd=cwd or ROOT,
        capture_output=True,
        text=True,
        env=env,
        preexec_fn=preexec,
        timeout=300,
    )


def tree(directory: Path) -> dict[str, bytes | None]:
    """Every path under ``directory`` (relative) with its bytes (None for folders)."""
    if not directory.exists():
        return {}
    out: dict[str, bytes | None] = {}
    for p in sorted(directory.rglob("*")):
        rel = str(p.relative_to(directory))
        out[rel] = None if p.is_dir() else p.read_bytes()
    return out
