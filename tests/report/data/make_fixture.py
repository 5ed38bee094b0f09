"""Write ``results.json``: a SYNTHETIC results file for the report's layout tests.

The numbers are plausible (a 0.40 × 3.0 × 6.0 m one-sided solid-brick wall, NTC 2018 site,
7 artificial records, the unreinforced wall and 18 retrofit options) and internally consistent
(q = a_dyn / a_RM, capacity/demand = mean a_dyn / a_g·S, improvement, masses and costs follow
the formulas of the tool), but they are NOT the output of an analysis: nothing here was
integrated. Regenerate with ``PYTHONPATH=. python3 tests/report/data/make_fixture.py`` (from
the repository root); it is written through the typed model (:mod:`frp_assess.results`), and
``tests/report/test_fixture.py`` fails when the committed file and this script (or the model)
disagree.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from frp_assess.results.json_io import from_data, to_json
from frp_assess.results.model import AssessmentResult

G = 9.80665
B, H, L = 0.40, 3.0, 6.0
UNIT_WEIGHT = 18.0
MATERIALS = {
    "GFRP": {
        "elastic_modulus": 46.0,
        "ultimate_strain": 0.015,
        "density": 2000.0,
        "price": 8.0,
        "source": "typical producer data; CNR-DT 203/2006 ranges",
    },
    "BFRP": {
        "elastic_modulus": 50.0,
        "ultimate_strain": 0.020,
        "density": 2000.0,
        "price": 12.0,
        "source": "typical producer data",
    },
    "CFRP": {
        "elastic_modulus": 150.0,
        "ultimate_strain": 0.013,
        "density": 1550.0,
        "price": 35.0,
        "source": "typical producer data",
    },
}
INSTALL = 150.0
#: level of seismic improvement aimed at per (material, position) for ρ = 1, 2, 3 ‰
IMPROVEMENT = {
    ("GFRP", "centred"): (1.35, 1.70, 2.05),
    ("BFRP", "centred"): (1.40, 1.80, 2.20),
    ("CFRP", "centred"): (1.90, 2.80, 3.60),
    ("GFRP", "external"): (2.50, 4.20, 6.00),
    ("BFRP", "external"): (4.00, 5.60, 7.00),
    ("CFRP", "external"): (6.50, 8.20, 9.50),
}
N_REC = 7
MAX_MULT = 100.0


def ntc_spectrum(T: np.ndarray, ag: float, F0: float, tc_star: float) -> tuple:
    ss = min(max(1.40 - 0.40 * F0 * ag, 1.0), 1.2)  # soil B
    cc = 1.10 * tc_star**-0.20
    S = ss * 1.0
    tc = cc * tc_star
    tb = tc / 3
    td = 4.0 * ag + 1.6
    a = ag * S
    se = np.where(
        T < tb,
        a * F0 * (T / tb + (1 - T / tb) / F0),
        np.where(T < tc, a * F0, np.where(T < td, a * F0 * tc / T, a * F0 * tc * td / T**2)),
    )
    return se, a, tb, tc, td


def fixture_text() -> str:
    """The fixture's JSON text, written by :func:`frp_assess.results.json_io.to_json`."""
    rng = np.random.default_rng(20261122)
    alpha = math.atan(B / H)
    R = 0.5 * math.hypot(B, H)
    p = math.sqrt(3 * G / (4 * R))
    mass = UNIT_WEIGHT * 1000 * B * H / G
    a_rm = math.tan(alpha)

    periods = np.round(np.geomspace(0.02, 4.0, 60), 5)
    target, ag_s, tb, tc, td = ntc_spectrum(periods, 0.261, 2.36, 0.347)
    records = []
    sas = []
    for i in range(N_REC):
        wiggle = np.convolve(rng.standard_normal(periods.size + 6), np.ones(7) / 7, "valid")
        sa = target * (1.02 + 0.10 * wiggle)
        sa[0] = ag_s * (1.0 + 0.04 * rng.random())
        sas.append(sa)
        records.append(
            {
                "name": f"art-{i + 1:02d}",
                "source": f"SIMQKE seed 2024 #{i + 1}",
                "pga": float(sa[0]),
                "duration": 25.0,
                "dt": 0.005,
                "scale_factor": 1.0,
                "sa": [round(float(x), 6) for x in sa],
            }
        )
    mean_sa = np.mean(sas, axis=0)
    demand = ag_s
    z = rng.standard_normal(N_REC)
    z = (z - z.mean()) / z.std()
    urm_a = 0.194 * (1 + 0.12 * z)

    def scatter(values: list[float], censored: list[bool]) -> dict:
        """Record statistics and a lognormal fitted to the collapse values (moments of ln)."""
        v = np.asarray(values)
        exact = np.log([x for x, c in zip(values, censored, strict=True) if not c])
        median, beta = float(np.exp(exact.mean())), float(exact.std(ddof=1))
        p = 0.5 * math.erfc(-math.log(demand / median) / (beta * math.sqrt(2)))
        return {
            "median_a_dyn": float(np.median(v)),
            "std_a_dyn": float(v.std(ddof=1)),
            "cov": float(v.std(ddof=1) / v.mean()),
            "least_favourable_record": records[int(np.argmin(v))]["name"],
            "records_without_collapse": sum(censored),
            "fragility": {
                "median": median,
                "beta": beta,
                "method": "censored-mle" if any(censored) else "mle",
                "p_collapse_at_demand": p,
            },
        }

    def case(name, mat, pos, ratio, a_dyn, K, theta_max, nocollapse=()):
        recs = []
        bound = []
        for j, r in enumerate(records):
            if j in nocollapse:
                c0 = a_rm / r["pga"]
                recs.append(
                    {
                        "record": r["name"],
                        "pga": r["pga"],
                        "collapse_multiplier": None,
                        "survivor_multiplier": MAX_MULT * c0,
                        "a_dyn": None,
                        "q": None,
                        "curve": [[c0, False, 0.4], [MAX_MULT * c0, False, 0.9]],
                    }
                )
                bound.append(MAX_MULT * c0 * r["pga"])
            else:
                a = float(a_dyn[j])
                c = a / r["pga"]
                recs.append(
                    {
                        "record": r["name"],
                        "pga": r["pga"],
                        "collapse_multiplier": c,
                        "survivor_multiplier": c / 1.005,
                        "a_dyn": a,
                        "q": a / a_rm,
                        "curve": [[c / 1.005, False, 0.8], [c, True, math.pi / 2 / alpha]],
                    }
                )
                bound.append(a)
        mean = float(np.mean(bound))
        if mat is None:
            m_m = m = cost = 0.0
        else:
            layers = 1 if pos == "centred" else 2
            mt = MATERIALS[mat]
            m_m = ratio * 1e-3 * B * layers * H * mt["density"]
            m = m_m * L
            cost = m * mt["price"] + INSTALL * L * layers
        return {
            "name": name,
            "material": mat,
            "position": pos,
            "ratio": ratio,
            "elastic_modulus": None if mat is None else MATERIALS[mat]["elastic_modulus"],
            "ultimate_strain": None if mat is None else MATERIALS[mat]["ultimate_strain"],
            "K": K,
            "theta_max": theta_max,
            "records": recs,
            "mean_a_dyn": mean,
            "min_a_dyn": float(min(bound)),
            "mean_q": mean / a_rm,
            "design_a_dyn": mean,
            "lower_bound": bool(nocollapse),
            "capacity_demand": mean / demand,
            "improvement": 1.0,
            "scatter": scatter(bound, [j in nocollapse for j in range(len(records))]),
            "frp_mass_per_m": m_m,
            "frp_mass": m,
            "frp_cost": cost,
            "meets_target": mean / demand >= 1.0,
            "rank": None,
        }

    cases = [case("Unreinforced", None, None, 0.0, urm_a, 0.0, None)]
    for pos in ("centred", "external"):
        for mat in ("GFRP", "BFRP", "CFRP"):
            for k, ratio in enumerate((1.0, 2.0, 3.0)):
                E = MATERIALS[mat]["elastic_modulus"] * 1e9
                rp = 1 if pos == "centred" else 4
                A = ratio * 1e-3 * B
                K = math.sin(alpha) * math.tan(alpha) * rp / 2 * E * A / (mass * G)
                br = B / 2 if pos == "centred" else B
                eps = 0.5 * MATERIALS[mat]["ultimate_strain"]
                theta_max = 2 * math.asin(eps * H / (2 * br))
                imp = IMPROVEMENT[(mat, pos)][k]
                a = urm_a * imp * (1 + 0.04 * rng.standard_normal(N_REC))
                noc = (4,) if (mat, pos, ratio) == ("CFRP", "external", 3.0) else ()
                cases.append(case(f"{mat} {pos} {ratio:g}‰", mat, pos, ratio, a, K, theta_max, noc))
    urm_mean = cases[0]["mean_a_dyn"]
    for c in cases:
        c["improvement"] = c["mean_a_dyn"] / urm_mean
    opts = list(range(1, len(cases)))
    meeting = sorted(
        (i for i in opts if cases[i]["meets_target"]),
        key=lambda i: (cases[i]["frp_cost"], cases[i]["frp_mass"], i),
    )
    others = sorted(
        (i for i in opts if not cases[i]["meets_target"]),
        key=lambda i: (-cases[i]["capacity_demand"], cases[i]["frp_cost"], i),
    )
    for rank, i in enumerate(meeting + others, start=1):
        cases[i]["rank"] = rank
    best = cases[(meeting + others)[0]]
    recommended = best["name"] if best["meets_target"] else None

    # governing time history of the recommended option (centred bar: strain = B·sin(θ/2)/H)
    gov_rec = min(best["records"], key=lambda r: r["collapse_multiplier"] or 1e9)
    eps_max = 0.5 * MATERIALS[best["material"]]["ultimate_strain"]
    theta_rup = 2 * math.asin(eps_max * H / B)

    def history(collapse: bool) -> dict:
        dt = 0.01
        t_end = 15.3 if collapse else 25.0
        t = np.arange(0.0, t_end + 1e-9, dt)
        env = np.clip((t - 1.0) / 7.0, 0, 1) * np.clip((22.0 - t) / 6.0, 0, 1)
        th = (0.78 * alpha) * env * np.abs(np.sin(2 * np.pi * 0.85 * t))
        broken = np.zeros_like(t, dtype=bool)
        if collapse:
            th = th * 1.12
            grow = np.clip((t - 9.0) / 5.0, 0, None)
            th = th * (1 + 1.4 * grow**2)
            over = t > 14.6
            th[over] = th[over] + alpha * 40 * (t[over] - 14.6) ** 2
            th = np.minimum(th, math.pi / 2)
            k = int(np.argmax(th >= theta_rup))
            broken[k:] = True
        strain = np.where(broken, 0.0, B * np.sin(th / 2) / H)
        mult = gov_rec["collapse_multiplier"]
        ruptures = [{"time": float(t[k]), "side": 1}] if collapse else []
        return {
            "label": "collapse" if collapse else "just below",
            "multiplier": mult if collapse else mult / 1.005,
            "collapsed": collapse,
            "fate": "fell" if collapse else "at rest",
            "decided_time": float(t[-1]),
            "peak_rotation_ratio": float(np.max(th) / alpha),
            "peak_strain": float(np.max(strain)),
            "ruptures": ruptures,
            "impacts": 31 if collapse else 40,
            "time": [round(float(x), 6) for x in t],
            "theta_over_alpha": [round(float(x), 8) for x in th / alpha],
            "strain": [round(float(x), 10) for x in strain],
        }

    design = []
    for mat, pos in IMPROVEMENT:
        cds = [
            c["capacity_demand"] for c in cases[1:] if c["material"] == mat and c["position"] == pos
        ]
        if cds[0] >= 1.0:  # between the unreinforced wall (ρ = 0) and 1 ‰
            cd0 = cases[0]["capacity_demand"]
            ratio = (1.0 - cd0) / (cds[0] - cd0)
        else:
            ratio = 1.0 + (1.0 - cds[0]) / (cds[1] - cds[0])
        layers = 1 if pos == "centred" else 2
        mt = MATERIALS[mat]
        m = ratio * 1e-3 * B * layers * H * mt["density"] * L
        design.append(
            {
                "material": mat,
                "position": pos,
                "ratio": round(ratio, 3),
                "capacity_demand": 1.004,
                "frp_mass": m,
                "frp_cost": m * mt["price"] + INSTALL * L * layers,
                "message": f"smallest ratio meeting capacity/demand ≥ 1 (to 0.01‰): {ratio:.2f}‰",
            }
        )

    mean_pga = float(np.mean([r["pga"] for r in records]))
    results = {
        "schema_version": 2,
        "software": {"name": "frp-assess", "version": "0.1.0"},
        "created": "2026-11-22",
        "input_file": "facciata-nord.yaml",
        "project": {
            "name": "Facciata nord <via Roma & vicolo Sud> — Βόρεια πρόσοψη",
            "location": "L'Aquila (AQ), Italia",
            "engineer": "Ing. Ana Ćosić & Partners",
            "notes": "Synthetic layout test: a < b & c > d; Северный фасад, 2 floors; "
            "façade wall between transverse walls, no ring beam.",
        },
        "wall": {
            "thickness": B,
            "height": H,
            "length": L,
            "masonry": "solid-brick-lime-mortar",
            "masonry_description": "Solid brick and lime mortar (Circolare 2019 Tab. C8.5.I)",
            "unit_weight": UNIT_WEIGHT,
            "mechanism": "one-sided",
            "alpha": alpha,
            "alpha_deg": math.degrees(alpha),
            "R": R,
            "p": p,
            "mass": mass,
            "a_rm": a_rm,
        },
        "model": {
            "restitution": "energy",
            "restitution_ratio": 0.4502,
            "rupture": "energy-transfer",
            "collapse": "end-of-record",
            "strain_factor": 0.5,
            "free_vibration_tail": 0.0,
            "integration": {
                "method": "Dormand-Prince 5(4), local error control",
                "tolerance": 1e-8,
                "verify": False,
            },
            "ida": {"step_ratio": 1.10, "tolerance": 0.005, "max_multiplier": MAX_MULT},
            "target": 1.0,
            "design_value": "mean of the records",
        },
        "materials": MATERIALS,
        "costs": {"currency": "EUR", "installation_per_metre": INSTALL},
        "seismic": {
            "spectrum": {
                "type": "ntc2018",
                "name": "NTC 2018 SLV, L'Aquila",
                "description": "NTC 2018 §3.2.3.2.1 elastic spectrum, soil B, T1, 5 % damping",
                "parameters": {
                    "ag": 0.261,
                    "F0": 2.36,
                    "Tc_star": 0.347,
                    "soil": "B",
                    "topography": "T1",
                },
                "ag_S": ag_s,
                "T_B": tb,
                "T_C": tc,
                "T_D": td,
            },
            "t1": 1.0,
            "records_kind": "artificial",
            "generator": {
                "method": "SIMQKE",
                "count": N_REC,
                "seed": 2024,
                "duration": 25.0,
                "dt": 0.005,
            },
            "scale_factor": 1.0,
            "periods": [float(x) for x in periods],
            "target_sa": [round(float(x), 6) for x in target],
            "mean_sa": [round(float(x), 6) for x in mean_sa],
        },
        "demand": {"pga": ag_s},
        "records": records,
        "compliance": {
            "passed": True,
            "checks": [
                {
                    "code": "EC8",
                    "clause": "EN 1998-1 §3.2.3.1.2(4)a",
                    "requirement": "at least 3 records",
                    "found": f"{N_REC} records",
                    "passed": True,
                    "margin": N_REC - 3,
                    "unit": "records",
                },
                {
                    "code": "EC8",
                    "clause": "EN 1998-1 §3.2.3.1.2(4)b",
                    "requirement": "mean PGA >= a_g*S",
                    "found": f"{mean_pga:.3f} g >= {ag_s:.3f} g",
                    "passed": True,
                    "margin": mean_pga / ag_s - 1,
                    "unit": "",
                },
                {
                    "code": "EC8",
                    "clause": "EN 1998-1 §3.2.3.1.2(4)c",
                    "requirement": "mean spectrum >= 90 % of target in 0.2·T1–2·T1",
                    "found": "min ratio 0.96 at T = 0.39 s",
                    "passed": True,
                    "margin": 0.0667,
                    "unit": "",
                },
                {
                    "code": "NTC",
                    "clause": "NTC 2018 §3.2.3.6",
                    "requirement": "mean spectrum >= 90 % of target in 0.15–2.0 s",
                    "found": "min ratio 0.95 at T = 1.62 s",
                    "passed": True,
                    "margin": 0.0556,
                    "unit": "",
                },
                {
                    "code": "NTC",
                    "clause": "NTC 2018 §3.2.3.6",
                    "requirement": "stationary part >= 10 s, total >= 25 s",
                    "found": "25.0 s total, 15.0 s stationary",
                    "passed": True,
                    "margin": 0.0,
                    "unit": "s",
                },
            ],
        },
        "code_check": {
            "alpha0": a_rm,
            "e_star": 1.0,
            "M_star": mass,
            "FC": 1.35,
            "confidence_factor_level": "LC1",
            "behaviour_factor": 2.0,
            "a0_star": a_rm / 1.35,
            "demand": ag_s / 2.0,
            "ratio": a_rm / 1.35 / (ag_s / 2.0),
            "passed": a_rm / 1.35 >= ag_s / 2.0,
            "note": "Passive unbonded bars carry no load at rest: they do not change alpha0, "
            "so this check is the same for every retrofit option.",
        },
        "cases": cases,
        "ranking_rule": "Options meeting the target (capacity/demand >= 1) first, cheapest first "
        "(then lightest); then the others by capacity/demand, highest first.",
        "recommended": recommended,
        "retrofit_required": not cases[0]["meets_target"],
        "design": design,
        "governing": {
            "case": best["name"],
            "record": gov_rec["record"],
            "runs": [history(True), history(False)],
            "rupture_strain": eps_max,
        },
        "numerical_check": None,
        "input_warnings": [],
        "input_code_compliant": True,
        "sensitivity": {
            "case": best["name"],
            "rows": [
                {
                    "variant": v,
                    "design_a_dyn": best["design_a_dyn"] * f,
                    "capacity_demand": best["capacity_demand"] * f,
                    "lower_bound": False,
                }
                for v, f in (
                    ("as assessed", 1.0),
                    ("restitution: velocity", 0.93),
                    ("E -10% (41.4 GPa)", 0.97),
                    ("E +10% (50.6 GPa)", 1.02),
                )
            ],
        },
    }
    # through the typed model: a field the model lacks or requires fails here
    return to_json(from_data(AssessmentResult, json.loads(json.dumps(results))))


def main() -> None:
    out = Path(__file__).with_name("results.json")
    out.write_text(fixture_text(), encoding="utf-8")
    print(f"wrote {out} ({out.stat().st_size / 1e3:.0f} kB)")


if __name__ == "__main__":
    main()
