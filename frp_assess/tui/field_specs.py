"""The fields of the editor panes (wall, site spectrum, records, analysis options).

Every input is a :class:`~frp_assess.tui.fields.FieldRow` bound to a key path of the
project file; the help text of each field is the schema's own description (units, range).
The model and IDA options are derived whole from their declaration (``dynamics/options.py``,
see :mod:`~frp_assess.tui.option_fields`).
The panes (``wall_pane``, ``site_pane``, ``records_pane``, ``analysis_pane``) lay them out;
:class:`~frp_assess.tui.project_form.ProjectForm` collects and validates them.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from frp_assess.config.library import MASONRY
from frp_assess.config.schema import (
    CONFIDENCE_FACTORS,
    MIN_ARTIFICIAL_DURATION,
    AnalysisSpec,
    ArtificialRecordsSpec,
    BuildingSpec,
    CodeCheckSpec,
    CostsSpec,
    DesignSpec,
    Ec8Spectrum,
    Ntc2018Spectrum,
    PresetSpectrum,
    ProjectInfoSpec,
    RecordsSpec,
    SeismicSpec,
    SiteCoordinates,
    TableSpectrum,
    WallSpec,
)
from frp_assess.dynamics.options import (
    COLLAPSE,
    FREE_VIBRATION_TAIL,
    IDA_CAPACITY,
    IDA_LADDER_RATIO,
    IDA_MAX_MULTIPLIER,
    IDA_OFFSET,
    IDA_STEP_RATIO,
    IDA_TOLERANCE,
    INTEGRATION_TOLERANCE,
    PIVOT,
    RESTITUTION,
    RUPTURE,
    STRAIN_FACTOR,
    VERIFY,
)
from frp_assess.rules.intervention import CATEGORIES, CATEGORY_CLAUSE
from frp_assess.tui.fields import FieldSpec, choice, field_help, items, num, text
from frp_assess.tui.option_fields import option_field

W = ("wall",)
SP = ("seismic", "spectrum")
REC = ("seismic", "records")
ART = ("seismic", "records", "artificial")
AN = ("analysis",)

MASONRY_CHOICES = tuple((f"{k} ({m.unit_weight:g})", k) for k, m in MASONRY.items())

PROJECT_FIELDS = (
    text(("project", "name"), "Name", ProjectInfoSpec),
    text(("project", "location"), "Location", ProjectInfoSpec),
    text(("project", "engineer"), "Engineer", ProjectInfoSpec),
    text(("project", "notes"), "Notes", ProjectInfoSpec),
)
WALL_FIELDS = (
    num((*W, "thickness"), "Thickness B", "m, 0 < B < H", WallSpec),
    num((*W, "height"), "Height H", "m", WallSpec),
    num((*W, "length"), "Length L", "m", WallSpec, optional=True),
    choice(
        (*W, "masonry"),
        "Masonry",
        MASONRY_CHOICES,
        WallSpec,
        optional=True,
        width=40,
        help="Masonry type of Circolare 2019 Tab. C8.5.I (unit weight kN/m³); "
        "give it or the unit weight.",
    ),
    num(
        (*W, "unit_weight"),
        "Unit weight w",
        "kN/m³, 5-30 (wins)",
        WallSpec,
        optional=True,
        placeholder="(masonry)",
    ),
    num(
        (*W, "compressive_strength"),
        "Strength f_m",
        "MPa (wins)",
        WallSpec,
        optional=True,
        placeholder="(masonry, LC)",
    ),
    choice((*W, "mechanism"), "Mechanism", None, WallSpec, width=14),
)
SPECTRUM_TYPES = (
    ("NTC 2018 (site)", "ntc2018"),
    ("EN 1998-1", "ec8"),
    ("paper preset", "preset"),
    ("table (T, Se)", "table"),
)
#: what a spectrum type starts with when chosen (the template's values)
SPECTRUM_DEFAULTS: dict[str, dict[str, Any]] = {
    "ntc2018": {
        "type": "ntc2018",
        "ag": 0.261,
        "F0": 2.36,
        "Tc_star": 0.347,
        "soil": "B",
        "topography": "T1",
        "damping": 0.05,
    },
    "ec8": {"type": "ec8", "ag": 0.25, "ground": "B", "spectrum_type": 1, "damping": 0.05},
    "preset": {"type": "preset", "name": "A2"},
    "table": {
        "type": "table",
        "periods": [0.0, 0.15, 0.5, 2.0, 4.0],
        "accelerations": [0.3, 0.75, 0.75, 0.19, 0.05],
    },
}


SITE_TYPE = FieldSpec(
    (*SP, "type"),
    "Spectrum",
    "choice",
    choices=SPECTRUM_TYPES,
    width=20,
    selects="spectrum",
    help=field_help(SeismicSpec, "spectrum"),
)


def in_variant(group: str, value: str, *specs: FieldSpec) -> tuple[FieldSpec, ...]:
    """Fields that are part of the data only while variant ``group`` is ``value``."""
    return tuple(replace(f, variant=(group, value)) for f in specs)


BUILDING_MODE = FieldSpec(
    ("building", "mode"),
    "Stands",
    "choice",
    choices=(("at ground level", "off"), ("on a floor (Z)", "on")),
    width=20,
    virtual=True,
    selects="building",
    help="Where the wall stands: at ground level (shaken by the ground) or on a floor of the "
    "building, its base moving with the floor at Z (Circolare 2019 §C7.2.3, first mode).",
)
#: what the building block starts with when switched on: the template's commented values
BUILDING_DEFAULTS: dict[str, Any] = {"height": 10.0, "storeys": 3, "wall_base": 9.0}
BUILDING_FIELDS = in_variant(
    "building",
    "on",
    num(("building", "height"), "Building H_b", "m", BuildingSpec),
    num(("building", "storeys"), "Storeys n", "", BuildingSpec),
    num(("building", "wall_base"), "Wall base Z", "m, 0 ≤ Z < H_b", BuildingSpec),
    num(
        ("building", "period"),
        "Period T1",
        "s",
        BuildingSpec,
        optional=True,
        placeholder="(0.05·H_b^0.75)",
    ),
    num(("building", "damping"), "Damping ξ1", "-", BuildingSpec, optional=True),
)


NTC, EC8 = Ntc2018Spectrum, Ec8Spectrum
#: how the NTC 2018 spectrum is given: by a_g, F0, T_C* or by the site's coordinates
NTC_INPUT = replace(
    FieldSpec(
        (*SP, "given_by"),
        "Given by",
        "choice",
        choices=(("parameters a_g, F0, T_C*", "parameters"), ("site coordinates", "coordinates")),
        width=28,
        virtual=True,
        selects="ntc",
        help="NTC 2018 spectrum from its parameters a_g, F0, T_C*, or from the site's "
        "coordinates (the NTC reference grid, docs/site-hazard.md).",
    ),
    variant=("spectrum", "ntc2018"),
)
#: what the coordinates start with when chosen (L'Aquila, V_N 50, class II, SLV)
NTC_SITE_DEFAULTS: dict[str, Any] = {
    "type": "ntc2018",
    "site": {"latitude": 42.35, "longitude": 13.4},
    "soil": "B",
    "topography": "T1",
}
NTC_FIELDS: dict[str, tuple[FieldSpec, ...]] = {
    "parameters": in_variant(
        "ntc",
        "parameters",
        num((*SP, "ag"), "a_g", "g, on rock", NTC),
        num((*SP, "F0"), "F0", "-", NTC),
        num((*SP, "Tc_star"), "T_C*", "s", NTC),
    ),
    "coordinates": in_variant(
        "ntc",
        "coordinates",
        num((*SP, "site", "latitude"), "Latitude", "°", SiteCoordinates),
        num((*SP, "site", "longitude"), "Longitude", "°", SiteCoordinates),
        num((*SP, "nominal_life"), "Nominal life V_N", "years", NTC, optional=True, default=50),
        choice((*SP, "use_class"), "Use class", None, NTC, width=8, optional=True,
               default="II"),
        choice((*SP, "limit_state"), "Limit state", None, NTC, width=8, optional=True,
               default="SLV"),
    ),
}  # fmt: skip
SITE_FIELDS: dict[str, tuple[FieldSpec, ...]] = {
    "ntc2018": in_variant(
        "spectrum",
        "ntc2018",
        choice((*SP, "soil"), "Soil", None, NTC, width=8),
        choice((*SP, "topography"), "Topography", None, NTC, width=8),
        num((*SP, "damping"), "Damping ξ", "-", NTC, optional=True),
    ),
    "ec8": in_variant(
        "spectrum",
        "ec8",
        num((*SP, "ag"), "a_g", "g, ground A", EC8),
        choice((*SP, "ground"), "Ground", None, EC8, width=8),
        choice((*SP, "spectrum_type"), "Spectrum type", None, EC8, width=8),
        num((*SP, "damping"), "Damping ξ", "-", EC8, optional=True),
    ),
    "preset": in_variant(
        "spectrum", "preset", choice((*SP, "name"), "Preset", None, PresetSpectrum, width=8)
    ),
    "table": in_variant(
        "spectrum",
        "table",
        items((*SP, "periods"), "Periods T", TableSpectrum, unit="s", width=26),
        items((*SP, "accelerations"), "Se(T)", TableSpectrum, unit="g", width=26),
    ),
}
T1_FIELD = num(("seismic", "t1"), "T1 (checks)", "s", SeismicSpec, optional=True)

RECORD_SOURCE = FieldSpec(
    (*REC, "source"),
    "Records",
    "choice",
    choices=(("artificial (SIMQKE)", "artificial"), ("record files", "files")),
    width=22,
    virtual=True,
    selects="records",
    help=field_help(RecordsSpec, "artificial") + " / " + field_help(RecordsSpec, "files"),
)
#: what artificial records start with when chosen: the schema's defaults
ARTIFICIAL_DEFAULTS = ArtificialRecordsSpec.model_validate({}).model_dump(mode="json")
ARTIFICIAL_FIELDS = in_variant(
    "records",
    "artificial",
    num((*ART, "count"), "Count", "records, 1-100", ArtificialRecordsSpec, optional=True),
    num((*ART, "seed"), "Seed", "same seed, same set", ArtificialRecordsSpec, optional=True),
    num(
        (*ART, "duration"),
        "Duration",
        f"s, ≥ {MIN_ARTIFICIAL_DURATION:g}",
        ArtificialRecordsSpec,
        optional=True,
    ),
    num((*ART, "dt"), "Time step dt", "s, ≤ 0.05", ArtificialRecordsSpec, optional=True),
)
SCALE_FIELD = choice(
    (*REC, "scale_to_spectrum"),
    "Scale files",
    (("yes: to a_g·S", True), ("no", False)),
    RecordsSpec,
    width=18,
)

IDA = (*AN, "ida")
INTEGRATION = (*AN, "integration")
#: the declared options (dynamics/options.py), each field derived from its declaration
ANALYSIS_FIELDS = (
    option_field((*AN, "restitution"), "Restitution", RESTITUTION),
    option_field((*AN, "rupture"), "Bar rupture", RUPTURE),
    option_field((*AN, "collapse"), "Collapse", COLLAPSE),
    option_field(
        (*AN, "pivot"),
        "Pivot",
        PIVOT,
        labels={"crushing": "crushing (x/2 in)", "edge": "edge (paper)"},
    ),
    option_field((*AN, "strain_factor"), "Strain factor c", STRAIN_FACTOR),
    option_field((*AN, "free_vibration_tail"), "Free tail", FREE_VIBRATION_TAIL),
    option_field((*INTEGRATION, "tolerance"), "Integration tol.", INTEGRATION_TOLERANCE),
    option_field(
        (*INTEGRATION, "verify"),
        "Numerical check",
        VERIFY,
        labels={False: "off", True: "10x tighter"},
    ),
    option_field((*IDA, "step_ratio"), "IDA step ratio", IDA_STEP_RATIO),
    option_field((*IDA, "tolerance"), "IDA tolerance", IDA_TOLERANCE),
    option_field((*IDA, "max_multiplier"), "IDA max C/C0", IDA_MAX_MULTIPLIER),
    option_field((*IDA, "capacity"), "IDA capacity", IDA_CAPACITY),
    option_field((*IDA, "ladder_ratio"), "IDA ladder ratio", IDA_LADDER_RATIO),
    option_field((*IDA, "offset"), "IDA ladder offset", IDA_OFFSET),
    num((*AN, "target"), "Target C/D", "", AnalysisSpec, optional=True),
)
CODE_FIELDS = (
    choice(
        ("code_check", "knowledge_level"),
        "Knowledge level",
        tuple((f"{lc} (FC {fc:.2f})", lc) for lc, fc in CONFIDENCE_FACTORS.items()),
        CodeCheckSpec,
        width=16,
    ),
    num(("code_check", "behaviour_factor"), "Behaviour q", "1-4", CodeCheckSpec, optional=True),
    choice(
        ("code_check", "fc_in_ida"),
        "FC in the IDA",
        (("yes: a_dyn/(FC·a_g·S)", True), ("no: a_dyn/(a_g·S)", False)),
        CodeCheckSpec,
        width=24,
    ),
    choice(
        ("code_check", "intervention"),
        "Intervention",
        tuple((f"{c} ({CATEGORY_CLAUSE[c].removeprefix('NTC 2018 ')})", c) for c in CATEGORIES),
        CodeCheckSpec,
        width=24,
        optional=True,
    ),
    choice(
        ("code_check", "use_class"), "Use class", None, CodeCheckSpec, width=8, optional=True
    ),  # fmt: skip
    choice(
        ("code_check", "school"),
        "Class III school",
        (("no", False), ("yes", True)),
        CodeCheckSpec,
        width=8,
        optional=True,
    ),
)
COST_FIELDS = (
    text(("costs", "currency"), "Currency", CostsSpec, width=8),
    num(
        ("costs", "installation_per_metre"),
        "Installation",
        "per m per layer",
        CostsSpec,
        optional=True,
    ),
)
DESIGN_MODE = FieldSpec(
    ("design", "mode"),
    "Mode",
    "choice",
    choices=(("off", "off"), ("on: smallest ρ", "on")),
    width=18,
    virtual=True,
    selects="design",
    help="Design mode: the smallest ratio meeting the target per material and position.",
)
#: what design mode starts with when switched on: GFRP, and the schema's defaults
DESIGN_DEFAULTS = DesignSpec.model_validate({"materials": ["GFRP"]}).model_dump(mode="json")
DESIGN_FIELDS = in_variant(
    "design",
    "on",
    items(("design", "materials"), "Materials", DesignSpec, width=22),
    items(("design", "positions"), "Positions", DesignSpec, width=22),
    items(("design", "ratio_range"), "Ratio range", DesignSpec, unit="‰ low, high", width=12),
    num(("design", "resolution"), "Resolution", "‰", DesignSpec, optional=True),
)

#: where a problem whose key path is not a field is shown: key path prefix -> section id
SECTIONS: dict[tuple[str, ...], str] = {
    ("project",): "err-wall",
    ("wall",): "err-wall",
    ("building",): "err-wall",
    ("seismic",): "err-site",
    ("seismic", "spectrum"): "err-site",
    ("seismic", "records"): "err-records",
    ("analysis",): "err-analysis",
    ("code_check",): "err-analysis",
    ("costs",): "err-analysis",
    ("design",): "err-analysis",
}
