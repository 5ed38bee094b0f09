"""Table contents as pure functions of the typed results (docs/results-json.md).

Every function returns plain text (not markup): :mod:`frp_assess.report.flow` escapes it for
the PDF (:func:`frp_assess.text_safety.pdf`).  Header cells with sub/superscripts or line
breaks are :class:`~frp_assess.text_safety.Markup` written here; any user text inside them
(the currency) is escaped by :func:`head` first.
Number formats, used everywhere in the report:

- accelerations in g: 3 decimals (:func:`fmt_acc`);
- ratios (capacity/demand, improvement): 2 decimals (:func:`fmt_ratio`), q too (:func:`fmt_q`);
- IDA multipliers: 3 decimals; masses: 1 decimal (kg); costs: 0 decimals with thousands commas.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from frp_assess.numbers import fmt_against
from frp_assess.results.model import AssessmentResult, CaseResult, HistoryRun
from frp_assess.text_safety import Markup, pdf

Results = AssessmentResult
DASH = "—"
NO_COLLAPSE = "no collapse ≤ C_max"


@dataclass(frozen=True)
class TableData:
    """Header (plain text or :class:`Markup`) and body rows (plain text)."""

    header: list[str]
    rows: list[list[str]]


def head(template: str, **user: object) -> Markup:
    """A header cell of constant markup ``template`` with user values (escaped) filled in."""
    return Markup(template.format(**{k: pdf(v) for k, v in user.items()}))


# --- number formats -----------------------------------------------------------------------


def fmt_acc(x: float | None) -> str:
    return DASH if x is None else f"{x:.3f}"


def fmt_ratio(x: float | None) -> str:
    return DASH if x is None else f"{x:.2f}"


fmt_q = fmt_ratio


def fmt_capacity(case: CaseResult, target: float) -> str:
    """capacity/demand of a case with enough decimals to agree with its verdict against
    ``target`` (0.997 → '0.997', not '1.00', when it does not meet 1)."""
    return fmt_against(case.capacity_demand, target, case.meets_target)


def fmt_mult(x: float | None) -> str:
    return NO_COLLAPSE if x is None else f"{x:.3f}"


def fmt_mass(x: float | None) -> str:
    return DASH if x is None else f"{x:.1f}"


def fmt_cost(x: float | None) -> str:
    return DASH if x is None else f"{x:,.0f}"


def fmt_permille(x: float | None) -> str:
    """ρ in ‰: at most 2 decimals, trailing zeros dropped (2 → '2', 1.579 → '1.58')."""
    if x is None:
        return DASH
    return f"{x:.2f}".rstrip("0").rstrip(".")


def fmt_num(x: Any, digits: int = 3) -> str:
    """Generic value: numbers to ``digits`` significant figures, others as text."""
    if x is None:
        return DASH
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    return str(x)


def yes_no(x: bool | None) -> str:
    return DASH if x is None else ("yes" if x else "no")


def pass_fail(x: bool | None) -> str:
    return DASH if x is None else ("pass" if x else "FAIL")


# --- helpers on the results ---------------------------------------------------------------


def ranked_options(results: Results) -> list[CaseResult]:
    """Retrofit options by rank (1 first); unranked options last, in file order."""
    opts = [c for c in results.cases if c.material is not None]
    return sorted(opts, key=lambda c: (c.rank is None, c.rank or 0))


def a_dyn_label(results: Results) -> str:
    """Header markup of the design a_dyn column."""
    return Markup(
        "mean a<sub>dyn</sub> [g]" if results.design_is_mean else "min a<sub>dyn</sub> [g]"
    )


def bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower and text != DASH else text


def case_by_name(results: Results, name: str | None) -> CaseResult | None:
    for c in results.cases:
        if c.name == name:
            return c
    return None


def position_text(pos: str | None) -> str:
    return DASH if pos is None else pos


# --- the tables ---------------------------------------------------------------------------

RANKING_HEADER = [
    "rank",
    "option",
    "mate-<br/>rial",
    "position",
    "ρ [‰]",
    "FRP<br/>[kg/m]",
    "FRP wall<br/>[kg]",
    "cost<br/>[{cur}]",
    "{a_dyn}",
    "mean q",
    "improve-<br/>ment",
    "capacity /<br/>demand",
    "meets<br/>target",
]


def rank_text(case: CaseResult) -> str:
    """The rank, "dropped" for an option the pivot check dropped, else a dash."""
    if case.rank is not None:
        return str(case.rank)
    dropped = case.pivot is not None and case.pivot.dropped and not case.is_unreinforced
    return "dropped" if dropped else DASH


def ranking_row(case: CaseResult, target: float) -> list[str]:
    lb = case.lower_bound
    return [
        rank_text(case),
        case.name,
        case.material or "none",
        position_text(case.position),
        fmt_permille(case.ratio),
        fmt_mass(case.frp_mass_per_m),
        fmt_mass(case.frp_mass),
        fmt_cost(case.frp_cost),
        bound(fmt_acc(case.design_a_dyn), lb),
        bound(fmt_q(case.mean_q), lb),
        bound(fmt_ratio(case.improvement), lb),
        bound(fmt_capacity(case, target), lb),
        yes_no(case.meets_target),
    ]


def ranking_table(results: Results) -> TableData:
    """Unreinforced wall first, then every option by rank."""
    cur = results.costs.currency
    header: list[str] = [
        a_dyn_label(results) if h == "{a_dyn}" else head(h, cur=cur) for h in RANKING_HEADER
    ]
    target = float(results.model.target)
    cases = [results.urm, *ranked_options(results)]
    rows = [ranking_row(c, target) for c in cases]
    return TableData(header, rows)


def _probability(p: float | None) -> str:
    if p is None:
        return DASH
    return "< 0.1%" if p < 1e-3 else f"{p:.1%}"


def sensitivity_table(results: Results) -> TableData | None:
    """The assessed case under every model-convention variant, or None when not recorded."""
    sens = results.sensitivity
    if not sens or not sens.rows:
        return None
    base = sens.rows[0].design_a_dyn
    header = ["variant", a_dyn_label(results), "change [%]", "capacity/demand [–]"]
    rows = []
    for r in sens.rows:
        ge = "≥ " if r.lower_bound else ""
        rows.append(
            [
                r.variant,
                ge + fmt_acc(r.design_a_dyn),
                f"{100.0 * (r.design_a_dyn / base - 1.0):+.1f}",
                ge + f"{r.capacity_demand:.2f}",
            ]
        )
    return TableData(header, rows)


def scatter_table(results: Results) -> TableData:
    """Record-to-record scatter of a_dyn and the lognormal fragility of every case (unreinforced
    first, then by rank); the fragility columns show dashes where no lognormal was fitted."""
    header = [
        "option",
        "mean a_dyn [g]",
        "median [g]",
        "CoV [–]",
        "least favourable [g] (record)",
        "fragility median [g]",
        "β [–]",
        "P(collapse) at a_g·S",
    ]
    rows = []
    for c in [results.urm, *ranked_options(results)]:
        sc = c.scatter
        fr = sc.fragility
        rows.append(
            [
                c.name,
                fmt_acc(c.mean_a_dyn),
                fmt_acc(sc.median_a_dyn),
                f"{sc.cov:.2f}",
                f"{fmt_acc(c.min_a_dyn)} ({sc.least_favourable_record})",
                fmt_acc(None if fr is None else fr.median),
                DASH if fr is None else f"{fr.beta:.2f}",
                _probability(None if fr is None else fr.p_collapse_at_demand),
            ]
        )
    return TableData(header, rows)


def summary_table(results: Results, n_alternatives: int = 3) -> TableData:
    """The unreinforced wall, the recommended option and the best alternatives."""
    cur = results.costs.currency
    header = [
        "",
        "option",
        "FRP wall [kg]",
        f"cost [{cur}]",
        a_dyn_label(results),
        Markup("improve-<br/>ment"),
        Markup("capacity /<br/>demand"),
        Markup("meets<br/>target"),
    ]
    ranked = [c for c in ranked_options(results) if c.rank is not None]  # not the dropped
    chosen: list[tuple[str, CaseResult]] = [("existing", results.urm)]
    rec = case_by_name(results, results.recommended)
    if rec is not None:
        urm_ok = bool(results.urm.meets_target)
        if not results.input_code_compliant:
            label = "best ranked"
        else:
            label = "cheapest (optional)" if urm_ok else "recommended"
        chosen.append((label, rec))
    others = [c for c in ranked if c is not rec][:n_alternatives]
    chosen += [(f"alternative {i}" if rec else f"best {i}", c) for i, c in enumerate(others, 1)]
    rows = []
    for role, c in chosen:
        lb = c.lower_bound
        rows.append(
            [
                role,
                c.name,
                fmt_mass(c.frp_mass),
                fmt_cost(c.frp_cost),
                bound(fmt_acc(c.design_a_dyn), lb),
                bound(fmt_ratio(c.improvement), lb),
                bound(fmt_capacity(c, float(results.model.target)), lb),
                yes_no(c.meets_target),
            ]
        )
    return TableData(header, rows)


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
        ["free-vibration tail", f"{m.free_vibration_tail:g} s"],
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
        ["IDA step ratio s", f"{ida.step_ratio:g}"],
        ["IDA bisection tolerance", f"{ida.tolerance:g} (relative)"],
        ["IDA largest multiplier C_max", f"{ida.max_multiplier:g} × C₀"],
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


def case_records_table(case: CaseResult) -> TableData:
    header = [
        "record",
        "PGA [g]",
        "collapse multiplier C",
        Markup("a<sub>dyn</sub> [g]"),
        "q [–]",
    ]
    rows = [
        [
            r.record,
            fmt_acc(r.pga),
            fmt_mult(r.collapse_multiplier),
            fmt_acc(r.a_dyn),
            fmt_q(r.q),
        ]
        for r in case.records
    ]
    return TableData(header, rows)


def case_summary_rows(results: Results, case: CaseResult) -> list[list[str]]:
    lb = case.lower_bound
    rows = [
        ["mean a_dyn over the records", bound(f"{fmt_acc(case.mean_a_dyn)} g", lb)],
        ["least favourable a_dyn", f"{fmt_acc(case.min_a_dyn)} g"],
        ["mean q = a_dyn / a_RM", bound(fmt_q(case.mean_q), lb)],
        [
            "capacity/demand = a_dyn / (FC·a_g·S)",
            bound(fmt_capacity(case, float(results.model.target)), lb)
            + f" (FC = {case.fc:g}, demand a_g·S = {fmt_acc(results.demand.pga)} g)",
        ],
        [
            f"meets the target (≥ {results.model.target:g})",
            yes_no(case.meets_target),
        ],
    ]
    if case.design_a_dyn is not None and not results.design_is_mean:
        design = f"{fmt_acc(case.design_a_dyn)} g"
        rows.insert(2, ["design a_dyn (fewer than 7 records)", design])
    return rows


def code_check_rows(results: Results) -> list[list[str]]:
    k = results.code_check
    return [
        ["α₀ (load multiplier activating the mechanism)", f"{k.alpha0:.4f}"],
        ["e* (participating mass fraction)", f"{k.e_star:.3f}"],
        ["M* (participating mass)", f"{k.M_star:.1f} kg/m"],
        [
            "confidence factor FC",
            f"{k.FC:g} ({k.confidence_factor_level or DASH})",
        ],
        ["behaviour factor q", f"{k.behaviour_factor:g}"],
        ["a₀* = α₀·g / (e*·FC)", f"{fmt_acc(k.a0_star)} g"],
        ["demand a_Z / q" if results.building else "demand a_g·S / q", f"{fmt_acc(k.demand)} g"],
        ["ratio a₀* / demand", fmt_ratio(k.ratio)],
        ["verdict", "satisfied" if k.passed else "NOT satisfied"],
    ]


def comparison_table(results: Results) -> TableData:
    """The IDA verdict of the unreinforced wall next to the code linear kinematic check."""
    urm = results.urm
    k = results.code_check
    lb = urm.lower_bound
    header = ["assessment", "capacity [g]", "demand [g]", "capacity / demand", "verdict"]
    rows = [
        [
            "IDA, rocking dynamics (this report): a_dyn / FC"
            if urm.fc != 1.0
            else "IDA, rocking dynamics (this report)",
            bound(fmt_acc(urm.design_a_dyn / urm.fc), lb),
            fmt_acc(results.demand.pga),
            bound(fmt_capacity(urm, float(results.model.target)), lb),
            "satisfied" if urm.meets_target else "NOT satisfied",
        ],
        [
            "NTC 2018 / Circ. 2019 §C8.7.1 linear kinematic",
            fmt_acc(k.a0_star),
            fmt_acc(k.demand),
            fmt_ratio(k.ratio),
            "satisfied" if k.passed else "NOT satisfied",
        ],
    ]
    return TableData(header, rows)


def design_table(results: Results) -> TableData:
    cur = results.costs.currency
    header = [
        "material",
        "position",
        "smallest ρ [‰]",
        "capacity / demand",
        "FRP wall [kg]",
        f"cost [{cur}]",
        "note",
    ]
    rows = [
        [
            d.material,
            d.position,
            "none in range" if d.ratio is None else fmt_permille(d.ratio),
            fmt_ratio(d.capacity_demand),
            fmt_mass(d.frp_mass),
            fmt_cost(d.frp_cost),
            d.message or "",
        ]
        for d in results.design or []
    ]
    return TableData(header, rows)


def a_dyn_matrix(results: Results) -> TableData:
    """a_dyn [g] of every case and record, unreinforced wall first then by rank."""
    names = [r.name for r in results.records]
    header = ["option"] + names
    cases: Sequence[CaseResult] = [results.urm] + ranked_options(results)
    rows = []
    for c in cases:
        by_rec = {r.record: r for r in c.records}
        cells = []
        for n in names:
            r = by_rec.get(n)
            if r is None:
                cells.append(DASH)
            else:
                cells.append("n.c." if r.a_dyn is None else fmt_acc(r.a_dyn))
        rows.append([c.name, *cells])
    return TableData(header, rows)


def _fate(run: HistoryRun) -> str:
    """A time history's fate and when it was decided."""
    if run.decided_time is None:
        return run.fate
    return f"{run.fate} ({run.decided_time:.2f} s)"


def governing_runs_table(results: Results) -> TableData:
    header = [
        "run",
        "multiplier C",
        "a = C·PGA [g]",
        "fate (decided at)",
        "peak θ/α [–]",
        "peak ε [‰]",
    ]
    gov = results.governing
    if gov is None:
        return TableData(header, [])
    pga = None
    for r in results.records:
        if r.name == gov.record:
            pga = r.pga
    rows = []
    for run in gov.runs:
        rows.append(
            [
                run.label,
                fmt_mult(run.multiplier),
                DASH if pga is None else fmt_acc(run.multiplier * pga),
                _fate(run),
                f"{run.peak_rotation_ratio:.2f}",
                f"{1e3 * run.peak_strain:.2f}"
                + (f", broke at {run.ruptures[0].time:.2f} s" if run.ruptures else ""),
            ]
        )
    return TableData(header, rows)
