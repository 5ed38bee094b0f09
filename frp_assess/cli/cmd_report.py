"""`frp-assess report RESULTS_DIR`: rebuild the report from stored results: the PDF, or the
editable Word file (``--docx``, or an ``--out`` ending in .docx), in the language the project
asked for (results.json ``report.language``)."""

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
    p.add_argument(
        "--out",
        metavar="FILE",
        help="file to write (default RESULTS_DIR/report.pdf, or report.docx with --docx); "
        "a name ending in .docx writes the Word file",
    )
    p.add_argument(
        "--docx", action="store_true", help="write the editable Word report instead of the PDF"
    )
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    docx = bool(args.docx) or (args.out is not None and str(args.out).lower().endswith(".docx"))
    out = rebuild_report(Path(args.results_dir), Path(args.out) if args.out else None, docx=docx)
    print(f"wrote {plain_line(out)}")
    return 0
