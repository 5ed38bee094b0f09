"""`frp-assess run FILE`: the whole assessment of a project file."""

from __future__ import annotations

import argparse
import threading
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from frp_assess.api import default_out_dir, prepare_records, run_assessment
from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.results import recommendation_text
from frp_assess.errors import Cancelled, InputError
from frp_assess.motions import ComplianceReport


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "run",
        help="assess a project file (IDA of every option, ranking, report)",
        description="Build or read the records, run the IDA of the unreinforced "
        "wall and of every retrofit option on all cores, rank the options and "
        "write results.json, results.csv, spectra.csv, records/ and report.pdf.",
    )
    p.add_argument("file", help="project file (YAML)")
    p.add_argument(
        "--out", metavar="DIR", help="results directory (default: <name>-results/ next to the file)"
    )
    p.add_argument("--jobs", type=int, default=None, help="worker threads (default: all cores)")
    p.add_argument("--no-pdf", action="store_true", help="do not write report.pdf")
    p.set_defaults(handler=run)


def compliance_table(rep: ComplianceReport) -> Table:
    t = Table(title=f"Spectrum compatibility of the records (T1 = {rep.t1:g} s)")
    for col in ("code", "clause", "requirement", "found", "margin", "result"):
        t.add_column(col, overflow="fold")
    for c in rep.checks:
        margin = f"{c.margin:+.1%}" if c.unit == "" else f"{c.margin:+g} {c.unit}"
        t.add_row(
            c.code,
            c.clause,
            c.requirement,
            c.found,
            margin,
            "[green]pass[/]" if c.passed else "[red]FAIL[/]",
        )
    return t


def ranking_table(results: dict[str, Any]) -> Table:
    cur = results["costs"]["currency"]
    t = Table(
        title=f"Retrofit options (demand a_g·S = {results['demand']['pga']:.3f} g, "
        f"target capacity/demand ≥ {results['model']['target']:g})"
    )
    cols = [
        "rank",
        "option",
        "FRP [kg]",
        f"cost [{cur}]",
        "a_dyn [g]",
        "q",
        "improvement",
        "capacity/demand",
        "meets",
    ]
    for col in cols:
        if col == "option":
            t.add_column(col, justify="left", no_wrap=True)
        else:
            t.add_column(col, justify="right")
    ordered = sorted(results["cases"], key=lambda c: (c["rank"] is not None, c["rank"] or 0))
    for c in ordered:
        t.add_row(
            "—" if c["rank"] is None else str(c["rank"]),
            c["name"],
            f"{c['frp_mass']:.1f}",
            f"{c['frp_cost']:.0f}",
            f"{c['design_a_dyn']:.3f}",
            f"{c['mean_q']:.2f}",
            f"{c['improvement']:.2f}",
            f"{c['capacity_demand']:.2f}",
            "yes" if c["meets_target"] else "no",
        )
    return t


def run(args: argparse.Namespace) -> int:
    path = Path(args.file)
    inputs = load_inputs(path)  # InputError -> one line, exit 2, nothing written
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    out_dir = Path(args.out) if args.out else default_out_dir(path)
    console = Console()
    with console.status("generating/reading the records and checking them against the spectrum"):
        seismic = prepare_records(inputs)
    console.print(compliance_table(seismic.compliance))
    cancel = threading.Event()
    n_cases = 1 + len(inputs.options)
    with Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=False,
    ) as bar:
        tasks: dict[str, Any] = {}

        def progress(stage: str, done: int, total: int) -> None:
            label = {
                "ida": f"IDA {n_cases} cases × {len(seismic.records)} records",
                "design": "design mode",
                "writing": "writing results",
            }.get(stage)
            if label is None:
                return
            if stage not in tasks:
                tasks[stage] = bar.add_task(label, total=total)
            bar.update(tasks[stage], completed=done, total=total)

        try:
            results, stats = run_assessment(
                inputs,
                out_dir,
                jobs=args.jobs,
                progress=progress,
                cancel=cancel,
                seismic=seismic,
                pdf=not args.no_pdf,
            )
        except KeyboardInterrupt:
            cancel.set()
            raise Cancelled("interrupted") from None
    w = results["wall"]
    urm = results["cases"][0]
    console.print(
        f"wall B = {w['thickness']:g} m, H = {w['height']:g} m, α = {w['alpha_deg']:.2f}°, "
        f"a_RM = {w['a_rm']:.3f} g, {w['mechanism']}; unreinforced: a_dyn = "
        f"{urm['design_a_dyn']:.3f} g, capacity/demand = {urm['capacity_demand']:.2f} "
        f"({'meets' if urm['meets_target'] else 'does NOT meet'} the target)"
    )
    cc = results["code_check"]
    console.print(
        f"code kinematic check (Circolare 2019 §C8.7.1, q = {cc['behaviour_factor']:g}, "
        f"FC = {cc['FC']:g}): a0* = {cc['a0_star']:.3f} g vs a_g·S/q = {cc['demand']:.3f} g "
        f"-> {'satisfied' if cc['passed'] else 'NOT satisfied'}. {cc['note']}"
    )
    if len(results["cases"]) > 1:
        console.print(ranking_table(results))
        console.print(f"Ranking rule: {results['ranking_rule']}")
        console.print("Recommended: " + recommendation_text(results))
    for d in results["design"] or []:
        console.print(f"design {d['material']} {d['position']}: {d['message']}")
    console.print(
        f"{stats.computed} IDAs computed, {stats.reused} reused from the cache; "
        f"results in {out_dir}/"
    )
    return 0
