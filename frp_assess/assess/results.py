"""The results of an assessment as the plain dict of docs/results-json.md, and its files."""

from __future__ import annotations

import csv
import io
import json
import math
from typing import Any

import numpy as np

from frp_assess import __version__
from frp_assess.assess.code_check import KinematicCheck
from frp_assess.assess.inputs import (
    UNREINFORCED,
    ArtificialRecords,
    AssessmentInputs,
    Material,
    Option,
)
from frp_assess.assess.quantities import quantity_for
from frp_assess.assess.ranking import RANKING_RULE, Rankable, rank_options
from frp_assess.assess.runner import CaseSummary, DesignResult, design_value_rule
from frp_assess.assess.seismic import SeismicInput
from frp_assess.assess.statistics import fit_lognormal_fragility, record_statistics
from frp_assess.assess.verification import NumericalCheck
from frp_assess.dynamics import RockingModel
from frp_assess.motions import G
from frp_assess.numbers import no_retrofit_caveats

SCHEMA_VERSION = 1
#: most points stored per time history in results.json
MAX_HISTORY_POINTS = 2500


def _finite(x: float | None) -> float | None:
    return None if x is None or not math.isfinite(x) else float(x)


def material_dict(m: Material) -> dict[str, Any]:
    return {
        "elastic_modulus": m.elastic_modulus,
        "ultimate_strain": m.ultimate_strain,
        "density": m.density,
        "price": m.price,
        "source": m.source,
    }


def wall_dict(inputs: AssessmentInputs) -> dict[str, Any]:
    w = inputs.wall
    return {
        "thickness": inputs.thickness,
        "height": inputs.height,
        "length": inputs.length,
        "masonry": inputs.masonry,
        "masonry_description": inputs.masonry_description,
        "unit_weight": inputs.unit_weight,
        "mechanism": inputs.mechanism,
        "alpha": w.alpha,
        "alpha_deg": math.degrees(w.alpha),
        "R": w.R,
        "p": w.p,
        "mass": w.mass,
        "a_rm": w.a_rm_g,
    }


def scatter_dict(summary: CaseSummary, names: list[str], demand: float) -> dict[str, Any]:
    """How far the case's number can be trusted: record-to-record statistics of a_dyn [g]
    (records without collapse at their C_max lower bound) and a lognormal fragility fitted
    to the collapse accelerations (those records right-censored), with P(collapse) at the
    demand a_g·S."""
    collapsed = [a is not None for a in summary.a_dyn]
    st = record_statistics(summary.a_dyn_bound, collapsed)
    fragility = None
    exact = [a for a in summary.a_dyn if a is not None]
    if len(set(exact)) >= 2:
        censored = [b for a, b in zip(summary.a_dyn, summary.a_dyn_bound, strict=True) if a is None]
        fit = fit_lognormal_fragility(exact, censored)
        fragility = {
            "median": fit.median,
            "beta": fit.beta,
            "method": fit.method,
            "p_collapse_at_demand": fit.probability(demand),
        }
    return {
        "median_a_dyn": st.median,
        "std_a_dyn": st.std,
        "cov": st.cov,
        "least_favourable_record": names[st.least_favourable_index],
        "records_without_collapse": st.censored,
        "fragility": fragility,
    }


def case_dict(
    inputs: AssessmentInputs,
    option: Option | None,
    model: RockingModel,
    summary: CaseSummary,
    names: list[str],
    demand: float,
    urm_design: float,
) -> dict[str, Any]:
    records = []
    for name, res, a in zip(names, summary.results, summary.a_dyn, strict=True):
        records.append(
            {
                "record": name,
                "pga": res.pga / G,
                "collapse_multiplier": res.collapse_multiplier,
                "survivor_multiplier": res.survivor_multiplier,
                "a_dyn": a,
                "q": res.q,
                # every time history of the search, by C: [C, collapsed, peak θ/α]
                "curve": [[p.multiplier, p.collapsed, p.peak_ratio] for p in res.curve],
            }
        )
    if option is None:
        q_mass = q_mass_m = cost = 0.0
    else:
        q = quantity_for(inputs, option.material, option.position, option.ratio)
        q_mass, q_mass_m, cost = q.mass, q.mass_per_m, q.cost
    cd = summary.design_a_dyn / demand
    return {
        "name": option.name if option else UNREINFORCED,
        "material": option.material.name if option else None,
        "position": option.position if option else None,
        "ratio": option.ratio if option else 0.0,
        "elastic_modulus": option.material.elastic_modulus if option else None,
        "ultimate_strain": option.material.ultimate_strain if option else None,
        "K": model.K,
        "theta_max": _finite(model.theta_max) if option else None,
        "records": records,
        "mean_a_dyn": summary.mean_a_dyn,
        "min_a_dyn": summary.min_a_dyn,
        "mean_q": summary.mean_q,
        "design_a_dyn": summary.design_a_dyn,
        "lower_bound": summary.lower_bound,
        "capacity_demand": cd,
        "improvement": summary.design_a_dyn / urm_design,
        "scatter": scatter_dict(summary, names, demand),
        "frp_mass_per_m": q_mass_m,
        "frp_mass": q_mass,
        "frp_cost": cost,
        "meets_target": cd >= inputs.target,
        "rank": None,
    }


def rank_cases(cases: list[dict[str, Any]], target: float) -> str | None:
    """Fill ``rank`` of every option (not the unreinforced wall); return the rank-1 name."""
    items = [
        Rankable(i, c["capacity_demand"], c["frp_cost"], c["frp_mass"])
        for i, c in enumerate(cases)
        if i > 0
    ]
    order = rank_options(items, target)
    for rank, idx in enumerate(order, start=1):
        cases[idx]["rank"] = rank
    return cases[order[0]]["name"] if order and cases[order[0]]["meets_target"] else None


def below_collapse(collapse: float, survivor: float | None, tolerance: float) -> float:
    """The multiplier of the "just below collapse" time history.

    It is the largest multiplier the IDA ran without collapse (its bracket's C_lo), so the
    history shown surely survives; within ``tolerance`` of ``collapse``.  When the IDA's first
    try, C₀ (the onset of rocking), already collapsed there is none: C₀·(1 − tolerance) is
    used, below which the wall does not rock at all.
    """
    return survivor if survivor is not None else collapse * (1.0 - tolerance)


#: said in place of "recommended" when the record set fails the code's compatibility checks
NOT_COMPLIANT = "input not code-compliant"


def recommendation_label(results: dict[str, Any]) -> str:
    """The label of the rank-1 option: "Recommended", or "Best ranked (input not
    code-compliant)" when the record set fails the code's spectrum-compatibility checks."""
    if results.get("input_code_compliant", True):
        return "Recommended"
    return f"Best ranked ({NOT_COMPLIANT})"


def recommendation_text(results: dict[str, Any]) -> str:
    """One line saying what to do: the recommended option, or that no retrofit is needed.

    ``recommended`` is the cheapest option meeting the target even when the unreinforced wall
    already meets it; this says so instead of presenting that option as required.
    """
    rec = results.get("recommended")
    if results["cases"][0]["meets_target"]:
        text = "no retrofit needed: the unreinforced wall already meets the target"
        caveats = no_retrofit_caveats(results)
        if caveats:
            text += " (but " + "; ".join(caveats) + ")"
        return text + (f" (cheapest option for extra margin: {rec})" if rec else "")
    return rec or "none of the options meets the target"


def seismic_dict(inputs: AssessmentInputs, seismic: SeismicInput) -> dict[str, Any]:
    sp = inputs.spectrum
    rep = seismic.compliance
    gen = None
    if isinstance(inputs.records, ArtificialRecords):
        a = inputs.records
        gen = {
            "method": "SIMQKE",
            "count": a.count,
            "seed": a.seed,
            "duration": a.duration,
            "dt": a.dt,
        }
    return {
        "spectrum": {
            "type": sp.kind,
            "name": sp.name,
            "description": sp.description,
            "parameters": _jsonable(sp.parameters),
            "ag_S": sp.pga_g,
            "T_B": sp.T_B,
            "T_C": sp.T_C,
            "T_D": sp.T_D,
        },
        "t1": inputs.t1,
        "records_kind": "recorded" if seismic.recorded else "artificial",
        "generator": gen,
        "scale_factor": seismic.scale_factor,
        "periods": rep.periods.tolist(),
        "target_sa": rep.target.tolist(),
        "mean_sa": rep.mean.tolist(),
    }


def compliance_dict(seismic: SeismicInput) -> dict[str, Any]:
    rep = seismic.compliance
    return {
        "passed": rep.passed,
        "checks": [
            {
                "code": c.code,
                "clause": c.clause,
                "requirement": c.requirement,
                "found": c.found,
                "passed": c.passed,
                "margin": c.margin,
                "unit": c.unit,
            }
            for c in rep.checks
        ],
    }


def code_check_dict(check: KinematicCheck, mass: float) -> dict[str, Any]:
    return {
        "alpha0": check.alpha0,
        "e_star": check.e_star,
        "M_star": mass,
        "FC": check.fc,
        "confidence_factor_level": check.knowledge_level,
        "behaviour_factor": check.behaviour_factor,
        "a0_star": check.a0_star,
        "demand": check.demand,
        "ratio": check.ratio,
        "passed": check.passed,
        "note": "Passive unbonded bars carry no load at rest: they do not change alpha0, "
        "so this check is the same for every retrofit option.",
    }


def design_dicts(inputs: AssessmentInputs, found: list[DesignResult]) -> list[dict[str, Any]]:
    out = []
    for d in found:
        q = quantity_for(inputs, d.material, d.position, d.ratio) if d.ratio is not None else None
        out.append(
            {
                "material": d.material.name,
                "position": d.position,
                "ratio": d.ratio,
                "capacity_demand": d.capacity_demand,
                "frp_mass": None if q is None else q.mass,
                "frp_cost": None if q is None else q.cost,
                "message": d.message,
            }
        )
    return out


def history_dict(label: str, multiplier: float, res: Any, alpha: float) -> dict[str, Any]:
    h = res.history
    n = h.computed
    step = max(1, math.ceil(n / MAX_HISTORY_POINTS))
    sl = slice(0, n, step)
    return {
        "label": label,
        "multiplier": multiplier,
        "collapsed": res.collapsed,
        "fate": res.fate,
        "decided_time": res.decided_time,
        "peak_rotation_ratio": res.max_rotation_ratio,
        "peak_strain": res.peak_strain,
        "ruptures": [{"time": r.time, "side": r.side} for r in res.ruptures],
        "impacts": res.impacts,
        "time": np.round(h.time[sl], 6).tolist(),
        "theta_over_alpha": np.round(h.theta[sl] / alpha, 8).tolist(),
        "strain": np.round(h.strain[sl], 10).tolist(),
    }


def build_results(
    *,
    inputs: AssessmentInputs,
    seismic: SeismicInput,
    cases: list[dict[str, Any]],
    recommended: str | None,
    check: KinematicCheck,
    design: list[DesignResult] | None,
    governing: dict[str, Any] | None,
    materials: dict[str, Material],
    created: str,
    numerical_check: NumericalCheck | None = None,
    sensitivity: dict[str, Any] | None = None,
) -> dict[str, Any]:
    records = [
        {
            "name": r.name,
            "source": r.source,
            "pga": r.pga_g,
            "duration": r.duration,
            "dt": r.dt,
            "scale_factor": seismic.scale_factor,
            "sa": sa.tolist(),
        }
        for r, sa in zip(seismic.records, seismic.compliance.spectra, strict=True)
    ]
    m = inputs.model
    from frp_assess.dynamics import velocity_ratio

    return {
        "schema_version": SCHEMA_VERSION,
        "software": {"name": "frp-assess", "version": __version__},
        "created": created,
        "input_file": inputs.input_file,
        "project": dict(inputs.project),
        "wall": wall_dict(inputs),
        "model": {
            "restitution": m.restitution,
            "restitution_ratio": velocity_ratio(m.restitution, inputs.mechanism, inputs.wall.alpha),
            "rupture": m.rupture,
            "collapse": m.collapse,
            "strain_factor": inputs.strain_factor,
            "free_vibration_tail": m.free_vibration_tail,
            "integration": {
                "method": "Dormand-Prince 5(4), local error control",
                "tolerance": m.tolerance,
                "verify": inputs.verify,
            },
            "ida": {
                "step_ratio": inputs.ida.step_ratio,
                "tolerance": inputs.ida.tolerance,
                "max_multiplier": inputs.ida.max_multiplier,
            },
            "target": inputs.target,
            "design_value": design_value_rule(len(seismic.records)),
        },
        "materials": {k: material_dict(v) for k, v in materials.items()},
        "costs": {
            "currency": inputs.costs.currency,
            "installation_per_metre": inputs.costs.installation_per_metre,
        },
        "seismic": seismic_dict(inputs, seismic),
        "demand": {"pga": inputs.spectrum.pga_g},
        "records": records,
        "compliance": compliance_dict(seismic),
        "code_check": code_check_dict(check, inputs.wall.mass),
        "cases": cases,
        "ranking_rule": RANKING_RULE.format(target=inputs.target),
        "recommended": recommended,
        "retrofit_required": not cases[0]["meets_target"],
        "design": None if design is None else design_dicts(inputs, design),
        "governing": governing,
        "numerical_check": None
        if numerical_check is None
        else numerical_check_dict(numerical_check, cases, seismic),
        "input_warnings": list(seismic.warnings),
        # false: the records fail the code's spectrum-compatibility checks; the CLI, TUI and
        # report then call the rank-1 option "best ranked", never "recommended"
        "input_code_compliant": bool(seismic.compliance.passed),
        "sensitivity": sensitivity,
    }


def numerical_check_dict(
    check: NumericalCheck, cases: list[dict[str, Any]], seismic: SeismicInput
) -> dict[str, Any]:
    """The verification run of docs/model.md §4.5 (`analysis.integration.verify`)."""
    return {
        "tolerance": check.tolerance,
        "check_tolerance": check.check_tolerance,
        "max_change": None if math.isinf(check.max_change) else check.max_change,
        "fate_changed": math.isinf(check.max_change),
        "case": cases[check.case]["name"],
        "record": seismic.records[check.record].name,
        "changed_pairs": check.changed,
        "pairs": check.pairs,
    }


def _jsonable(obj: Any) -> Any:
    return json.loads(
        json.dumps(obj, default=lambda o: o.tolist() if hasattr(o, "tolist") else str(o))
    )


def results_json(results: dict[str, Any]) -> str:
    return json.dumps(results, indent=1, ensure_ascii=False, allow_nan=False) + "\n"


#: results.csv columns: each names its statistic and its unit (g: acceleration in g)
CSV_FIELDS = [
    "case",
    "material",
    "position",
    "ratio_permille",
    "record",
    "record_pga_g",
    "record_collapse_multiplier",
    "record_a_dyn_g",
    "record_q",
    "case_mean_a_dyn_g",
    "case_least_favourable_a_dyn_g",
    "case_design_a_dyn_g",
    "case_capacity_demand_design",
    "case_improvement_design",
    "case_frp_mass_kg",
    "case_frp_cost",
    "case_meets_target",
    "case_rank",
]


def results_csv(results: dict[str, Any]) -> str:
    """One row per (case, record); accelerations in g, mass kg, cost in the currency.

    ``record_*`` columns belong to the row's record, ``case_*`` ones to the whole case (the
    same on every row of the case): mean and least favourable over the records, and the
    design value (the mean with 7 or more records, else the least favourable) that the
    capacity/demand ratio and the improvement use.
    """
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_FIELDS)
    for c in results["cases"]:
        for r in c["records"]:
            w.writerow(
                [
                    c["name"],
                    c["material"] or "",
                    c["position"] or "",
                    c["ratio"],
                    r["record"],
                    f"{r['pga']:.6g}",
                    "" if r["collapse_multiplier"] is None else f"{r['collapse_multiplier']:.6g}",
                    "" if r["a_dyn"] is None else f"{r['a_dyn']:.6g}",
                    "" if r["q"] is None else f"{r['q']:.6g}",
                    f"{c['mean_a_dyn']:.6g}",
                    f"{c['min_a_dyn']:.6g}",
                    f"{c['design_a_dyn']:.6g}",
                    f"{c['capacity_demand']:.6g}",
                    f"{c['improvement']:.6g}",
                    f"{c['frp_mass']:.6g}",
                    f"{c['frp_cost']:.6g}",
                    c["meets_target"],
                    "" if c["rank"] is None else c["rank"],
                ]
            )
    return buf.getvalue()


def spectra_csv(results: dict[str, Any]) -> str:
    s = results["seismic"]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(
        ["period_s", "target_sa_g", "mean_sa_g"] + [f"{r['name']}_sa_g" for r in results["records"]]
    )
    for i, T in enumerate(s["periods"]):
        w.writerow(
            [f"{T:.6g}", f"{s['target_sa'][i]:.6g}", f"{s['mean_sa'][i]:.6g}"]
            + [f"{r['sa'][i]:.6g}" for r in results["records"]]
        )
    return buf.getvalue()
