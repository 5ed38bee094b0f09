"""Time the TUI headless: start-up, validation per key typed, and UI stalls during a run.

Run: ``python benchmarks/bench_tui.py [PROJECT.yaml] [--jobs N]``
(default: projects/facade-laquila.yaml, 19 cases × 7 records).  The project is copied to
a temporary folder, so its results directory is not touched.  Reported:

* start-up: from creating the app to the first screen (targets ≤ 3 s);
* revalidate: what one key typed in a field costs (collect, validate, derived values,
  tables; target ≤ 50 ms);
* the longest gap between two ticks of a 20 ms UI timer while the assessment runs in its
  worker thread (the UI must not freeze: target ≤ 500 ms; typical gaps are < 60 ms, the
  longest ones come from record generation and numba's first calls, which hold the GIL).

Not collected by pytest.
"""

from __future__ import annotations

import argparse
import asyncio
import shutil
import tempfile
import time
from pathlib import Path

from frp_assess.tui.app import FrpAssessApp

DEFAULT = Path(__file__).resolve().parents[1] / "projects" / "facade-laquila.yaml"
TARGET_START_S = 3.0
TARGET_KEY_MS = 50.0
TARGET_STALL_MS = 500.0


async def measure(project: Path, jobs: int | None) -> dict[str, float]:
    t0 = time.perf_counter()
    app = FrpAssessApp(project, jobs=jobs)
    out: dict[str, float] = {}
    async with app.run_test(size=(100, 30)) as pilot:
        await pilot.pause()
        out["start_s"] = time.perf_counter() - t0
        n = 20
        box = app.query_one("#f-wall-thickness-control")
        first = box.value
        t = time.perf_counter()
        for i in range(n):  # a new value each time: everything derived is redrawn
            with app.prevent(type(box).Changed):
                box.value = f"0.{30 + i}"
            app.revalidate()
        out["key_ms"] = (time.perf_counter() - t) / n * 1e3
        box.value = first
        await pilot.pause()
        ticks: list[float] = []
        timer = app.set_interval(0.02, lambda: ticks.append(time.perf_counter()))
        t = time.perf_counter()
        app.action_run()
        while app.running:
            await asyncio.sleep(0.02)
        out["run_s"] = time.perf_counter() - t
        timer.stop()
        gaps = [b - a for a, b in zip(ticks, ticks[1:], strict=False)]
        out["stall_ms"] = max(gaps, default=0.0) * 1e3
        out["ok"] = float(app.outcome is not None)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project", nargs="?", default=str(DEFAULT), help="a project file")
    ap.add_argument("--jobs", type=int, default=None, help="threads (default: all cores)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(args.project)
        copy = Path(tmp) / src.name
        shutil.copy(src, copy)
        if (src.parent / "records").is_dir():
            shutil.copytree(src.parent / "records", Path(tmp) / "records")
        r = asyncio.run(measure(copy, args.jobs))
    print(f"start-up            {r['start_s']:6.2f} s   (target ≤ {TARGET_START_S:g} s)")
    print(f"revalidate per key  {r['key_ms']:6.1f} ms  (target ≤ {TARGET_KEY_MS:g} ms)")
    print(f"run in the worker   {r['run_s']:6.2f} s   ({'finished' if r['ok'] else 'FAILED'})")
    print(f"longest UI stall    {r['stall_ms']:6.0f} ms  (target ≤ {TARGET_STALL_MS:g} ms)")
    ok = (
        r["ok"]
        and r["start_s"] <= TARGET_START_S
        and r["key_ms"] <= TARGET_KEY_MS
        and r["stall_ms"] <= TARGET_STALL_MS
    )
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
