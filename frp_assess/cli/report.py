"""`frp-assess report RESULTS_DIR`: rebuild the report from stored results: the PDF, or the
editable Word file (``--docx``, or an ``--out`` ending in .docx), in the language the project
asked for (results.json ``report.language``)."""

from __future__ import annotations

import argparse
from pathlib import Path

from frp_assess.cli.output import plain_line
from frp_assess.output_set import FolderLock, check_out_file
from frp_assess.report.document import (
    CONTRACT_ERRORS,
    build_docx,
    build_report,
    build_story,
    contract_error,
    load_results,
)


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
    results_dir = Path(args.results_dir)
    docx = bool(args.docx) or (args.out is not None and str(args.out).lower().endswith(".docx"))
    default = results_dir / ("report.docx" if docx else "report.pdf")
    out = check_out_file(Path(args.out) if args.out else default)
    results = load_results(results_dir)  # InputError -> one line, exit 2
    if docx:
        try:
            build_docx(results, out)
        except CONTRACT_ERRORS as exc:  # nothing written: build_docx writes atomically
            raise contract_error(exc, results_dir / "results.json") from None
        print(f"wrote {plain_line(out)}")
        return 0
    try:
        story = build_story(results)  # a value that breaks the contract fails here
        if out.resolve().parent == results_dir.resolve():
            # report.pdf is a member of the run's output set: replace it under the lock
            with FolderLock(results_dir, key="RESULTS_DIR"):
                build_report(results, out, story=story)
        else:
            build_report(results, out, story=story)
    except CONTRACT_ERRORS as exc:  # nothing written: build_report writes atomically
        raise contract_error(exc, results_dir / "results.json") from None
    print(f"wrote {plain_line(out)}")
    return 0
