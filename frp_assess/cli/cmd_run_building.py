"""`frp-assess run BUILDING.yaml [--wall NAME]`: every wall of a building file, then the
building summary (:mod:`frp_assess.app.building_run`)."""

from __future__ import annotations

import argparse
import sys
import threading
from contextlib import ExitStack
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from rich.console import Console

from frp_assess.cli.output import Column, make_console, print_table, user
from frp_assess.errors import Cancelled, InputError
from frp_assess.results.building_rows import CHECK_HEADERS, check_rows, retrofit_rows
from frp_assess.results.building_summary import CHECK_COLUMNS, BuildingResults
from frp_assess.text_safety import plain

if TYPE_CHECKING:
    from frp_assess.app.assessment import SeismicInput
    from frp_assess.app.building_run import BuildingInputs, WallInputs
    from frp_assess.app.study import Executor


def _with_options(building: BuildingInputs, args: argparse.Namespace) -> BuildingInputs:
    """The walls' inputs with ``--rtol`` and ``--verify`` applied (as a one-wall run)."""
    walls = []
    for w in building.walls:
        inputs = w.inputs
        if args.rtol is not None:
            inputs = replace(inputs, model=replace(inputs.model, tolerance=args.rtol))
        if args.verify:
            inputs = replace(inputs, verify=True)
        walls.append(replace(w, inputs=inputs))
    return replace(building, walls=tuple(walls))


def _executor(args: argparse.Namespace) -> Executor | None:
    """The Dask executor of ``--executor dask`` / ``--scheduler ADDRESS`` (its ``--jobs``
    workers on a LocalCluster), or None: the walls on local threads.  Without dask installed:
    one line, exit 2."""
    from frp_assess.app.study import make_executor

    if args.executor == "local" and args.scheduler is None:
        return None
    return make_executor(args.executor, args.scheduler, args.jobs)


def run_building_file(args: argparse.Namespace, path: Path, out: Path) -> int:
    """Run a building file (every wall, or ``--wall NAME``) into ``out``."""
    from frp_assess.app.building_run import check_building_out, load_building_inputs, run_building
    from frp_assess.app.kernel import compile_notice
    from frp_assess.app.rerun import referenced_paths
    from frp_assess.cli.cmd_run import print_compliance, print_summary, progress_bars

    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    building = load_building_inputs(path, only=args.wall)  # InputError: one line, exit 2
    building = _with_options(building, args)
    files = referenced_paths(building.walls[0].wall.loaded.project)
    out_dir = check_building_out(out, building, [path, *(path.parent / f for f in files)])
    console = make_console()
    if (notice := compile_notice()) is not None:
        console.print(notice)
    cancel = threading.Event()
    executor = _executor(args)
    if executor is not None:
        console.print(f"walls' IDAs on {executor.describe()}")
    with ExitStack() as bars:

        def records_ready(seismic: SeismicInput) -> None:
            for line in seismic.warnings:
                print(f"frp-assess: warning: {plain(line)}", file=sys.stderr)
            print_compliance(console, seismic.compliance)
            state["records"] = len(seismic.records)

        def wall_started(index: int, count: int, wall: WallInputs) -> None:
            bars.close()  # the previous wall's bars
            console.rule(user(f"wall {index + 1} of {count}: {wall.name} ({wall.folder}/)"))
            n_cases = 1 + len(wall.inputs.options)
            n_records = state.get("records", 0)
            assert isinstance(n_records, int)
            state["progress"] = bars.enter_context(progress_bars(console, n_cases, n_records))

        state: dict[str, object] = {}

        def progress(stage: str, done: int, total: int) -> None:
            callback = state.get("progress")
            if callable(callback):
                callback(stage, done, total)

        try:
            run = run_building(
                building,
                out_dir,
                jobs=args.jobs,
                progress=progress,
                wall_started=wall_started,
                records_ready=records_ready,
                cancel=cancel,
                created=args.created,
                pdf=not args.no_pdf,
                reuse=args.created is None,  # --created (the golden tests): always run
                executor=executor,
            )
        except KeyboardInterrupt:
            cancel.set()
            raise Cancelled("interrupted") from None
        finally:
            if executor is not None:
                executor.close()
    for outcome in run.walls:
        console.rule(user(f"{outcome.wall.name}: {outcome.wall.folder}/"))
        if outcome.unchanged:
            console.print(f"unchanged since {user(outcome.results.created)}: nothing recomputed")
        print_summary(console, outcome.results)
    if run.building is not None:
        print_building_summary(console, run.building)
    per_wall = "; ".join(
        f"{o.wall.name}: unchanged"
        if o.unchanged
        else f"{o.wall.name}: {o.stats.computed} computed, {o.stats.reused} reused"
        for o in run.walls
    )
    where = f"{out_dir}/" if run.building is not None else f"{out_dir}/{run.walls[0].wall.folder}/"
    console.print(
        f"{run.computed} IDAs computed, {run.reused} reused from the cache ({user(per_wall)}); "
        f"results in {user(where)}"
    )
    if run.building is None:
        console.print(
            "one wall run (--wall): the building's summary in "
            f"{user(out_dir)}/ is written by a run of every wall"
        )
    return 0


def print_building_summary(console: Console, b: BuildingResults) -> None:
    """The building summary: the checks' ζ_E per wall, the verdicts and retrofits, the
    totals and the governing mechanism."""
    console.rule(user(f"building: {b.project.name}"))
    check_cols = (
        Column("wall", text=True),
        Column("α0"),
        Column("a0* [g]"),
        *(Column(CHECK_HEADERS[key]) for key, _ in CHECK_COLUMNS),
        Column("governing", text=True, fold=False),
    )
    print_table(console, "Building summary: ζ_E of every check (the walls as they are)",
                check_cols, check_rows(b))  # fmt: skip
    retrofit_cols = (
        Column("wall", text=True),
        Column("as it is", text=True, fold=False),
        Column("proposed retrofit (bars as built)", text=True),
        Column("retrofitted", text=True),
        Column("FRP [kg]"),
        Column(f"cost [{b.totals.currency}]"),
    )
    print_table(console, "Building summary: verdicts and proposed retrofits",
                retrofit_cols, retrofit_rows(b))  # fmt: skip
    t = b.totals
    console.print(
        f"building: {t.walls} walls, {t.walls_failing} failing as they are; retrofit proposed "
        f"for {t.walls_retrofitted}: FRP {t.frp_mass:.1f} kg, {t.cost:,.0f} "
        f"{user(t.currency)} (indicative)"
        + (
            f"; {t.walls_without_solution} failing wall(s) with no passing option"
            if t.walls_without_solution
            else ""
        )
    )
    failing = [w.name for w in b.walls if not w.input_code_compliant]
    if failing:
        console.print(
            "[bold red]INPUT NOT CODE-COMPLIANT[/]: the records of "
            f"{user(', '.join(failing))} fail the code's spectrum-compatibility checks; the "
            "building's verdicts are not a basis for a signed verdict."
        )
    margin = "unbounded" if t.governing_margin is None else f"ζ_E = {t.governing_margin:.2f}"
    console.print(
        f"governing mechanism: {user(t.governing_wall)} ({user(t.governing_check or '—')}, "
        f"{margin})"
    )
