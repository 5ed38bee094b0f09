"""`frp-assess run FILE`: the whole assessment of a project file."""

from __future__ import annotations

import argparse
import datetime as _dt
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rich.console import Console

from frp_assess.app.building_file import is_building_file
from frp_assess.app.rerun import (
    inputs_digest,
    referenced_paths,
    unchanged_run,
    write_sidecar,
)
from frp_assess.cli.cmd_study import add_executor_options
from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.cli.ranking import print_ranking
from frp_assess.errors import Cancelled, InputError
from frp_assess.numbers import (
    checks_summary,
    fmt_capacity,
    noncompliant_sets,
    numerical_check_text,
    recommendation_label,
    recommendation_text,
    verdict_text,
)
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import plain

#: progress(stage, done, total), as frp_assess.app.assessment.Progress
ProgressFn = Callable[[str, int, int], None]

if TYPE_CHECKING:  # the numerics are imported only when a run computes (not when unchanged)
    from frp_assess.app.assessment import AssessmentInputs, ComplianceReport


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "run",
        help="assess a project file (IDA of every option, ranking, report)",
        description="Build or read the records, run the IDA of the unreinforced "
        "wall and of every retrofit option on all cores, rank the options and "
        "write results.json, results.csv, spectra.csv, records/, report.pdf and report.docx.",
    )
    p.add_argument("file", help="project file (YAML)")
    p.add_argument(
        "--out", metavar="DIR", help="results directory (default: <name>-results/ next to the file)"
    )
    p.add_argument("--jobs", type=int, default=None, help="worker threads (default: all cores)")
    p.add_argument(
        "--no-pdf", action="store_true", help="do not write the reports (report.pdf, report.docx)"
    )
    p.add_argument(
        "--rtol",
        type=tolerance,
        default=None,
        metavar="TOL",
        help="integration tolerance, overriding analysis.integration.tolerance",
    )
    p.add_argument(
        "--verify",
        action="store_true",
        help="repeat every IDA at a 10x tighter tolerance and report the largest change of C",
    )
    p.add_argument(
        "--wall",
        metavar="NAME",
        default=None,
        help="a building file (walls:): assess only the wall called NAME",
    )
    add_executor_options(p)  # a building file's walls on Dask (cli/cmd_run_building.py)
    # hidden: fixes results.json's `created` (tests/golden; or SOURCE_DATE_EPOCH, api.run_date)
    p.add_argument("--created", type=iso_date, default=None, help=argparse.SUPPRESS)
    p.set_defaults(handler=run)


def tolerance(text: str) -> float:
    """``--rtol TOL``: the integration tolerance, in its declared range (dynamics/options.py;
    imported here, when the option is given, not when the parser is built)."""
    from frp_assess.cli.wall_args import TOLERANCE

    return TOLERANCE(text)


def default_out_dir(project_file: Path) -> Path:
    """``<stem>-results/`` next to the project file (as
    :func:`frp_assess.app.assessment.default_out_dir`, without importing the numerics)."""
    return project_file.with_name(f"{project_file.stem}-results")


def iso_date(text: str) -> str:
    """``--created YYYY-MM-DD``: the date written as the run's ``created``."""
    try:
        return _dt.date.fromisoformat(text).isoformat()
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a date YYYY-MM-DD, found {text!r}") from None


def compliance_rows(rep: ComplianceReport) -> list[list[str]]:
    """The code checks of the record set, one row each (plain text)."""
    rows = []
    for c in rep.checks:
        margin = f"{c.margin:+.1%}" if c.unit == "" else f"{c.margin:+g} {c.unit}"
        rows.append(
            [c.code, c.clause, c.requirement, c.found, margin, "pass" if c.passed else "FAIL"]
        )
    return rows


COMPLIANCE_COLUMNS = (
    Column("code", text=True),
    Column("clause", text=True),
    Column("requirement", text=True),
    Column("found", text=True),
    Column("margin", text=True),
    Column("result", text=True, fold=False),
)


def print_compliance(con: Console, rep: ComplianceReport) -> None:
    print_table(
        con,
        f"Spectrum compatibility of the records (T1 = {rep.t1:g} s)",
        COMPLIANCE_COLUMNS,
        compliance_rows(rep),
    )


def built_lines(results: AssessmentResult) -> list[str]:
    """The recommended option's bars as built and their anchorage (none without them); the
    cheapest passing option's "if installed" when the wall needs no retrofit."""
    rec = results.case(results.recommended)
    if rec is None or rec.as_built is None:
        return []
    b = rec.as_built
    head = "  built as" if results.retrofit_required else f"  {rec.name}, if installed: built as"
    return [f"{head} {b.note}; {b.anchorage.note}"]


def print_floor_and_checks(console: Console, results: AssessmentResult) -> None:
    """The floor-motion line (a wall above ground) and one line of code-check verdicts for
    the unreinforced wall and the rank-1 option (:func:`frp_assess.numbers.checks_summary`)."""
    b = results.building
    if b is not None:
        console.print(
            f"shaken by the floor motion at Z = {b.wall_base:g} m of {b.height:g} m "
            f"(first mode: γ1 = {b.gamma1:.3g}, ψ1 = {b.psi1:.3g}, T1 = {b.period:.3g} s); "
            "a_dyn and capacity/demand are in ground terms"
        )
    kc = results.kinematic_checks
    if kc is not None and kc.intensity_basis:
        console.print(f"limit states: {user(kc.intensity_basis)}")
    for label, line in checks_summary(results, labelled=True):
        console.print(f"code checks, {user(label)}: {user(line)}")


def run(args: argparse.Namespace) -> int:
    path = Path(args.file)
    out = Path(args.out) if args.out else default_out_dir(path)
    if is_building_file(path, args.wall):  # several walls: cli/cmd_run_building.py
        from frp_assess.cli.cmd_run_building import run_building_file

        return run_building_file(args, path, out)
    if args.executor != "local" or args.scheduler is not None:
        flag = "--scheduler" if args.scheduler is not None else "--executor"
        raise InputError(
            f"{flag} runs the walls of a building file (walls:) on Dask; {path} is a one-wall "
            "project: run it without it",
            key=flag,
        )
    if args.created is None and (args.jobs is None or args.jobs >= 1):
        same = unchanged_run(path, out, rtol=args.rtol, verify=args.verify, pdf=not args.no_pdf)
        if same is not None:
            return _unchanged(same.out_dir, same.created)
    from frp_assess.app.assessment import load_inputs
    from frp_assess.app.project import load_project
    from frp_assess.output_set import (  # not needed when unchanged
        FolderLock,
        check_out_dir,
        refuse_inputs_inside,
    )

    inputs = load_inputs(path)  # InputError -> one line, exit 2, nothing written
    files = referenced_paths(load_project(path).project)
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    if args.rtol is not None:
        inputs = replace(inputs, model=replace(inputs.model, tolerance=args.rtol))
    if args.verify:
        inputs = replace(inputs, verify=True)
    out_dir = check_out_dir(out)  # nothing of the user's replaced: output_set's rules
    refuse_inputs_inside(out_dir, [path, *(path.parent / f for f in files)])
    with FolderLock(out_dir):  # a second run into the same folder refuses here, exit 2
        return _run(args, inputs, out_dir, files)


def _unchanged(out_dir: Path, created: str) -> int:
    """Nothing changed since the stored run: say so and print its summary (results.json)."""
    from frp_assess.io_utils import read_results_text
    from frp_assess.results.json_io import from_json

    stored = out_dir / "results.json"
    results = from_json(read_results_text(stored), file=str(stored))
    console = make_console()
    console.print(f"unchanged since {user(created)}: nothing to recompute")
    print_summary(console, results)
    console.print(f"results in {user(out_dir)}/")
    return 0


def activation_text(results: AssessmentResult) -> str:
    """``a_RM = … g`` [g] of the unreinforced wall's model, with the crushing pivot's depth x
    [mm] when the model turns about it (then a_RM = g·(B − x)/H, not g·tan α; docs/model.md
    §1.1)."""
    text = f"a_RM = {results.wall.a_rm:.3f} g"
    piv = results.urm.pivot
    if piv is not None and piv.model_pivot == "crushing" and piv.pivot_shift > 0.0:
        text += f" about the crushing pivot (x = {piv.depth * 1000:.0f} mm)"
    return text


@contextmanager
def progress_bars(console: Console, n_cases: int, n_records: int) -> Iterator[ProgressFn]:
    """A progress callback (stage, done, total) drawing one bar per stage of a run."""
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
    )

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
                "ida": f"IDA {n_cases} cases × {n_records} records",
                "design": "design mode",
                "sensitivity": "sensitivity to the model conventions",
                "checks": "code checks (time histories at a_g·S)",
                "writing": "writing results",
                "verify": "numerical check (10x tighter tolerance)",
            }.get(stage)
            if label is None:
                return
            if stage not in tasks:
                tasks[stage] = bar.add_task(label, total=total)
            bar.update(tasks[stage], completed=done, total=total)

        yield progress


def _run(
    args: argparse.Namespace, inputs: AssessmentInputs, out_dir: Path, files: list[str]
) -> int:
    from frp_assess.app.assessment import prepare_records, run_assessment
    from frp_assess.app.kernel import compile_notice

    path = Path(args.file)
    digest = inputs_digest(path, files, rtol=args.rtol, verify=args.verify)
    console = make_console()
    if (notice := compile_notice()) is not None:  # a cold numba cache: say why it waits
        console.print(notice)
    with console.status("generating/reading the records and checking them against the spectrum"):
        seismic = prepare_records(inputs)
    for line in seismic.warnings:
        print(f"frp-assess: warning: {plain(line)}", file=sys.stderr)
    print_compliance(console, seismic.compliance)
    cancel = threading.Event()
    with progress_bars(console, 1 + len(inputs.options), len(seismic.records)) as progress:
        try:
            results, stats = run_assessment(
                inputs,
                out_dir,
                jobs=args.jobs,
                progress=progress,
                cancel=cancel,
                seismic=seismic,
                pdf=not args.no_pdf,
                created=args.created,
                inputs_digest=digest,
            )
        except KeyboardInterrupt:
            cancel.set()
            raise Cancelled("interrupted") from None
    write_sidecar(out_dir, digest, results.created, files, pdf=not args.no_pdf)
    print_summary(console, results)
    console.print(
        f"{stats.computed} IDAs computed, {stats.reused} reused from the cache; "
        f"results in {user(out_dir)}/"
    )
    return 0


def print_summary(console: Console, results: AssessmentResult) -> None:
    """What a run prints after its progress: the wall, the checks, the ranking, the
    recommendation (from the typed results only: also for an unchanged rerun)."""
    w = results.wall
    urm = results.urm
    target = float(results.model.target)
    console.print(
        f"wall B = {w.thickness:g} m, H = {w.height:g} m, α = {w.alpha_deg:.2f}°, "
        f"{activation_text(results)}, {user(w.mechanism)}; unreinforced: design a_dyn = "
        f"{urm.design_a_dyn:.3f} g, capacity/demand = {fmt_capacity(urm, target)} at "
        f"FC·a_g·S = {urm.fc * results.demand.pga:.3f} g (FC = {urm.fc:g}); "
        f"verdict: {verdict_text(urm)}"
    )
    print_floor_and_checks(console, results)
    cc = results.code_check
    console.print(
        f"code kinematic check (Circolare 2019 §C8.7.1, q = {cc.behaviour_factor:g}, "
        f"FC = {cc.FC:g}): a0* = {cc.a0_star:.3f} g vs "
        f"{'a_Z/q' if results.building else 'a_g·S/q'} = {cc.demand:.3f} g "
        f"-> {'satisfied' if cc.passed else 'NOT satisfied'} (supporting check). "
        f"{user(cc.note)}"
    )
    if len(results.cases) > 1:
        print_ranking(console, results)
        console.print(f"Decision rule: {user(results.decision_rule)}")
        console.print(f"Ranking rule: {user(results.ranking_rule)}")
        console.print(f"{recommendation_label(results)}: " + user(recommendation_text(results)))
        for line in built_lines(results):
            console.print(user(line))
        if results.robustness is not None:
            console.print(f"Robustness: {user(results.robustness.summary)}")
    if not results.input_code_compliant:
        console.print(
            f"[bold red]INPUT NOT CODE-COMPLIANT[/]: {noncompliant_sets(results)} fail the "
            "code's spectrum-compatibility checks; the results are not a basis for a "
            "signed verdict and no option is recommended."
        )
    for d in results.design or ():
        console.print(f"design {user(d.material)} {user(d.position)}: {user(d.message)}")
    check = numerical_check_text(results)
    if check is not None:
        console.print(user(check))
