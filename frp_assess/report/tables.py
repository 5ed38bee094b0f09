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

from frp_assess.report.formats import (  # re-exported: tables.X for the sections
    DASH as DASH,
)
from frp_assess.report.formats import (
    NO_COLLAPSE as NO_COLLAPSE,
)
from frp_assess.report.formats import (
    TableData as TableData,
)
from frp_assess.report.formats import (
    a_dyn_label as a_dyn_label,
)
from frp_assess.report.formats import (
    bound as bound,
)
from frp_assess.report.formats import (
    case_by_name as case_by_name,
)
from frp_assess.report.formats import (
    fmt_acc as fmt_acc,
)
from frp_assess.report.formats import (
    fmt_capacity as fmt_capacity,
)
from frp_assess.report.formats import (
    fmt_cost as fmt_cost,
)
from frp_assess.report.formats import (
    fmt_mass as fmt_mass,
)
from frp_assess.report.formats import (
    fmt_mult as fmt_mult,
)
from frp_assess.report.formats import (
    fmt_num as fmt_num,
)
from frp_assess.report.formats import (
    fmt_permille as fmt_permille,
)
from frp_assess.report.formats import (
    fmt_q as fmt_q,
)
from frp_assess.report.formats import (
    fmt_ratio as fmt_ratio,
)
from frp_assess.report.formats import (
    head as head,
)
from frp_assess.report.formats import (
    pass_fail as pass_fail,
)
from frp_assess.report.formats import (
    position_text as position_text,
)
from frp_assess.report.formats import (
    ranked_options as ranked_options,
)
from frp_assess.report.formats import (
    yes_no as yes_no,
)
from frp_assess.report.lang import Lang
from frp_assess.report.tables_inputs import (
    COLLAPSE_WORDS as COLLAPSE_WORDS,
)
from frp_assess.report.tables_inputs import (
    activation_label as activation_label,
)
from frp_assess.report.tables_inputs import (
    compliance_table as compliance_table,
)
from frp_assess.report.tables_inputs import (
    crushing_shift as crushing_shift,
)
from frp_assess.report.tables_inputs import (
    design_strain as design_strain,
)
from frp_assess.report.tables_inputs import (
    fmt_margin as fmt_margin,
)
from frp_assess.report.tables_inputs import (
    materials_table as materials_table,
)
from frp_assess.report.tables_inputs import (
    model_rows as model_rows,
)
from frp_assess.report.tables_inputs import (
    records_table as records_table,
)
from frp_assess.report.tables_inputs import (
    rupture_strain_words as rupture_strain_words,
)
from frp_assess.report.tables_inputs import (
    software_rows as software_rows,
)
from frp_assess.report.tables_inputs import (
    spectrum_rows as spectrum_rows,
)
from frp_assess.report.tables_inputs import (
    wall_property_rows as wall_property_rows,
)
from frp_assess.report.tables_inputs import (  # re-exported, as above
    wall_rows as wall_rows,
)
from frp_assess.report.verdict_text import (
    cell,
    governing,
)
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.rules.record_sets import MEAN_OF_RECORDS_FROM
from frp_assess.text_safety import Markup

Results = AssessmentResult
#: the English words of the verdict: the catalogue's, as in the body (report/verdict_text.py)
EN = Lang("en")
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
    "deciding<br/>checks",
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
        case.material or ("tie" if case.tie is not None else "none"),
        position_text(case.position),
        fmt_permille(case.ratio),
        fmt_mass(case.frp_mass_per_m),
        fmt_mass(case.frp_mass),
        fmt_cost(case.option_cost),
        bound(fmt_acc(case.design_a_dyn), lb),
        bound(fmt_q(case.mean_q), lb),
        bound(fmt_ratio(case.improvement), lb),
        bound(fmt_capacity(case, target), lb),
        cell(case, EN),
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
        Markup("deciding<br/>checks"),
    ]
    ranked = [c for c in ranked_options(results) if c.rank is not None]  # not the dropped
    chosen: list[tuple[str, CaseResult]] = [("existing", results.urm)]
    rec = case_by_name(results, results.recommended)
    if rec is not None:
        urm_ok = cell(results.urm, EN) == EN.t("verdict.cell.pass")
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
                fmt_cost(c.option_cost),
                bound(fmt_acc(c.design_a_dyn), lb),
                bound(fmt_ratio(c.improvement), lb),
                bound(fmt_capacity(c, float(results.model.target)), lb),
                cell(c, EN),
            ]
        )
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
        ["deciding checks", f"{cell(case, EN)}: {governing(case, EN)}"],
    ]
    if case.design_a_dyn is not None and not results.design_is_mean:
        design = f"{fmt_acc(case.design_a_dyn)} g"
        rows.insert(2, [f"design a_dyn (fewer than {MEAN_OF_RECORDS_FROM} records)", design])
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
