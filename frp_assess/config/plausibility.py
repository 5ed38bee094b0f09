"""Legal but implausible values of a project file: warnings, not errors.

The schema (:mod:`frp_assess.config.schema`) refuses what the model cannot compute; a value
inside that range but outside the range of practice — a wall 32 m high, a ratio of
0.0015 ‰ — usually is a typing or units mistake, yet it runs silently.
:func:`project_warnings` returns one :class:`PlausibilityWarning` per such value (the model of
:mod:`frp_assess.motions.pga_plausibility` for record units).  ``validate`` and ``run`` print each
once as ``frp-assess: warning: file:line: key: message``; ``run`` also stores them, as
``key: message``, in results.json's ``input_warnings`` and the report lists them.  Pure: it
only reads the project.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass

from frp_assess.config.messages import Loc, format_path, line_of
from frp_assess.config.schema import (
    Ec8Spectrum,
    Intervention,
    Ntc2018Spectrum,
    Project,
    TieOption,
)
from frp_assess.errors import InputError


@dataclass(frozen=True)
class Practice:
    """The range of practice of one key: [low, high] in ``unit``, and why."""

    low: float
    high: float
    unit: str
    reason: str


#: ranges of practice (the ranges the model accepts are wider: see the schema)
WALL_THICKNESS = Practice(0.1, 1.5, "m", "masonry walls are 0.1-1.5 m thick")
WALL_HEIGHT = Practice(1.0, 15.0, "m", "a wall panel between restraints is 1-15 m high")
WALL_LENGTH = Practice(0.5, 100.0, "m", "a wall is 0.5-100 m long")
UNIT_WEIGHT = Practice(11.0, 24.0, "kN/m3", "Circolare 2019 Tab. C8.5.I gives 12-22 kN/m3")
COMPRESSIVE_STRENGTH = Practice(
    0.5, 15.0, "MPa", "Circolare 2019 Tab. C8.5.I gives f_m of 1-10 MPa"
)
AG = Practice(0.01, 0.6, "g", "NTC 2018's grid gives a_g of about 0.02-0.5 g")
F0 = Practice(2.0, 3.0, "", "NTC 2018's grid gives F0 of 2.2-2.9")
TC_STAR = Practice(0.1, 0.7, "s", "NTC 2018's grid gives T_C* of 0.15-0.6 s")
T1 = Practice(0.1, 4.0, "s", "the compatibility checks span 0.2*T1-2*T1")
RATIO = Practice(0.1, 10.0, "‰", "vertical FRP bars are designed at 0.5-5 ‰")
ELASTIC_MODULUS = Practice(20.0, 300.0, "GPa", "FRP bars have E of 30-250 GPa")
STRAIN = Practice(0.003, 0.05, "", "FRP bars break at 0.005-0.035")
DENSITY = Practice(1200.0, 2800.0, "kg/m3", "FRP bars weigh 1400-2600 kg/m3")
MIN_SPACING = Practice(0.05, 2.0, "m", "bars are drilled 0.1-1 m apart")
MAX_SPACING = Practice(0.1, 3.0, "m", "bars are drilled 0.1-1 m apart")
STRAIN_FACTOR = Practice(0.3, 1.0, "", "the cyclic reduction c is 0.5-1")
BUILDING_PERIOD = Practice(0.05, 2.0, "s", "masonry buildings have T1 of 0.1-1 s")
STOREY_HEIGHT = Practice(2.5, 6.0, "m", "a storey is 2.5-6 m high")


@dataclass(frozen=True)
class PlausibilityWarning:
    """One implausible value: where it is and what is unusual about it."""

    loc: Loc
    message: str

    @property
    def key(self) -> str:
        """The dotted key path, e.g. ``interventions[0].ratio``."""
        return format_path(self.loc)

    def text(self) -> str:
        """``key: message`` (the form stored in results.json)."""
        return f"{self.key}: {self.message}"

    def located(self, file: str, lines: Mapping[Loc, int]) -> str:
        """``file:line: key: message`` (the form printed on the console)."""
        return str(InputError(self.message, file=file, line=line_of(lines, self.loc), key=self.key))


def _fmt(value: float, unit: str) -> str:
    return f"{value:g} {unit}".rstrip()


def _check(value: float | None, practice: Practice, loc: Loc) -> Iterator[PlausibilityWarning]:
    if value is None or practice.low <= value <= practice.high:
        return
    side = "below" if value < practice.low else "above"
    yield PlausibilityWarning(
        loc,
        f"{_fmt(value, practice.unit)} is {side} the range of practice "
        f"{practice.low:g}-{_fmt(practice.high, practice.unit)} ({practice.reason}); check the "
        "value and its units",
    )


def _values(project: Project) -> Iterator[tuple[float | None, Practice, Loc]]:
    """Every checked value with its range of practice and location, in file order."""
    w = project.wall
    yield w.thickness, WALL_THICKNESS, ("wall", "thickness")
    yield w.height, WALL_HEIGHT, ("wall", "height")
    yield w.length, WALL_LENGTH, ("wall", "length")
    yield w.unit_weight, UNIT_WEIGHT, ("wall", "unit_weight")
    yield w.compressive_strength, COMPRESSIVE_STRENGTH, ("wall", "compressive_strength")
    b = project.building
    if b is not None:
        yield b.height / b.storeys, STOREY_HEIGHT, ("building", "height")
        yield b.period, BUILDING_PERIOD, ("building", "period")
    spectrum = project.seismic.spectrum
    if isinstance(spectrum, Ntc2018Spectrum | Ec8Spectrum):
        yield spectrum.ag, AG, ("seismic", "spectrum", "ag")
    if isinstance(spectrum, Ntc2018Spectrum):
        yield spectrum.F0, F0, ("seismic", "spectrum", "F0")
        yield spectrum.Tc_star, TC_STAR, ("seismic", "spectrum", "Tc_star")
    yield project.seismic.t1, T1, ("seismic", "t1")
    for name, m in project.materials.items():
        loc: Loc = ("materials", name)
        yield m.elastic_modulus, ELASTIC_MODULUS, (*loc, "elastic_modulus")
        yield m.ultimate_strain, STRAIN, (*loc, "ultimate_strain")
        yield m.density, DENSITY, (*loc, "density")
        yield m.characteristic_strain, STRAIN, (*loc, "characteristic_strain")
    for i, item in enumerate(project.interventions):
        if isinstance(item, Intervention):
            yield item.ratio, RATIO, ("interventions", i, "ratio")
        elif not isinstance(item, TieOption):
            for j, ratio in enumerate(item.sweep.ratio):
                yield ratio, RATIO, ("interventions", i, "sweep", "ratio", j)
    if project.design is not None:
        for j, ratio in enumerate(project.design.ratio_range):
            yield ratio, RATIO, ("design", "ratio_range", j)
    yield project.analysis.strain_factor, STRAIN_FACTOR, ("analysis", "strain_factor")
    yield project.bars.min_spacing, MIN_SPACING, ("bars", "min_spacing")
    yield project.bars.max_spacing, MAX_SPACING, ("bars", "max_spacing")


def project_warnings(project: Project) -> tuple[PlausibilityWarning, ...]:
    """One :class:`PlausibilityWarning` per value of ``project`` outside its range of practice,
    and one for a site near Italy's land border (the site module's warning)."""
    found = [
        warning
        for value, practice, loc in _values(project)
        for warning in _check(value, practice, loc)
    ]
    spectrum = project.seismic.spectrum
    hazard = spectrum.site_hazard() if isinstance(spectrum, Ntc2018Spectrum) else None
    if hazard is not None and hazard.border_warning:
        found.append(PlausibilityWarning(("seismic", "spectrum", "site"), hazard.border_warning))
    return tuple(found)
