"""`frp-assess records`: generate spectrum-compatible accelerograms and check record sets.

frp-assess records generate --spectrum A2 --count 7 --seed 1 --out records/
frp-assess records check rec1.AT2 rec2.AT2 rec3.AT2 --spectrum ec8:type=1,ground=B,ag=0.25
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from rich.console import Console
from rich.table import Table

from frp_assess.app.records import (
    DEFAULT_T1,
    ENVELOPES,
    FORMATS,
    SPECTRUM_HELP,
    UNITS,
    ComplianceReport,
    ElasticSpectrum,
    check_compliance,
    generate_records,
    parse_spectrum,
    read_records,
)
from frp_assess.cli.arg_types import number_in, whole_number_in
from frp_assess.config.schema import (
    MAX_RECORD_DURATION,
    MAX_SEED,
    MIN_SPECTRUM_G,
    MIN_TIME_STEP,
    T1_RANGE,
)
from frp_assess.errors import InputError
from frp_assess.output_set import check_out_dir

#: bounds of the arguments (those of the project file's schema)
COUNT = whole_number_in(1, 100)
SEED = whole_number_in(0, MAX_SEED)
DURATION = number_in(0, MAX_RECORD_DURATION, low_open=True, unit="s")
TIME_STEP = number_in(MIN_TIME_STEP, 0.05, unit="s")
T1 = number_in(*T1_RANGE, unit="s")

T1_HELP = (
    f"fundamental period T1 of the structure [s] for the check ranges (EC8 0.2T1-2T1, NTC "
    f"0.15 s-max(2 s, 2T1)); default {DEFAULT_T1:g} s, a choice for a rocking wall, whose "
    "apparent period grows with the amplitude"
)


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "records",
        help="generate artificial accelerograms, check record sets against a code spectrum",
        description="Spectrum-compatible artificial accelerograms (SIMQKE) and the code checks "
        "of EN 1998-1 §3.2.3.1.2 and NTC 2018 §3.2.3.6.",
    )
    rsub = p.add_subparsers(dest="records_command", metavar="ACTION", parser_class=type(p))
    rsub.required = True

    g = rsub.add_parser(
        "generate",
        help="generate a set of spectrum-compatible records",
        description="Generate COUNT artificial accelerograms compatible with the target "
        "spectrum (SIMQKE, Gasparini & Vanmarcke 1976), write them as PEER .AT2 files (in g) "
        "with spectra.csv (target and mean spectra), and print the code checks. "
        "The same seed gives the same records, bit for bit.",
    )
    g.add_argument("--spectrum", required=True, metavar="SPEC", help=SPECTRUM_HELP)
    g.add_argument("--count", type=COUNT, default=7, help="number of records, 1-100 (default 7)")
    g.add_argument("--seed", type=SEED, default=1, help=f"random seed, 0-{MAX_SEED} (default 1)")
    g.add_argument(
        "--duration",
        type=DURATION,
        default=25.0,
        help=f"total duration [s], at most {MAX_RECORD_DURATION:g} (25)",
    )
    g.add_argument(
        "--dt", type=TIME_STEP, default=0.005, help=f"time step [s], {MIN_TIME_STEP:g}-0.05 (0.005)"
    )
    g.add_argument(
        "--stationary",
        type=DURATION,
        default=10.0,
        help="stationary part of the envelope [s] (10), shorter than the duration",
    )
    g.add_argument("--envelope", choices=ENVELOPES, default="trapezoidal", help="envelope shape")
    g.add_argument("--t1", type=T1, default=DEFAULT_T1, metavar="T1", help=T1_HELP)
    g.add_argument("--out", required=True, metavar="DIR", help="output folder")
    g.set_defaults(handler=run_generate)

    c = rsub.add_parser(
        "check",
        help="check a set of record files against a code spectrum",
        description="Check any set of records (recorded or artificial) against the target "
        "spectrum, clause by clause (EN 1998-1 §3.2.3.1.2, NTC 2018 §3.2.3.6). "
        "Exit code 0 if every check passes, 1 otherwise.",
    )
    c.add_argument("files", nargs="+", metavar="FILE", help="record files")
    c.add_argument("--spectrum", required=True, metavar="SPEC", help=SPECTRUM_HELP)
    c.add_argument("--units", default="g", choices=sorted(UNITS), help="units of the files")
    c.add_argument("--format", default="auto", choices=FORMATS, help="file format")
    c.add_argument(
        "--dt",
        type=TIME_STEP,
        default=None,
        help=f"time step [s] of one-column files, {MIN_TIME_STEP:g}-0.05",
    )
    c.add_argument(
        "--recorded",
        action="store_true",
        help="check as recorded records (NTC: mean within 90-130 %% of the target)",
    )
    c.add_argument("--t1", type=T1, default=DEFAULT_T1, metavar="T1", help=T1_HELP)
    c.set_defaults(handler=run_check)


def _positive(value: float, key: str) -> None:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"expected a number > 0, found {value:g}", key=key)


def spectrum_arg(text: str) -> ElasticSpectrum:
    """The spectrum of ``--spectrum``, refused (one line) when its a_g*S is below the
    project file's smallest, :data:`~frp_assess.config.schema.MIN_SPECTRUM_G`."""
    spectrum = parse_spectrum(text)
    if not spectrum.pga_g >= MIN_SPECTRUM_G:
        raise InputError(
            f"expected a spectrum with a_g*S >= {MIN_SPECTRUM_G:g} g, found {spectrum.pga_g:g} g",
            key="--spectrum",
        )
    return spectrum


def run_generate(args: argparse.Namespace) -> int:
    spectrum = spectrum_arg(args.spectrum)
    check_out_dir(Path(args.out))
    for key in ("duration", "dt", "stationary", "t1"):
        _positive(getattr(args, key), f"--{key}")
    if args.count < 1:
        raise InputError(f"expected a count >= 1, found {args.count}", key="--count")
    if args.stationary >= args.duration:
        raise InputError(
            f"expected a stationary part shorter than --duration {args.duration:g} s, found "
            f"{args.stationary:g} s",
            key="--stationary",
        )
    out = Path(args.out)
    # written as one set: no half-written set behind a full disk or an interrupt
    made = generate_records(
        spectrum,
        out,
        count=args.count,
        seed=args.seed,
        duration=args.duration,
        dt=args.dt,
        stationary=args.stationary,
        envelope=args.envelope,
        t1=args.t1,
    )
    console = Console()
    console.print(
        f"wrote {len(made.records)} records and spectra.csv to {out} "
        f"(seed {args.seed}, set factor {made.set_scale_factor:.4f})"
    )
    print_report(made.report, spectrum, console)
    return 0 if made.report.passed else 1


def run_check(args: argparse.Namespace) -> int:
    spectrum = spectrum_arg(args.spectrum)
    _positive(args.t1, "--t1")
    records, warnings = read_records(args.files, format=args.format, units=args.units, dt=args.dt)
    for warning in warnings:
        print(f"frp-assess: warning: {warning}", file=sys.stderr)
    report = check_compliance(records, spectrum, t1=args.t1, recorded=args.recorded)
    print_report(report, spectrum, Console())
    return 0 if report.passed else 1


def print_report(
    report: ComplianceReport, spectrum: ElasticSpectrum, console: Console | None = None
) -> None:
    """The compliance table (one row per requirement) and the verdict."""
    console = console or Console()
    kind = "recorded" if report.recorded else "artificial"
    table = Table(
        title=f"{len(report.record_names)} {kind} records vs {spectrum.name} "
        f"(T1 = {report.t1:g} s, ξ = {report.damping:.0%})"
    )
    table.add_column("code", no_wrap=True)
    table.add_column("clause", no_wrap=True)
    table.add_column("requirement")
    table.add_column("found")
    table.add_column("margin", justify="right", no_wrap=True)
    table.add_column("result", no_wrap=True)
    for c in report.checks:
        margin = f"{c.margin:+.1%}" if c.unit == "" else f"{c.margin:+g} {c.unit}"
        result = "[green]pass[/green]" if c.passed else "[bold red]FAIL[/bold red]"
        table.add_row(c.code, c.clause, c.requirement, c.found, margin, result)
    console.print(table)
    console.print(spectrum.description)
    verdict = "all checks pass" if report.passed else "some checks FAIL"
    console.print(f"[bold]{verdict}[/bold]")
