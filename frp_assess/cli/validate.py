"""`frp-assess validate FILE`: check a project file and summarise it; nothing is computed."""

from __future__ import annotations

import argparse
import sys

from frp_assess.config import LoadedProject, load_project
from frp_assess.config.library import MASONRY
from frp_assess.config.problems import problems_of
from frp_assess.config.schema import (
    Ec8Spectrum,
    Ntc2018Spectrum,
    PresetSpectrum,
    Project,
    TableSpectrum,
)
from frp_assess.errors import InputError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "validate",
        help="check a project file and print a short summary",
        description="Load and validate a project file (YAML): every problem is reported as "
        "one line 'file:line: key: message' with exit code 2. Nothing is computed or written.",
    )
    p.add_argument("file", help="project file (YAML)")
    p.set_defaults(handler=run)


def spectrum_summary(project: Project) -> str:
    """One line describing the spectrum of the project."""
    s = project.seismic.spectrum
    if isinstance(s, Ntc2018Spectrum):
        return (
            f"NTC 2018, a_g = {s.ag:g} g, F0 = {s.F0:g}, T_C* = {s.Tc_star:g} s, "
            f"soil {s.soil}, {s.topography}"
        )
    if isinstance(s, Ec8Spectrum):
        return f"EC8 type {s.spectrum_type}, a_g = {s.ag:g} g, ground {s.ground}"
    if isinstance(s, PresetSpectrum):
        return f"preset {s.name} (the paper's spectra)"
    assert isinstance(s, TableSpectrum)
    return f"table of {len(s.periods)} points, T = {s.periods[0]:g}-{s.periods[-1]:g} s"


def summary(loaded: LoadedProject) -> list[str]:
    """The lines printed by `validate`."""
    p = loaded.project
    w = p.wall
    source = f" ({w.masonry})" if w.masonry and w.unit_weight is None else ""
    if w.masonry and w.unit_weight is not None:
        source = f" (explicit; {w.masonry} would give {MASONRY[w.masonry].unit_weight:g})"
    rec = p.seismic.records
    if rec.artificial is not None:
        a = rec.artificial
        records = (
            f"{a.count} artificial (seed {a.seed}, {a.duration:g} s, dt = {a.dt:g} s), "
            f"T1 = {p.seismic.t1:g} s"
        )
    else:
        files = rec.files or []
        scaled = "scaled to a_g*S" if rec.scale_to_spectrum else "not scaled"
        records = f"{len(files)} file(s), {scaled}"
    options = p.expand_interventions()
    names = ", ".join(o.name or "" for o in options[:4]) + (", ..." if len(options) > 4 else "")
    a = p.analysis
    lines = [
        f"{loaded.path}: OK — {p.project.name}",
        f"  wall: B = {w.thickness:g} m, H = {w.height:g} m, L = {w.length:g} m, "
        f"w = {p.unit_weight_kn():g} kN/m3{source}, {w.mechanism}",
        f"  spectrum: {spectrum_summary(p)}",
        f"  records: {records}",
        f"  options: {len(options)} after expansion"
        + (f" ({names})" if options else " (only the unreinforced wall)"),
        f"  analysis: restitution {a.restitution}, rupture {a.rupture}, collapse "
        f"{a.collapse}, target capacity/demand {a.target:g}",
    ]
    if p.design is not None:
        d = p.design
        lines.append(
            f"  design: {', '.join(d.materials)} × {', '.join(d.positions)}, ratio "
            f"{d.ratio_range[0]:g}-{d.ratio_range[1]:g} ‰"
        )
    return lines


def print_problems(error: InputError) -> None:
    """Every problem of ``error`` on stderr, one line each, as the CLI prints an error."""
    for problem in problems_of(error):
        print(f"frp-assess: error: {problem}", file=sys.stderr)


def run(args: argparse.Namespace) -> int:
    try:
        loaded = load_project(args.file)
    except InputError as exc:
        print_problems(exc)
        return 2
    print("\n".join(summary(loaded)))
    return 0
