"""Fixtures of the TUI tests: small project files (2-3 short artificial records)."""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any

import pytest

#: a project that runs in about a second: 3 records of 14 s at dt 0.01, two options
SMALL = """\
project: {name: Small wall}
wall: {thickness: 0.3, height: 3.0, length: 5.0, masonry: solid-brick-lime-mortar,
       mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 3, seed: 7, duration: 14.0, dt: 0.01}
interventions:
  - {material: GFRP, position: external, ratio: 1.0}
  - {material: CFRP, position: centred, ratio: 2.0}
costs: {currency: EUR, installation_per_metre: 100.0}
"""

#: a project whose run takes several seconds (to cancel it)
BIG = """\
wall: {thickness: 0.3, height: 3.0, unit_weight: 18.0, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 3, seed: 3, duration: 20.0, dt: 0.01}
interventions:
  - sweep:
      material: [GFRP, BFRP, CFRP]
      position: [centred, external]
      ratio: [0.4, 0.6, 0.8, 1.2, 1.6, 2, 2.4, 2.8, 3.2, 3.6, 4, 4.4, 4.8, 5.2, 5.6, 6.4]
"""  # ratios a 0.3 m wall has in whole bars, each its own bars (docs/model.md §2.1)


@pytest.fixture
def small_project(tmp_path: Path) -> Path:
    path = tmp_path / "small.yaml"
    path.write_text(SMALL, encoding="utf-8")
    return path


@pytest.fixture
def big_project(tmp_path: Path) -> Path:
    path = tmp_path / "big.yaml"
    path.write_text(BIG, encoding="utf-8")
    return path


def run_async(fn: Callable[[], Awaitable[Any]]) -> Any:
    """Run an async test body (no pytest-asyncio needed)."""
    return asyncio.run(fn())


#: rounds of ``pilot.pause()`` a wait allows before it fails: each round lets the app
#: handle what is queued (a round lasts longer while a worker thread computes)
MAX_ROUNDS = 600


async def settle(pilot: Any, condition: Callable[[], bool], rounds: int = MAX_ROUNDS) -> None:
    """Let the app handle its messages until ``condition()`` holds (fail after ``rounds``)."""
    for _ in range(rounds):
        if condition():
            return
        await pilot.pause()
    if not condition():
        raise AssertionError(f"the app did not reach the state waited for in {rounds} rounds")


async def after_workers(pilot: Any, condition: Callable[[], bool] = lambda: True) -> None:
    """Wait until the app's workers (run, history, export...) have finished, then until the
    app has handled what they posted and ``condition()`` holds."""
    await pilot.app.workers.wait_for_complete()
    await settle(pilot, condition)


async def show_tab(pilot: Any, tab_id: str) -> None:
    """Show a main tab as the user does (F2...F10) and let its fields be made and mounted
    (a tab's fields are made the first time it is shown)."""
    pilot.app.show_tab(tab_id)
    await pilot.pause()
