"""`frp-assess report RESULTS_DIR`: rebuild the PDF report from stored results."""

from __future__ import annotations

import argparse
from pathlib import Path

from frp_assess.app.report import rebuild_report
from frp_assess.cli.output import plain_line


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "report",
        help="rebuild report.pdf from a results directory (no analysis is rerun)",
        description="Read RESULTS_DIR/results.json, written by `frp-assess run`, and write the "
        "PDF assessment report (default RESULTS_DIR/report.pdf).",
    )
    p.add_argument("results_dir", metavar="RESULTS_DIR", help="results directory of a run")
    p.add_argument("--out", metavar="FILE", help="PDF to write (default RESULTS_DIR/report.pdf)")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    out = rebuild_report(Path(args.results_dir), Path(args.out) if args.out else None)
    print(f"wrote {plain_line(out)}")
    return 0
