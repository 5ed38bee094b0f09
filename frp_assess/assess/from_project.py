"""From a validated project file (:mod:`frp_assess.config`) to :class:`AssessmentInputs`.

The config layer knows YAML keys and their validation; the assessment knows domain objects.
This module is the one place where the first is translated into the second, so that the CLI
and the TUI build exactly the same inputs from the same project.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path

from frp_assess.assess.bar_catalogue import BarSize
from frp_assess.assess.bars_as_built import as_built_difference, option_with_layout
from frp_assess.assess.decision import InterventionCategory
from frp_assess.assess.inputs import (
    AnchorageSettings,
    ArtificialRecords,
    AssessmentInputs,
    BarSettings,
    BuildingSettings,
    CodeCheckSettings,
    CostSettings,
    DesignRequest,
    Material,
    RecordFile,
    RetrofitOption,
    TiePrices,
)
from frp_assess.assess.load_inputs import (
    NO_LOAD_INPUTS,
    LoadsInput,
    ThrustInput,
    TieInput,
    TopLoadInput,
    default_name,
)
from frp_assess.assess.wall_model import base_problem
from frp_assess.config import MASONRY, FrpMaterial, LoadedProject, Project, load_project
from frp_assess.config.messages import Loc, format_path, line_of
from frp_assess.config.plausibility import project_warnings
from frp_assess.config.problems import problems_of, raise_all
from frp_assess.config.schema import (
    BarsSpec,
    BuildingSpec,
    Ec8Spectrum,
    Intervention,
    Ntc2018Spectrum,
    PresetSpectrum,
    TableSpectrum,
    TieOption,
)
from frp_assess.config.schema.loads_spec import TieSpec, WallLoadsSpec
from frp_assess.errors import InputError
from frp_assess.motions import (
    ElasticSpectrum,
    Record,
    ec8_spectrum,
    ntc2018_spectrum,
    preset_spectrum,
    read_record,
    table_spectrum,
)
from frp_assess.results.run_inputs import ReportSettings


def spectrum_of(
    spec: Ntc2018Spectrum | Ec8Spectrum | PresetSpectrum | TableSpectrum,
) -> ElasticSpectrum:
    """The elastic spectrum described by the ``seismic.spectrum`` block."""
    if isinstance(spec, Ntc2018Spectrum):
        ag, f0, tc = spec.parameters()
        return ntc2018_spectrum(ag, f0, tc, spec.soil, spec.topography, spec.damping)
    if isinstance(spec, Ec8Spectrum):
        return ec8_spectrum(spec.ag, spec.ground, spec.spectrum_type, spec.damping)
    if isinstance(spec, PresetSpectrum):
        return preset_spectrum(spec.name)
    return table_spectrum(spec.periods, spec.accelerations, name="user table")


def material_of(frp: FrpMaterial) -> Material:
    return Material(
        frp.name,
        frp.elastic_modulus,
        frp.ultimate_strain,
        frp.density,
        frp.price,
        frp.source,
        characteristic_strain=frp.characteristic_strain,
        fibre=frp.fibre,
    )


def building_of(spec: BuildingSpec | None) -> BuildingSettings | None:
    """The building of the ``building`` block (T1 defaulted by Circolare 2019 eq. C7.3.2)."""
    if spec is None:
        return None
    return BuildingSettings(
        float(spec.height),
        int(spec.storeys),
        float(spec.wall_base),
        spec.first_period,
        float(spec.damping),
    )


def loads_of(spec: WallLoadsSpec | None) -> LoadsInput:
    """The project's ``wall.loads`` as the assessment's loads (docs/model.md §12), each
    named (the project's name, else its kind and place in its list)."""
    if spec is None:
        return NO_LOAD_INPUTS
    return LoadsInput(
        top=tuple(
            TopLoadInput(
                default_name("top load", i, p.name),
                float(p.load),
                float(p.distance),
                p.inertia == "carried",
            )
            for i, p in enumerate(spec.top)
        ),
        thrusts=tuple(
            ThrustInput(default_name("thrust", i, f.name), float(f.force), float(f.height))
            for i, f in enumerate(spec.thrust)
        ),
        ties=tuple(tie_of(t, default_name("tie", i, t.name)) for i, t in enumerate(spec.ties)),
    )


def tie_of(spec: TieSpec, name: str) -> TieInput:
    """A tie of ``wall.loads.ties`` or of a tie option, named ``name``."""
    return TieInput(
        name,
        float(spec.height),
        spec.area_mm2,
        float(spec.spacing),
        float(spec.length),
        float(spec.yield_strength),
        float(spec.elastic_modulus),
        None if spec.anchorage is None else float(spec.anchorage),
        None if spec.diameter is None else float(spec.diameter),
    )


def option_of(option: Intervention | TieOption, table: Mapping[str, Material]) -> RetrofitOption:
    """An expanded (named) option of ``interventions`` as the assessment's option: its bars
    (none for ``type: tie``) and its tie, named as the option for a tie alone."""
    if isinstance(option, TieOption):
        return RetrofitOption(str(option.name), None, None, 0.0, tie=tie_of(option, option.name))
    return RetrofitOption(
        str(option.name),
        table[option.material],
        option.position,
        float(option.ratio),
        ratio_asked=float(option.ratio),
        diameter=None if option.diameter is None else float(option.diameter),
        tie=None if option.tie is None else tie_of(option.tie, option.tie.name or "tie"),
    )


def costs_of(project: Project) -> CostSettings:
    """The ``costs`` block: the bars' installation and the prices of a tie."""
    c = project.costs
    ties = TiePrices(
        float(c.tie_steel_per_kg),
        float(c.tie_steel_per_metre),
        float(c.tie_plate),
        float(c.tie_installation),
    )
    return CostSettings(str(c.currency), c.installation_per_metre, ties)


def bar_settings_of(spec: BarsSpec) -> BarSettings:
    """The ``bars:`` block as :class:`BarSettings`."""
    a = spec.anchorage
    return BarSettings(
        exposure=spec.exposure,
        design_values=spec.design_values,
        whole_bars=spec.whole_bars,
        min_spacing=spec.min_spacing,
        max_spacing=spec.max_spacing,
        catalogue=tuple(
            BarSize(b.material, float(b.diameter), float(b.area), str(b.source))
            for b in spec.catalogue
        ),
        anchorage=None
        if a is None
        else AnchorageSettings(a.hole_clearance, a.bond_bar, a.bond_masonry, a.tensile_strength),
    )


def _option_loc(project: Project, option: RetrofitOption, key: str) -> Loc:
    """Where in the file an expanded option comes from (its item, or the sweep's ratio)."""
    if option.material is None:
        return ("interventions",)  # a tie alone: never laid out
    for i, item in enumerate(project.interventions):
        if isinstance(item, TieOption):
            continue
        if isinstance(item, Intervention):
            if (
                item.material == option.material.name
                and item.position == option.position
                and float(item.ratio) == option.asked
                and item.diameter == option.diameter
            ):
                return ("interventions", i, key)
        elif (
            option.diameter is None
            and option.material.name in item.sweep.material
            and option.position in item.sweep.position
            and option.asked in item.sweep.ratio
        ):
            return ("interventions", i, "sweep", "ratio", item.sweep.ratio.index(option.asked))
    return ("interventions",)


def laid_out(
    project: Project, inputs: AssessmentInputs, *, file: str | None = None,
    lines: Mapping[Loc, int] | None = None,
) -> AssessmentInputs:  # fmt: skip
    """``inputs`` with every option laid out in whole bars (docs/model.md §2.1); every option
    that cannot be built is a problem located at its item (line when ``lines`` is given)."""
    options: list[RetrofitOption] = []
    problems: list[InputError] = []
    for option in inputs.options:
        try:
            options.append(option_with_layout(inputs, option))
        except InputError as exc:
            loc = _option_loc(project, option, exc.key or "ratio")
            problems.append(
                InputError(
                    f"{option.name}: {exc.message}",
                    file=file,
                    line=None if lines is None else line_of(lines, loc),
                    key=format_path(loc),
                )
            )
    raise_all(problems)
    return replace(inputs, options=tuple(options))


def report_settings(project: Project, base_dir: Path, file: str | None) -> ReportSettings:
    """The report block: its language, and the Word template resolved next to the project
    file (an InputError naming ``report.template`` when it is not a .docx file there)."""
    given = project.report.template
    if given is None:
        return ReportSettings(language=project.report.language, template=None)
    path = base_dir / str(given)
    if path.suffix.lower() != ".docx" or not path.is_file():
        raise InputError(
            f"expected a Word file (.docx) next to the project file, found {str(given)!r}"
            + ("" if path.is_file() else " (no such file)"),
            file=file,
            key="report.template",
        )
    return ReportSettings(language=project.report.language, template=str(path))


def intervention_of(
    project: Project, file: str | None, lines: Mapping[Loc, int] | None
) -> InterventionCategory:
    """The category of the intervention (``code_check.intervention``, NTC 2018 §8.4) with the
    building's use class: ``code_check.use_class``, else the spectrum's (by coordinates).
    Refused: two different use classes, an improvement without one (§8.4.2 depends on it),
    ``school`` for a class other than III."""
    cc = project.code_check
    spectrum = project.seismic.spectrum
    of_site = spectrum.use_class if isinstance(spectrum, Ntc2018Spectrum) else None
    use_class = cc.use_class or of_site

    def refuse(message: str, loc: Loc) -> InputError:
        line = None if lines is None else line_of(lines, loc)
        return InputError(message, file=file, line=line, key=format_path(loc))

    if cc.use_class is not None and of_site is not None and cc.use_class != of_site:
        raise refuse(
            f"expected one use class of the building, found code_check.use_class "
            f"{cc.use_class} and seismic.spectrum.use_class {of_site}",
            ("code_check", "use_class"),
        )
    if cc.intervention == "improvement" and use_class is None:
        raise refuse(
            "an improvement (NTC 2018 §8.4.2) depends on the building's use class: give "
            "code_check.use_class (I-IV); none was found",
            ("code_check", "intervention"),
        )
    if cc.school and use_class != "III":
        raise refuse(
            f"school: true applies to use class III (NTC 2018 §8.4.2), found use class "
            f"{use_class or 'none'}",
            ("code_check", "school"),
        )
    return InterventionCategory(cc.intervention, use_class, cc.school)


def inputs_from_project(
    project: Project,
    base_dir: Path,
    input_file: str = "",
    *,
    lines: Mapping[Loc, int] | None = None,
    file: str | None = None,
) -> AssessmentInputs:
    """Map a validated :class:`Project` onto the assessment's inputs, every option laid out
    in whole bars (:func:`laid_out`; an option that cannot be built is an InputError naming
    ``file`` (default ``input_file``), with its line when ``lines`` is given).

    Record file paths are resolved against ``base_dir`` (the project file's folder).
    """
    wall, seismic, analysis = project.wall, project.seismic, project.analysis
    table = {name: material_of(m) for name, m in project.material_table().items()}
    options = tuple(option_of(o, table) for o in project.expand_interventions())
    spec = seismic.records
    records: ArtificialRecords | tuple[RecordFile, ...]
    if spec.artificial is not None:
        a = spec.artificial
        records = ArtificialRecords(a.count, a.seed, a.duration, a.dt)
    else:
        records = tuple(
            RecordFile(str((base_dir / f.path).resolve()), f.format, f.units, f.dt, f.name)
            for f in spec.files or ()
        )
    design = None
    if project.design is not None:
        d = project.design
        design = DesignRequest(
            tuple(table[m] for m in d.materials),
            tuple(d.positions),
            (float(d.ratio_range[0]), float(d.ratio_range[1])),
            d.resolution,
        )
    info = project.project
    masonry_description = ""
    if wall.masonry is not None and wall.unit_weight is None:
        masonry_description = MASONRY[wall.masonry].description
    elif wall.masonry is not None:
        masonry_description = f"{MASONRY[wall.masonry].description}; unit weight given explicitly"
    ntc = seismic.spectrum if isinstance(seismic.spectrum, Ntc2018Spectrum) else None
    inputs = AssessmentInputs(
        thickness=wall.thickness,
        height=wall.height,
        unit_weight=project.unit_weight_kn(),
        mechanism=wall.mechanism,
        loads=loads_of(wall.loads),
        spectrum=spectrum_of(seismic.spectrum),
        site=ntc.site_hazard() if ntc is not None else None,
        site_limit_state=ntc.chosen_limit_state if ntc is not None else "SLV",
        records=records,
        options=options,
        length=wall.length,
        masonry=wall.masonry,
        masonry_description=masonry_description,
        compressive_strength=None
        if wall.compressive_strength is None
        else float(wall.compressive_strength),
        scale_to_spectrum=spec.scale_to_spectrum,
        t1=seismic.t1,
        model=analysis.model_options(analysis.integration.tolerance),
        verify=analysis.integration.verify,
        strain_factor=analysis.strain_factor,
        ida=analysis.ida.settings(),
        target=analysis.target,
        costs=costs_of(project),
        design=design,
        code_check=CodeCheckSettings(
            project.code_check.knowledge_level,
            project.code_check.behaviour_factor,
            project.code_check.fc_in_ida,
        ),
        building=building_of(project.building),
        project={
            "name": info.name,
            "location": info.location,
            "engineer": info.engineer,
            "notes": info.notes,
        },
        input_file=input_file,
        bars=bar_settings_of(project.bars),
        report=report_settings(project, base_dir, file or input_file or None),
        intervention=intervention_of(project, file or input_file or None, lines),
    )
    problem = base_problem(inputs.wall_input)
    if problem is not None:  # the one refusal of the masonry at the base (rules/masonry.py)
        raise InputError(
            problem,
            file=file or input_file or None,
            line=None if lines is None else line_of(lines, ("wall", "thickness")),
            key="wall.thickness",
        )
    if project.wall.loads is not None:
        try:  # the base and the uplift with the loads (docs/model.md §12), before any output
            inputs.model_for(None)
        except InputError as exc:
            loc = tuple(exc.key.split(".")) if exc.key else ("wall", "loads")
            raise InputError(
                exc.message,
                file=file or input_file or None,
                line=None if lines is None else line_of(lines, loc),
                key=exc.key,
            ) from None
    return laid_out(project, inputs, file=file or input_file or None, lines=lines)


def _print_warning(line: str) -> None:
    print(f"frp-assess: warning: {line}", file=sys.stderr)


def load_inputs(
    path: str | Path, *, warn: Callable[[str], None] | None = _print_warning
) -> AssessmentInputs:
    """Load, validate and map a project file; errors are one-line :class:`InputError`.

    Args:
        path: the project file.
        warn: called with each warning line of the file (placeholders left unchanged...);
            the default prints it on stderr as ``frp-assess: warning: ...``; None: silent.
    """
    return inputs_of_loaded(load_project(path), warn=warn)


def inputs_of_loaded(
    loaded: LoadedProject, *, warn: Callable[[str], None] | None = _print_warning
) -> AssessmentInputs:
    """:func:`load_inputs` of a project already loaded (a wall of a building file)."""
    _, problems = read_record_files(loaded.project, loaded.base_dir)
    raise_all(problems)  # before any output folder is made: a bad record writes nothing
    if warn is not None:
        for line in loaded.warnings:
            warn(line)
    inputs = inputs_from_project(
        loaded.project,
        loaded.base_dir,
        str(loaded.path.name),
        lines=loaded.lines,
        file=str(loaded.path),
    )
    warnings = tuple(w.text() for w in project_warnings(loaded.project))
    built = as_built_warnings(loaded, inputs)
    if warn is not None:
        for error in built:
            warn(str(error))
    warnings += tuple(f"{e.key}: {e.message}" for e in built)
    return replace(inputs, warnings=warnings) if warnings else inputs


def as_built_warnings(loaded: LoadedProject, inputs: AssessmentInputs) -> tuple[InputError, ...]:
    """One located warning (an InputError's file, line, key and message, not raised) per
    option whose bars as built are far from the ratio asked
    (:func:`~frp_assess.assess.bars_as_built.as_built_difference`)."""
    found = []
    for option in inputs.options:
        message = as_built_difference(option, whole_bars=inputs.bars.whole_bars)
        if message is not None:
            loc = _option_loc(loaded.project, option, "ratio")
            line = line_of(loaded.lines, loc)
            found.append(
                InputError(message, file=str(loaded.path), line=line, key=format_path(loc))
            )
    return tuple(found)


def layout_problems(loaded: LoadedProject) -> tuple[list[InputError], tuple[str, ...]]:
    """The options of a loaded project that cannot be built in whole bars (one located
    problem each), and the located warning lines of those built far from the ratio asked
    (:func:`as_built_warnings`), for ``validate``."""
    try:
        inputs = inputs_from_project(
            loaded.project,
            loaded.base_dir,
            str(loaded.path.name),
            lines=loaded.lines,
            file=str(loaded.path),
        )
    except InputError as exc:
        return list(problems_of(exc)), ()
    return [], tuple(str(e) for e in as_built_warnings(loaded, inputs))


def read_record_files(project: Project, base_dir: Path) -> tuple[list[Record], list[InputError]]:
    """Read every record file of a project (none for artificial records).

    Returns:
        the records read and the problems (one per unreadable file, each naming the file and,
        where it applies, its line), so that ``validate`` and ``run`` refuse a bad record file
        before any work or output.
    """
    records: list[Record] = []
    problems: list[InputError] = []
    for f in project.seismic.records.files or []:
        try:
            records.append(
                read_record(base_dir / f.path, format=f.format, units=f.units, dt=f.dt, name=f.name)
            )
        except InputError as exc:
            problems.append(exc)
    return records, problems
