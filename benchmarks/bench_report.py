"""Time the PDF report of a 19-option assessment (target: ≤ 5 s).

Run: ``python benchmarks/bench_report.py [RESULTS_JSON] [--repeat N]``
(default: the synthetic fixture tests/report/data/results.json). Not collected by pytest.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from frp_assess.report import build_report
from frp_assess.results.json_io import from_json

DEFAULT = Path(__file__).resolve().parents[1] / "tests" / "report" / "data" / "results.json"
TARGET_S = 5.0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results", nargs="?", default=str(DEFAULT), help="a results.json")
    ap.add_argument("--repeat", type=int, default=3, help="builds to time (default 3)")
    args = ap.parse_args()
    results = from_json(Path(args.results).read_text(encoding="utf-8"))
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "report.pdf"
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            build_report(results, out)
            times.append(time.perf_counter() - t0)
        size = out.stat().st_size
    n = len(results.cases)
    print(
        f"report of {n} cases ({n - 1} options), {size / 1e3:.0f} kB: first build "
        f"{times[0]:.2f} s (fonts registered), best {min(times):.2f} s, target ≤ {TARGET_S} s"
    )
    return 0 if times[0] <= TARGET_S else 1


if __name__ == "__main__":
    raise SystemExit(main())
