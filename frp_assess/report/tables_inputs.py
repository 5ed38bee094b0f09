"""The tables of the inputs (wall, materials, model settings, software, spectrum, records,
compliance) as pure functions of the typed results; plain text, like
:mod:`frp_assess.report.tables`, whose number formats they use."""

from __future__ import annotations

from frp_assess.report.formats import (
    DASH,
    TableData,
    fmt_acc,
    fmt_cost,
    fmt_num,
    pass_fail,
)
from frp_assess.report.ida_words import settings_value
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup

Results = AssessmentResult


def wall_rows(results: Results) -> list[list[str]]:
    w = results.wall
    return [
        ["thickness B", f"{w.thickness:.3f} m"],
        ["height H", f"{w.height:.3f} m"],
        ["length L", f"{w.length:.3f} m"],
        ["masonry", w.masonry_description or w.masonry or DASH],
        ["unit weight w", f"{w.unit_weight:g} kN/m³"],
        ["mechanism", w.mechanism],
    ]


def wall_property_rows(results: Results) -> list[list[str]]:
    w = results.wall
    return [
        ["slenderness α (tan α = B/H)", f"{w.alpha:.4f} rad = {w.alpha_deg:.2f}°"],
        ["half diagonal R", f"{w.R:.3f} m"],
        ["frequency parameter p", f"{w.p:.3f} rad/s"],
        ["mass per metre m", f"{w.mass:.1f} kg/m"],
        [activation_label(results), f"{fmt_acc(w.a_rm)} g"],
    ]


def crushing_shift(results: Results) -> float | None:
    """x [m] of the unreinforced wall's crushing pivot, None when its model turns about the
    edge (docs/model.md §1.1): results.json ``wall.a_rm`` is about that pivot."""
    piv = results.urm.pivot
    if piv is None or piv.model_pivot != "crushing" or piv.pivot_shift <= 0.0:
        return None
    return piv.depth


def activation_label(results: Results) -> str:
    """The label of a_RM with the formula of the model's pivot: g·tan α about the edge,
    g·(B − x)/H about the crushing pivot (docs/model.md §1.1, §5.1)."""
    x = crushing_shift(results)
    if x is None:
        return "rocking activation a_RM = g·tan α"
    return f"rocking activation a_RM = g·(B − x)/H (crushing pivot, x = {x * 1000:.0f} mm)"


def design_strain(results: Results) -> bool:
    """True when the bars' rupture strain is the design value c·η_a·ε_fk/γ_f (some option
    has bars as built with ``bars.design_values``), False for the mean c·ε_u (docs/model.md
    §2.1)."""
    return any(c.as_built is not None and c.as_built.strain.design_values for c in results.cases)


def rupture_strain_words(results: Results) -> str:
    """ε_max in symbols, as the model used it: c·η_a·ε_fk/γ_f or c·ε_u."""
    return "c·η_a·ε_fk/γ_f" if design_strain(results) else "c·ε_u"


def materials_table(results: Results) -> TableData:
    cur = results.costs.currency
    header = [
        "material",
        "E [GPa]",
        Markup("ε<sub>u</sub> [–]"),
        "density [kg/m³]",
        f"price [{cur}/kg]",
        "source",
    ]
    rows = [
        [
            name,
            f"{m.elastic_modulus:g}",
            f"{m.ultimate_strain:g}",
            f"{m.density:g}",
            f"{m.price:.2f}",
            m.source or DASH,
        ]
        for name, m in sorted(results.materials.items())
    ]
    return TableData(header, rows)


#: the collapse rules in words (docs/model.md §3.5)
COLLAPSE_WORDS = {
    "overturning": "overturning: the wall falls (followed after the record until its fate "
    "is certain)",
    "end-of-record": "end-of-record: |θ| ≥ α when the record ends (the paper's convention)",
    "first-exceedance": "first-exceedance: |θ| reaches α at any time",
}


#: the capacity rules in words (docs/model.md §5, §11)
CAPACITY_WORDS = {
    "effective": "effective collapse intensity",
    "first-collapse": "first collapse (paper's convention)",
}


def model_rows(results: Results) -> list[list[str]]:
    m = results.model
    ida = m.ida
    cur = results.costs.currency
    rows = [
        [
            "restitution at impact",
            f"{m.restitution} (velocity ratio applied {m.restitution_ratio:.3f})",
        ],
        ["rupture rule", m.rupture],
        ["collapse criterion", COLLAPSE_WORDS.get(m.collapse, m.collapse)],
        [
            f"cyclic strain factor c (ε_max = {rupture_strain_words(results)})",
            f"{m.strain_factor:g}",
        ],
        [
            "free-vibration tail",
            f"{m.free_vibration_tail:g} s"
            + (
                " (the overturning rule follows the wall after the record until its fate is "
                "certain, without a fixed tail)"
                if m.collapse == "overturning"
                else ""
            ),
        ],
        ["target capacity/demand", f"≥ {m.target:g}"],
    ]
    integ = m.integration
    if integ:
        rows.append(
            [
                "time integration",
                f"Dormand–Prince 5(4), local error tolerance {integ.tolerance:g}",
            ]
        )
    if m.design_value:
        rows.append(["design value of a_dyn", str(m.design_value)])
    rows += [
        ["IDA capacity of a record", CAPACITY_WORDS.get(ida.capacity, ida.capacity)],
        ["IDA sampling", settings_value(results, Lang("en"))],
        [
            "installation cost",
            f"{fmt_cost(results.costs.installation_per_metre)} {cur} per metre of wall "
            "and layer of bars (indicative)",
        ],
    ]
    return rows


def software_rows(results: Results) -> list[list[str]]:
    p = results.project
    sw = results.software
    return [
        ["project", p.name or DASH],
        ["location", p.location or DASH],
        ["engineer", p.engineer or DASH],
        ["notes", p.notes or DASH],
        ["project file", results.input_file or DASH],
        ["date of the run", results.created or DASH],
        ["software", f"{sw.name} {sw.version}"],
        ["results schema", str(results.schema_version)],
    ]


def spectrum_rows(results: Results) -> list[list[str]]:
    s = results.seismic
    sp = s.spectrum
    params = ", ".join(f"{k} = {fmt_num(v, 4)}" for k, v in (sp.parameters or {}).items())
    rows = [
        ["spectrum", sp.name or sp.type or DASH],
        ["description", sp.description or DASH],
        ["parameters", params or DASH],
        ["zero-period acceleration a_g·S", f"{fmt_acc(sp.ag_S)} g"],
    ]
    corners = [
        f"{k} = {v:.3f} s"
        for k, v in (("T_B", sp.T_B), ("T_C", sp.T_C), ("T_D", sp.T_D))
        if v is not None
    ]
    if corners:
        rows.append(["corner periods", ", ".join(corners)])
    rows.append(["demand a_g·S used for capacity/demand", f"{fmt_acc(results.demand.pga)} g"])
    rows.append(["reference period T1 of the checks", f"{s.t1:g} s"])
    gen = s.generator
    if s.records_kind == "artificial" and gen:
        rows.append(
            [
                "records",
                f"{gen.count} artificial ({gen.method}), seed {gen.seed}, "
                f"duration {gen.duration:g} s, dt {gen.dt:g} s",
            ]
        )
    else:
        rows.append(["records", f"{len(results.records)} recorded accelerograms"])
    return rows


def records_table(results: Results) -> TableData:
    header = ["record", "source / seed", "PGA [g]", "duration [s]", "dt [s]", "scale factor"]
    rows = [
        [
            r.name,
            r.source or DASH,
            fmt_acc(r.pga),
            f"{r.duration:.2f}",
            f"{r.dt:g}",
            f"{r.scale_factor:.3f}",
        ]
        for r in results.records
    ]
    return TableData(header, rows)


def fmt_margin(margin: float | None, unit: str | None) -> str:
    if margin is None:
        return DASH
    if not unit:
        return f"{margin:+.1%}"
    return f"{margin:+g} {unit}"


def compliance_table(results: Results) -> TableData:
    header = ["code", "clause", "requirement", "found", "margin", "result"]
    rows = [
        [
            c.code,
            c.clause,
            c.requirement,
            c.found,
            fmt_margin(c.margin, c.unit),
            pass_fail(c.passed),
        ]
        for c in results.compliance.checks
    ]
    return TableData(header, rows)
