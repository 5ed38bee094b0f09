"""`frp-assess validate FILE`: check a project or study file and summarise it; nothing is
computed or written.  Every problem of the file is printed, one line each, in file order."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from frp_assess.app.project import (
    CheckedBuilding,
    CheckedStudy,
    LoadedProject,
    check_file,
    problems_of,
)
from frp_assess.app.study import StudyFile
from frp_assess.config.library import MASONRY
from frp_assess.config.schema import (
    Ec8Spectrum,
    Ntc2018Spectrum,
    PresetSpectrum,
    Project,
    TableSpectrum,
)
from frp_assess.config.schema.loads_spec import WallLoadsSpec
from frp_assess.errors import InputError
from frp_assess.rules.intervention import CATEGORY_CLAUSE
from frp_assess.rules.tie_rods import tie_anchorage_force, tie_is_ductile, tie_yield_force


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "validate",
        help="check a project or study file and print a short summary",
        description="Load and validate a project file or a study file (YAML, told apart by "
        "their keys): every problem is reported as one line 'file:line: key: message', in file "
        "order, with exit code 2. Nothing is computed or written.",
    )
    p.add_argument("file", help="project or study file (YAML)")
    p.set_defaults(handler=run)


def spectrum_summary(project: Project) -> str:
    """One line describing the spectrum of the project."""
    s = project.seismic.spectrum
    if isinstance(s, Ntc2018Spectrum):
        ag, f0, tc = s.parameters()
        where = ""
        hazard = s.site_hazard()
        if hazard is not None:
            state = s.chosen_limit_state
            where = (
                f" (site {hazard.latitude:g}°N {hazard.longitude:g}°E, V_R = {hazard.V_R:g} "
                f"years, {state} T_R = {hazard[state].TR:.0f} years)"
            )
            ag, f0, tc = round(ag, 4), round(f0, 3), round(tc, 3)
        return (
            f"NTC 2018, a_g = {ag:g} g, F0 = {f0:g}, T_C* = {tc:g} s{where}, "
            f"soil {s.soil}, {s.topography}"
        )
    if isinstance(s, Ec8Spectrum):
        return f"EC8 type {s.spectrum_type}, a_g = {s.ag:g} g, ground {s.ground}"
    if isinstance(s, PresetSpectrum):
        return f"preset {s.name} (the paper's spectra)"
    assert isinstance(s, TableSpectrum)
    return f"table of {len(s.periods)} points, T = {s.periods[0]:g}-{s.periods[-1]:g} s"


def building_summary(project: Project) -> str:
    """Where the wall stands: at ground level, or on the floor at Z of the building."""
    b = project.building
    if b is None:
        return "none: the wall stands at ground level and is shaken by the ground"
    period = f"T1 = {b.first_period:.3g} s" + ("" if b.period is not None else " (0.05*H_b^0.75)")
    return (
        f"H_b = {b.height:g} m, {b.storeys} storeys, wall base Z = {b.wall_base:g} m "
        f"(Z/H_b = {b.wall_base / b.height:.3g}), {period}, xi = {b.damping:g}: "
        "shaken by the floor motion at Z"
    )


def code_check_summary(project: Project) -> str:
    """Knowledge level, FC [-] and whether FC divides the IDA's capacity/demand (docs/model.md
    §5.3, §5.5), the behaviour factor q [-] and the category of the intervention (NTC 2018
    §8.4)."""
    cc = project.code_check
    fc = cc.confidence_factor
    where = (
        "in the IDA verdict too" if cc.fc_in_ida else "not in the IDA verdict (fc_in_ida: false)"
    )
    category = f"{cc.intervention} ({CATEGORY_CLAUSE[cc.intervention]})"
    if cc.use_class is not None:
        category += f", use class {cc.use_class}" + (" school" if cc.school else "")
    return (
        f"{cc.knowledge_level}, FC = {fc:g} ({where}), q = {cc.behaviour_factor:g}; "
        f"intervention: {category}"
    )


#: newtons in a kilonewton: mm²·MPa is N, the summary prints kN
_N_PER_KN = 1000.0


def loads_summary(loads: WallLoadsSpec) -> str:
    """One line: every load with its lever (d from the outer face, h above the base) and
    whether its mass moves with the wall; each tie's F_y and whether it yields before its
    anchorage fails (docs/model.md §12)."""
    parts = [
        f"{p.name or f'top load {i + 1}'} {p.load:g} kN/m at d = {p.distance:g} m ({p.inertia})"
        for i, p in enumerate(loads.top)
    ]
    parts += [
        f"{f.name or f'thrust {i + 1}'} {f.force:g} kN/m outward at h = {f.height:g} m"
        for i, f in enumerate(loads.thrust)
    ]
    for i, t in enumerate(loads.ties):
        f_y = tie_yield_force(t.area_mm2, float(t.yield_strength), float(t.spacing)) / _N_PER_KN
        f_a = tie_anchorage_force(None if t.anchorage is None else float(t.anchorage),
                                  float(t.spacing))  # fmt: skip
        kind = "ductile" if tie_is_ductile(f_y, f_a) else f"brittle, F_a/i_t = {f_a:.3g} kN/m"
        parts.append(
            f"{t.name or f'tie {i + 1}'} A_s = {t.area_mm2:.4g} mm2 every {t.spacing:g} m at "
            f"h_t = {t.height:g} m (F_y = {f_y:.3g} kN/m, {kind})"
        )
    return "; ".join(parts) or "none"


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
    an = p.analysis
    lines = [
        f"{loaded.path}: OK — {p.project.name}",
        f"  wall: B = {w.thickness:g} m, H = {w.height:g} m, L = {w.length:g} m, "
        f"w = {p.unit_weight_kn():g} kN/m3{source}, {w.mechanism}",
        f"  spectrum: {spectrum_summary(p)}",
        f"  records: {records}",
        f"  options: {len(options)} after expansion"
        + (f" ({names})" if options else " (only the unreinforced wall)"),
        f"  analysis: restitution {an.restitution}, rupture {an.rupture}, collapse "
        f"{an.collapse}, pivot {an.pivot}, integration tolerance "
        f"{an.integration.tolerance:g}, target capacity/demand {an.target:g}",
        f"  code check: {code_check_summary(p)}",
    ]
    if p.building is not None:
        lines.insert(3, f"  building: {building_summary(p)}")
    if w.loads is not None:
        lines.insert(2, f"  loads: {loads_summary(w.loads)}")
    if p.design is not None:
        d = p.design
        lines.append(
            f"  design: {', '.join(d.materials)} × {', '.join(d.positions)}, ratio "
            f"{d.ratio_range[0]:g}-{d.ratio_range[1]:g} ‰"
        )
    return lines


#: the lines of :func:`summary` that belong to a wall of a building (the rest is shared)
_WALL_LINES = ("  wall:", "  loads:", "  building:", "  options:", "  design:")


def building_file_summary(checked: CheckedBuilding) -> list[str]:
    """The lines printed by `validate` for a building file: the shared blocks once, then
    each wall's own lines under its name."""
    b = checked.building
    first = summary(b.walls[0].loaded)
    lines = [f"{b.path}: OK — building {b.name!r}: {len(b.walls)} walls"]
    lines += [ln for ln in first[1:] if not ln.startswith(_WALL_LINES)]
    for w in b.walls:
        lines.append(f"  walls[{w.entry.index}] {w.name!r} (results in walls/{w.entry.slug}/):")
        own = summary(w.loaded)[1:]
        lines += [f"  {ln}" for ln in own if ln.startswith(_WALL_LINES)]
    return lines


def study_summary(study: StudyFile, file: str) -> list[str]:
    """The lines printed by `validate` for a study file."""
    rec = study.records
    geometry = "alpha_deg" if study.alpha_deg is not None else "thickness"
    return [
        f"{file}: OK — study {study.name!r}: {study.case_count():,} cases",
        f"  axes: {len(study.height)} height(s) × {len(study.alpha_deg or study.thickness or [])} "
        f"{geometry} × {len(study.mechanism)} mechanism(s) × {len(study.spectrum)} spectra; "
        f"{len(study.material)} material(s) × {len(study.position)} position(s) × "
        f"{len(study.ratio)} ratio(s)",
        f"  records: {rec.count} artificial per spectrum (seed {rec.seed}, {rec.duration:g} s, "
        f"dt = {rec.dt:g} s)",
    ]


def validate_file(path: Path) -> tuple[list[str], tuple[str, ...]]:
    """Validate a project or a study file (:func:`frp_assess.app.project.check_file`).

    Returns:
        the summary lines and the warnings (one line each, e.g. placeholders left unchanged).

    Raises:
        InputError: every problem (:class:`~frp_assess.config.problems.InputErrors`).
    """
    checked = check_file(path)
    if isinstance(checked, CheckedStudy):
        return study_summary(checked.study, checked.file), ()
    if isinstance(checked, CheckedBuilding):
        return building_file_summary(checked), checked.warnings
    return summary(checked.loaded), checked.warnings


def print_problems(error: InputError) -> None:
    """Every problem of ``error`` on stderr, one line each, as the CLI prints an error."""
    for problem in problems_of(error):
        print(f"frp-assess: error: {problem}", file=sys.stderr)


def run(args: argparse.Namespace) -> int:
    try:
        lines, warnings = validate_file(Path(args.file))
    except InputError as exc:
        print_problems(exc)
        return 2
    for warning in warnings:
        print(f"frp-assess: warning: {warning}", file=sys.stderr)
    print("\n".join(lines))
    return 0
