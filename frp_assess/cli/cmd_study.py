"""`frp-assess study FILE`: a parametric study (cross product of axes), chunked and resumable."""

from __future__ import annotations

import argparse
import threading
from pathlib import Path
from typing import Any

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

from frp_assess.cli.output import make_console, user
from frp_assess.errors import Cancelled, InputError
from frp_assess.output_set import check_out_dir


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "study",
        help="run a parametric study (cross product of wall, retrofit and spectrum axes)",
        description="Run the IDA of every case of a study file (the cross product of its axes) "
        "over its records, chunked and cached: an interrupted study resumes where it stopped. "
        "Writes long.csv (case x record), summary.csv (per case: mean a_dyn [g], mean q, "
        "improvement), study.json, and study.pdf with the figures and the comparison "
        "with the paper when the axes allow it.",
    )
    p.add_argument("file", help="study file (YAML)")
    p.add_argument(
        "--out", metavar="DIR", help="results directory (default: <name>-results/ next to FILE)"
    )
    p.add_argument("--jobs", type=int, default=None, help="local worker threads (default: all)")
    add_executor_options(p)
    p.add_argument("--no-figures", action="store_true", help="do not write study.pdf")
    p.set_defaults(handler=run)


def add_executor_options(p: argparse.ArgumentParser) -> None:
    """``--executor local|dask`` and ``--scheduler ADDRESS``: where the IDAs run (``study``,
    and ``run`` of a building file)."""
    p.add_argument(
        "--executor",
        choices=("local", "dask"),
        default="local",
        help="local threads (default) or a Dask LocalCluster (needs the 'dask' extra)",
    )
    p.add_argument(
        "--scheduler", metavar="ADDRESS", help="run on the Dask cluster at ADDRESS (tcp://...)"
    )


def run(args: argparse.Namespace) -> int:
    from frp_assess.app.study import load_study, make_executor, plan_and_records, run_study

    path = Path(args.file)
    study = load_study(path)
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    out_dir = check_out_dir(Path(args.out) if args.out else path.with_name(f"{path.stem}-results"))
    console = make_console()
    executor = make_executor(args.executor, args.scheduler, args.jobs)
    cancel = threading.Event()
    try:
        with Progress(
            TextColumn("{task.description}"),
            BarColumn(),
            MofNCompleteColumn(),
            TimeElapsedColumn(),
            TimeRemainingColumn(),
            console=console,
        ) as bar:
            task: dict[str, Any] = {}

            def progress(done: int, total: int) -> None:
                if "id" not in task:
                    task["id"] = bar.add_task("IDA (case × record)", total=total)
                bar.update(task["id"], completed=done, total=total)

            with console.status("generating the records"):
                plan, records = plan_and_records(study)
            console.print(
                f"{user(study.name)}: {len(plan)} cases ({plan.n_unreinforced} unreinforced, "
                f"{plan.n_reinforced} reinforced) × {study.records.count} records on "
                f"{executor.describe()}"
            )
            try:
                outcome = run_study(
                    study,
                    out_dir,
                    executor=executor,
                    progress=progress,
                    cancel=cancel,
                    records=records,
                    figures=not args.no_figures,
                )
            except KeyboardInterrupt:
                cancel.set()
                raise Cancelled("interrupted") from None
    finally:
        executor.close()
    stats = outcome.stats
    console.print(
        f"{stats.computed} IDAs computed, {stats.reused} reused; {stats.seconds:.1f} s; "
        f"results in {user(out_dir)}/"
    )
    for w in outcome.figures:
        console.print(f"wrote {user(w)}")
    return 0
