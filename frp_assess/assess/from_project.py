"""From a validated project file (:mod:`frp_assess.config`) to :class:`AssessmentInputs`.

The config layer knows YAML keys and their validation; the assessment knows domain objects.
This module is the one place where the first is translated into the second, so that the CLI
and the TUI build exactly the same inputs from the same project.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    Building,
    CodeCheckSettings,
    Costs,
    DesignRequest,
    Material,
    Option,
    RecordFile,
)
from frp_assess.config import MASONRY, FrpMaterial, Project, load_project
from frp_assess.config.problems import raise_all
from frp_assess.config.schema import (
    BuildingSpec,
    Ec8Spectrum,
    Ntc2018Spectrum,
    PresetSpectrum,
    TableSpectrum,
)
from frp_assess.dynamics import IdaSettings
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


def spectrum_of(
    spec: Ntc2018Spectrum | Ec8Spectrum | PresetSpectrum | TableSpectrum,
) -> ElasticSpectrum:
    """The elastic spectrum described by the ``seismic.spectrum`` block."""
    if isinstance(spec, Ntc2018Spectrum):
        return ntc2018_spectrum(
            spec.ag, spec.F0, spec.Tc_star, spec.soil, spec.topography, spec.damping
        )
    if isinstance(spec, Ec8Spectrum):
        return ec8_spectrum(spec.ag, spec.ground, spec.spectrum_type, spec.damping)
    if isinstance(spec, PresetSpectrum):
        return preset_spectrum(spec.name)
    return table_spectrum(spec.periods, spec.accelerations, name="user table")


def material_of(frp: FrpMaterial) -> Material:
    return Material(
        frp.name, frp.elastic_modulus, frp.ultimate_strain, frp.density, frp.price, frp.source
    )


def building_of(spec: BuildingSpec | None) -> Building | None:
    """The building of the ``building`` block (T1 defaulted by Circolare 2019 eq. C7.3.2)."""
    if spec is None:
        return None
    return Building(
        float(spec.height),
        int(spec.storeys),
        float(spec.wall_base),
        spec.first_period,
        float(spec.damping),
    )


def inputs_from_project(project: Project, base_dir: Path, input_file: str = "") -> AssessmentInputs:
    """Map a validated :class:`Project` onto the assessment's inputs.

    Record file paths are resolved against ``base_dir`` (the project file's folder).
    """
    wall, seismic, analysis = project.wall, project.seismic, project.analysis
    table = {name: material_of(m) for name, m in project.material_table().items()}
    options = tuple(
        Option(str(o.name), table[o.material], o.position, float(o.ratio))
        for o in project.expand_interventions()
    )
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
    return AssessmentInputs(
        thickness=wall.thickness,
        height=wall.height,
        unit_weight=project.unit_weight_kn(),
        mechanism=wall.mechanism,
        spectrum=spectrum_of(seismic.spectrum),
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
        ida=IdaSettings(
            analysis.ida.step_ratio, analysis.ida.tolerance, analysis.ida.max_multiplier
        ),
        target=analysis.target,
        costs=Costs(str(project.costs.currency), project.costs.installation_per_metre),
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
    )


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
    loaded = load_project(path)
    _, problems = read_record_files(loaded.project, loaded.base_dir)
    raise_all(problems)  # before any output folder is made: a bad record writes nothing
    if warn is not None:
        for line in loaded.warnings:
            warn(line)
    return inputs_from_project(loaded.project, loaded.base_dir, str(loaded.path.name))


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
