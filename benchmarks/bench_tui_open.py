"""CPU time of one TUI session headless: open and close the app, and show every tab.

Run: ``PYTHONPATH=. python3 benchmarks/bench_tui_open.py [PROJECT.yaml] [--repeat N]``
(default: the small project of tests/tui/conftest.py, written to a temporary folder).

What a Pilot test pays before it does anything: the first open in the process imports and
warms Textual, so it is left out; each of the next ``N`` opens is timed with
``time.process_time`` (CPU seconds of this process: fair on a shared machine, where wall
time depends on the other load).  Reported: the widgets mounted after opening, the CPU
seconds of an open/close (min and median), and of an open that then shows each editor tab
once (its fields are made the first time it is shown).

Not collected by pytest.
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import tempfile
import time
from pathlib import Path

from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.core.tabs import TABS

SIZE = (100, 30)


async def session(path: Path | None, show_tabs: bool) -> int:
    """Open the app, optionally show each editor tab, close it; returns the widget count
    after opening."""
    app = FrpAssessApp(path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        widgets = len(app.query("*"))
        if show_tabs:
            for tab_id, _ in TABS[:6]:  # Wall ... Analysis: the tabs with fields
                app.show_tab(tab_id)
                await pilot.pause()
    return widgets


def cpu_seconds(path: Path | None, show_tabs: bool, repeat: int) -> tuple[int, list[float]]:
    """The widget count and the CPU seconds of ``repeat`` sessions (after a warm-up one)."""
    widgets = asyncio.run(session(path, show_tabs))
    times = []
    for _ in range(repeat):
        t = time.process_time()
        asyncio.run(session(path, show_tabs))
        times.append(time.process_time() - t)
    return widgets, times


def small_project(folder: Path) -> Path:
    """The small project of the TUI tests (3 short artificial records, two options)."""
    from tests.tui.conftest import SMALL

    path = folder / "small.yaml"
    path.write_text(SMALL, encoding="utf-8")
    return path


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project", nargs="?", default=None, help="a project file")
    ap.add_argument("--repeat", type=int, default=5, help="timed sessions (default 5)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(args.project) if args.project else small_project(Path(tmp))
        for label, show_tabs in (("open/close", False), ("open, every tab", True)):
            widgets, t = cpu_seconds(path, show_tabs, args.repeat)
            print(
                f"{label:16s} {min(t):6.3f} CPU-s min, {statistics.median(t):6.3f} median "
                f"({args.repeat} runs; {widgets} widgets after opening)"
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
