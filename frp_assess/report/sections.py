"""The seven sections of the report, each a list of flowables built from the typed results."""

from __future__ import annotations

import math

from reportlab.lib.units import mm
from reportlab.platypus import CondPageBreak, Flowable, KeepTogether, PageBreak

from frp_assess.numbers import no_retrofit_caveats, numerical_check_text
from frp_assess.report import charts, floor_section, site_section
from frp_assess.report import tables as tb
from frp_assess.report.flow import esc, gap, grid, key_value, markup, para
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult
MECHANISM_TEXT = {
    "one-sided": "one-sided rocking (the wall leans against transverse walls or floors on one "
    "side, so it can only rotate outwards and rebounds at each impact)",
    "two-sided": "two-sided rocking (a free-standing wall or parapet, rotating about either "
    "base edge)",
}


def design_statistic(results: Results) -> str:
    """What the design a_dyn is: the mean of the records or the least favourable one."""
    if results.design_is_mean:
        return "the mean over the records"
    return "the least favourable record, as there are fewer than 7 (EN 1998-1 §4.3.3.4.3)"


def h1(text: str) -> Flowable:
    return markup(esc(text), "h1")


def h2(text: str) -> Flowable:
    return markup(esc(text), "h2")


def _verdict(ok: bool, text: str) -> Flowable:
    return markup(text, "verdict_ok" if ok else "verdict_bad")


def _option_sentence(results: Results, c: CaseResult) -> str:
    cur = results.costs.currency
    lb = c.lower_bound
    return (
        f"<b>{esc(c.name)}</b>: {tb.fmt_mass(c.frp_mass)} kg of {esc(c.material)} "
        f"({tb.fmt_mass(c.frp_mass_per_m)} kg per metre of wall), indicative cost "
        f"{tb.fmt_cost(c.frp_cost)} {esc(cur)}; capacity/demand "
        f"{esc(tb.bound(tb.fmt_capacity(c, results.model.target), lb))}, improvement "
        f"{esc(tb.bound(tb.fmt_ratio(c.improvement), lb))} × the unreinforced wall"
        + ("" if c.meets_target else " (does <b>not</b> reach the target)")
        + "."
        + ("" if c.as_built is None else f" Built as {esc(c.as_built.note)}.")
    )


# --- 1 Summary ----------------------------------------------------------------------------


def summary(results: Results) -> list[Flowable]:
    p = results.project
    w = results.wall
    s = results.seismic
    urm = results.urm
    target = results.model.target
    demand = results.demand.pga
    n_rec = len(results.records)
    out: list[Flowable] = [
        para(p.name or "Unnamed project", "title"),
        markup(
            "Out-of-plane seismic assessment of a rocking masonry wall and of its retrofit with "
            "vertical FRP rebars (incremental dynamic analysis)"
            + "<br/>"
            + esc(" · ".join(x for x in (p.location, p.engineer) if x))
            + (" · " if (p.location or p.engineer) else "")
            + f"results of {esc(results.created)}",
            "subtitle",
        ),
        h1("1  Summary"),
    ]
    mech = MECHANISM_TEXT.get(w.mechanism, esc(w.mechanism))
    x_pivot = tb.crushing_shift(results)
    out.append(
        markup(
            f"<b>The wall.</b> {w.thickness:.2f} m thick, {w.height:.2f} m high and "
            f"{w.length:.2f} m long, "
            f"{esc(w.masonry_description or w.masonry or 'masonry')} "
            f"({w.unit_weight:g} kN/m³), assessed for {esc(mech)}. Its slenderness is "
            f"α = {w.alpha_deg:.2f}° and it starts rocking at a<sub>RM</sub> = "
            f"{tb.fmt_acc(w.a_rm)} g"
            + (
                "."
                if x_pivot is None
                else f" about a pivot {x_pivot * 500:.0f} mm inside its edge (the masonry "
                f"crushed under its weight, x = {x_pivot * 1000:.0f} mm; section 6.4), "
                f"against g·tan α = {tb.fmt_acc(math.tan(w.alpha))} g about the edge."
            )
        )
    )
    site = esc(p.location or "The site")
    comp = results.compliance
    out.append(
        markup(
            f"<b>The site and the demand.</b> {site}: {esc(s.spectrum.name or '')}; "
            f"design ground acceleration a<sub>g</sub>·S = {tb.fmt_acc(demand)} g. "
            f"{n_rec} {esc(RECORDS_KIND.get(s.records_kind, s.records_kind + ' records'))}, "
            + (
                "compatible with the spectrum (all code checks passed)."
                if comp.passed
                else "<b>NOT all spectrum-compatibility checks passed</b> (see section 3)."
            )
        )
    )
    floor = floor_section.floor_sentence(results)
    if floor is not None:
        out.append(markup(floor))
    ok = bool(urm.meets_target)
    lb = urm.lower_bound
    out.append(
        markup(
            f"<b>The wall as it is.</b> Over the {n_rec} records the unreinforced wall "
            f"overturns at a design ground acceleration a<sub>dyn</sub> = "
            f"{esc(tb.bound(tb.fmt_acc(urm.design_a_dyn), lb))} g "
            f"({esc(design_statistic(results))}), i.e. "
            f"{esc(tb.bound(tb.fmt_capacity(urm, target), lb))} times the demand"
            + (f" once divided by the confidence factor FC = {urm.fc:g}." if urm.fc != 1.0 else ".")
        )
    )
    out.append(
        _verdict(
            ok,
            (
                "Verdict: the unreinforced wall is adequate"
                if ok
                else "Verdict: the unreinforced wall is NOT adequate"
            )
            + f" (capacity/demand {esc(tb.bound(tb.fmt_capacity(urm, target), lb))} "
            + ("≥" if ok else "<")
            + f" target {target:g}).",
        )
    )
    k = floor_section.linear_check(results)
    out.append(
        markup(
            "For comparison, the linear kinematic check of NTC 2018 / Circolare 2019 §C8.7.1 "
            f"gives a<sub>0</sub>* = {tb.fmt_acc(k.a0_star)} g against "
            f"{tb.fmt_acc(k.demand)} g (ratio {tb.fmt_ratio(k.ratio)}: "
            + ("satisfied" if k.passed else "not satisfied")
            + "). The dynamic analysis accounts for the wall's rocking capacity beyond "
            "activation, which the static check ignores.",
            "small",
        )
    )
    out += floor_section.checks_verdict_lines(results)
    rec = tb.case_by_name(results, results.recommended)
    ranked = [c for c in tb.ranked_options(results) if c.rank is not None]  # not the dropped
    compliant = bool(results.input_code_compliant)
    if not compliant:
        out.append(
            _verdict(
                False,
                "Input not code-compliant: the record set fails the code's spectrum-"
                "compatibility checks (section 3.3). The results below are not a basis for a "
                "signed verdict; no option is recommended, the first one is only best ranked.",
            )
        )
    if rec is not None and not compliant:
        out.append(markup("<b>Best ranked retrofit.</b> " + _option_sentence(results, rec)))
        out.append(
            markup(
                f"It ranks first under the ranking rule: {esc(results.ranking_rule)}",
                "small",
            )
        )
    elif rec is not None:
        if ok:
            out.append(
                markup(
                    "<b>No retrofit is needed</b> for this demand"
                    + "".join(f"; <b>but</b> {esc(c)}" for c in no_retrofit_caveats(results))
                    + ". If extra margin is wanted, the cheapest option is: "
                    + _option_sentence(results, rec)
                )
            )
        else:
            out.append(markup("<b>Recommended retrofit.</b> " + _option_sentence(results, rec)))
        out.append(
            markup(
                "It is the cheapest option that meets the target (ranking rule: "
                f"{esc(results.ranking_rule)})",
                "small",
            )
        )
        alts = [c for c in ranked if c is not rec][:3]
        if alts:
            out.append(markup("<b>Alternatives</b>, next in the ranking:"))
            for c in alts:
                out.append(markup(_option_sentence(results, c), "bullet"))
    elif ranked:
        out.append(
            _verdict(
                False,
                f"No retrofit option examined reaches capacity/demand ≥ {target:g}. "
                "The best ones are:",
            )
        )
        for c in ranked[:3]:
            out.append(markup(_option_sentence(results, c), "bullet"))
    elif not results.options:
        out.append(para("No retrofit option was examined."))
    n_dropped = sum(1 for c in results.options if c.rank is None)
    if n_dropped:
        out.append(
            para(
                f"{n_dropped} of {len(results.options)} options "
                + ("fails" if n_dropped == 1 else "fail")
                + " the pivot check (the masonry cannot carry the wall and the bars at rupture "
                "on a compressed zone small enough for the rocking mechanism) and "
                + ("is" if n_dropped == 1 else "are")
                + ' dropped from the ranking: see section 6.4, "The masonry at the pivot".',
                "small",
            )
        )
    out.append(gap(4))
    data = tb.summary_table(results)
    widths = [25 * mm, 37 * mm, 18 * mm, 18 * mm, 20 * mm, 17 * mm, 20 * mm, 15 * mm]
    out.append(
        grid(
            data, widths, wrap=(0, 1), numeric_from=2, highlight_rows=[1] if rec is not None else []
        )
    )
    out.append(
        para(
            f"All accelerations in g; costs are indicative ({results.costs.currency}, "
            "material at the stated price per kg plus installation per metre of wall and layer "
            "of bars) and must be confirmed by quotes. Full list of options: section 5.",
            "caption",
        )
    )
    out.append(PageBreak())
    return out


# --- 2 Inputs -----------------------------------------------------------------------------


#: results.json ``seismic.records_kind`` in words ("recorded": read from the project's files,
#: which may themselves be artificial; "7 recorded records" said neither)
RECORDS_KIND = {"artificial": "artificial records", "recorded": "records read from files"}


def inputs(results: Results) -> list[Flowable]:
    w = results.wall
    out: list[Flowable] = [h1("2  Inputs"), h2("2.1  Project and software")]
    out.append(key_value(tb.software_rows(results)))
    out.append(h2("2.2  Wall, masonry and mechanism"))
    rows = tb.wall_rows(results)
    rows[-1] = ["mechanism", MECHANISM_TEXT.get(w.mechanism, w.mechanism)]
    out.append(key_value(rows))
    out.append(h2("2.3  FRP materials"))
    data = tb.materials_table(results)
    out.append(grid(data, [18 * mm, 16 * mm, 14 * mm, 22 * mm, 22 * mm, 82 * mm], wrap=(5,)))
    out.append(
        para(
            "Prices are indicative defaults or user inputs, not quotes. ε_u is the ultimate "
            "tensile strain of the bar (mean producer value); the rupture strain of the model "
            f"is ε_max = {tb.rupture_strain_words(results)} with c = "
            f"{results.model.strain_factor:g}"
            + (
                " (CNR-DT 200 design values, section 6.2)."
                if tb.design_strain(results)
                else " (mean values)."
            ),
            "caption",
        )
    )
    out.append(h2("2.4  Model options and IDA settings"))
    out.append(key_value(tb.model_rows(results), sub_values=True))
    return out


# --- 3 Seismic input ----------------------------------------------------------------------


def seismic(results: Results) -> list[Flowable]:
    out: list[Flowable] = [PageBreak(), h1("3  Seismic input"), h2("3.1  Target spectrum")]
    out.append(key_value(tb.spectrum_rows(results), sub_values=True, verbatim_rows=(0, 1)))
    out += site_section.site_section(results)
    out.append(h2("3.2  Records"))
    out.append(
        grid(
            tb.records_table(results),
            [22 * mm, 62 * mm, 20 * mm, 22 * mm, 18 * mm, 22 * mm],
            wrap=(0, 1),
            numeric_from=2,
        )
    )
    for warning in results.input_warnings or []:
        out.append(para("Warning: " + str(warning), "small"))
    out.append(gap(6))
    out.append(
        KeepTogether(
            [
                charts.spectra_chart(results),
                para(
                    "Figure 1. Elastic response spectra at 5 % damping: the target, 90 % of it, "
                    "each record's spectrum and their mean (the quantity the code checks compare).",
                    "caption",
                ),
            ]
        )
    )
    comp = results.compliance
    out.append(CondPageBreak(60 * mm))
    out.append(h2("3.3  Code compliance of the record set"))
    out.append(
        grid(
            tb.compliance_table(results),
            [18 * mm, 30 * mm, 46 * mm, 42 * mm, 20 * mm, 14 * mm],
            wrap=(0, 1, 2, 3),
            numeric_from=4,
        )
    )
    out.append(
        _verdict(bool(comp.passed), "All checks passed." if comp.passed else "Some checks FAILED.")
    )
    out += floor_section.floor_motion_part(results)
    return out


# --- 4 Unreinforced wall ------------------------------------------------------------------


def unreinforced(results: Results) -> list[Flowable]:
    urm = results.urm
    out: list[Flowable] = [
        PageBreak(),
        h1("4  The unreinforced wall"),
        h2("4.1  Rocking properties"),
    ]
    out.append(key_value(tb.wall_property_rows(results), sub_values=True))
    out.append(h2("4.2  Incremental dynamic analysis, record by record"))
    out.append(grid(tb.case_records_table(urm), [30 * mm, 28 * mm, 40 * mm, 28 * mm, 24 * mm]))
    out.append(
        para(
            "C: the smallest multiplier of the record that overturns the wall (first collapse); "
            "a_dyn = C·PGA; q = a_dyn / a_RM. 'no collapse ≤ C_max': the wall did not overturn "
            "up to the largest multiplier tried.",
            "caption",
        )
    )
    out.append(key_value(tb.case_summary_rows(results, urm), sub_values=True))
    out.append(h2("4.3  Dynamic assessment next to the code kinematic check"))
    out.append(
        grid(tb.comparison_table(results), [62 * mm, 24 * mm, 24 * mm, 28 * mm, 30 * mm], wrap=(0,))
    )
    out.append(gap(6))
    out.append(key_value(tb.code_check_rows(results), sub_values=True))
    note = results.code_check.note
    if note:
        out.append(para(note, "caption"))
    out += floor_section.checks_part(results)
    return out


# --- 5 Retrofit options -------------------------------------------------------------------


def options(results: Results) -> list[Flowable]:
    out: list[Flowable] = [PageBreak(), h1("5  Retrofit options"), h2("5.1  Ranking")]
    out.append(para("Ranking rule: " + results.ranking_rule, "small"))
    data = tb.ranking_table(results)
    rec_name = results.recommended
    hl = [i for i, r in enumerate(data.rows) if r[1] == rec_name]
    widths = [12, 25, 11, 14, 8, 11, 11, 11, 14, 12, 16, 16, 11]  # rank: 'dropped'
    out.append(
        grid(
            data,
            [x * mm for x in widths],
            wrap=(1, 2, 3),
            small=True,
            numeric_from=4,
            highlight_rows=hl,
        )
    )
    out.append(
        markup(
            "ρ: ratio of the active bars to the wall cross-section (external bars: the same on "
            "each face, so twice the quantity is installed). FRP masses per metre of wall and "
            "for the whole wall; costs indicative. q = a<sub>dyn</sub>/a<sub>RM</sub>; "
            "improvement = a<sub>dyn</sub> / a<sub>dyn</sub> of the unreinforced wall; "
            "capacity/demand = a<sub>dyn</sub> / (FC·a<sub>g</sub>·S). '≥': lower bound, "
            "some record did not overturn up to C_max. Highlighted: the "
            + (
                "recommended option."
                if results.input_code_compliant
                else "best ranked option (input not code-compliant: nothing is recommended)."
            ),
            "caption",
        )
    )
    for c in results.options:  # dropped by the pivot check: no rank, the reason here
        if c.pivot is not None and c.pivot.dropped:
            out.append(para(c.pivot.reason, "small"))
    out.append(CondPageBreak(90 * mm))
    out.append(h2("5.2  Effect of the FRP quantity"))
    out.append(
        KeepTogether(
            [
                charts.options_chart(results, "improvement"),
                para(
                    "Figure 2. Level of seismic improvement against the FRP installed on the wall, "
                    "one line per material and position.",
                    "caption",
                ),
            ]
        )
    )
    out.append(
        KeepTogether(
            [
                charts.options_chart(results, "capacity_demand"),
                para(
                    "Figure 3. Capacity/demand against the FRP installed on the wall; options "
                    "above the target line meet it.",
                    "caption",
                ),
            ]
        )
    )
    out.append(CondPageBreak(50 * mm))
    out.append(h2("5.3  Design mode: the smallest ratio that meets the target"))
    if results.design:
        out.append(
            grid(
                tb.design_table(results),
                [16 * mm, 18 * mm, 20 * mm, 20 * mm, 18 * mm, 18 * mm, 64 * mm],
                wrap=(6,),
                numeric_from=2,
            )
        )
    else:
        out.append(para("Design mode was not run for this project."))
    out.append(CondPageBreak(80 * mm))
    out.append(h2("5.4  a_dyn [g] of every option and record"))
    mat = tb.a_dyn_matrix(results)
    n = len(mat.header) - 1
    other = (174 - 34) / max(n, 1)
    out.append(grid(mat, [34 * mm] + [other * mm] * n, wrap=(0,), small=True))
    out.append(para("n.c.: no collapse up to C_max for that record.", "caption"))
    out.append(CondPageBreak(60 * mm))
    out.append(h2("5.5  How far the numbers can be trusted: scatter and fragility"))
    out.append(
        grid(
            tb.scatter_table(results),
            [x * mm for x in (34, 18, 16, 13, 33, 20, 12, 28)],
            wrap=(0, 4),
            small=True,
            numeric_from=1,
        )
    )
    out.append(
        para(
            "Statistics of a_dyn over the records (a record without collapse up to C_max "
            "enters at its lower bound C_max·PGA). Fragility: a lognormal curve fitted by "
            "maximum likelihood to the collapse accelerations (records without collapse "
            "right-censored); P(collapse) is its value at the demand a_g·S. With few records "
            "the fit is coarse: read it as the scatter of the result, not as a site "
            "probability.",
            "caption",
        )
    )
    sens = tb.sensitivity_table(results)
    if sens is not None and results.sensitivity is not None:
        out.append(CondPageBreak(60 * mm))
        out.append(h2("5.6  What the result depends on: the model conventions"))
        out.append(grid(sens, [x * mm for x in (70, 34, 26, 34)], wrap=(0,), numeric_from=1))
        out.append(
            para(
                f"{results.sensitivity.case} under the conventions the paper leaves open, "
                "one at a time (docs/model.md §3), and a ±10 % change of the bars' elastic "
                "modulus; the same records, the design value of a_dyn.",
                "caption",
            )
        )
    return out


# --- 6 Governing time history -------------------------------------------------------------


def governing(results: Results) -> list[Flowable]:
    out: list[Flowable] = [PageBreak(), h1("7  The governing time history")]
    gov = results.governing
    if not gov or not gov.runs:
        out.append(para("No time history is stored in the results."))
        return out
    rs = gov.rupture_strain
    out.append(
        markup(
            f"Case <b>{esc(gov.case)}</b>, record <b>{esc(gov.record)}</b> (the record "
            "that overturns it at the smallest multiplier). The response at the collapse "
            "multiplier and just below it shows how the wall fails"
            + (
                f"; the bar ruptures when its strain reaches ε<sub>max</sub> = "
                f"{1e3 * rs:.2f} ‰ (c·ε<sub>u</sub>)."
                if rs is not None
                else "."
            )
        )
    )
    out.append(
        grid(
            tb.governing_runs_table(results),
            [24 * mm, 22 * mm, 24 * mm, 36 * mm, 22 * mm, 46 * mm],
            wrap=(0, 3, 5),
        )
    )
    out.append(gap(8))
    chart = charts.history_chart(results)
    if chart is not None:
        out.append(chart)
        out.append(
            para(
                "Figure 4. Rotation θ/α (θ = α: the wall has rotated as far as its slenderness; "
                "collapse follows the criterion of section 2.4) and strain of the acting bar, at "
                "the collapse multiplier (red) and just below it (blue); after the record the "
                "wall moves freely until its fate is decided.",
                "caption",
            )
        )
    return out


# --- 7 Method and references --------------------------------------------------------------

EQUATIONS = [
    (
        "Equation of motion (paper Eq. 10), s = sgn θ",
        "θ'' = −p²·[ sin(α·s − θ) + (ü<sub>g</sub>/g)·cos(α·s − θ) + K<sub>s</sub>·sin θ ],   "
        "p² = 3g/(4R),   K = sin α·tan α·(r<sub>p</sub>/2)·E·A/(m·g),   r<sub>p</sub> = 1 centred, "
        "4 external; K<sub>s</sub> = K while the bar acting on side s is intact, 0 after rupture.",
    ),
    (
        "Restitution at impact (Housner; paper Eq. 13–14)",
        "r<sub>2</sub> = (1 − 1.5·sin²α)² two-sided; r<sub>1</sub> = [(1 − 1.5·sin²α)²·"
        "(1 − 1.5·cos²α)]² one-sided; convention 'energy': |θ'<sub>+</sub>| = √r·|θ'<sub>−</sub>|; "
        "'velocity': |θ'<sub>+</sub>| = r·|θ'<sub>−</sub>|.",
    ),
    (
        "Bar rupture (paper Eq. 11–12)",
        "θ<sub>max</sub> = 2·asin(ε<sub>max</sub>·H / (2·b<sub>r</sub>)), ε<sub>max</sub> = "
        "c·ε<sub>u</sub> (mean values) or c·η<sub>a</sub>·ε<sub>fk</sub>/γ<sub>f</sub> "
        "(design values, section 6.2), b<sub>r</sub> = B/2 centred, B external; "
        "'energy-transfer': "
        "½I<sub>0</sub>θ'<sub>+</sub>² = ½I<sub>0</sub>θ'<sub>−</sub>² + U<sub>r</sub>(θ<sub>max"
        "</sub>), U<sub>r</sub> = ½·(E·A/H)·e², e = 2·b<sub>r</sub>·sin(θ/2).",
    ),
    (
        "Incremental dynamic analysis",
        "C<sub>0</sub> = a<sub>RM</sub>/PGA; C = C<sub>0</sub>·s<sup>k</sup> until the first "
        "collapse (C ≤ C_max), then bisection to (C<sub>hi</sub> − C<sub>lo</sub>) ≤ "
        "tol·C<sub>hi</sub>; a<sub>dyn</sub> = C<sub>hi</sub>·PGA.",
    ),
    (
        "Force reduction factor (paper Eq. 15–16)",
        "q = a<sub>dyn</sub> / a<sub>RM</sub>, a<sub>RM</sub> = g·tan α about the edge, "
        "g·(B − x)/H about the crushing pivot (section 6.4; α, R, I<sub>0</sub>, p and "
        "b<sub>r</sub> are then those about the shifted pivot, docs/model.md §1.1).",
    ),
    (
        "Improvement and capacity/demand",
        "I = a<sub>dyn,d</sub>(retrofitted) / a<sub>dyn,d</sub>(unreinforced); "
        "capacity/demand = a<sub>dyn,d</sub> / (FC·a<sub>g</sub>·S), where the design value "
        "a<sub>dyn,d</sub> is the mean over the records (7 or more), else the least favourable, "
        "and FC the confidence factor (below).",
    ),
]

#: the first assumption, by the pivot rule of the run (docs/model.md §1.1)
PIVOT_ASSUMPTION = {
    "edge": "The wall is a rigid monolithic block rocking about its base edges (no sliding, "
    "no bouncing, no crushing of the edge: the pivot check of section 6.4 says where this "
    "fails); the analysis is per metre of wall.",
    "crushing": "The wall is a rigid monolithic block rocking about a pivot inside the "
    "compressed zone of its base, at x/2 from the edge, x sized on the weight and the bar "
    "force at rupture and held for the whole time history (conservative below rupture; "
    "section 6.4); no sliding, no bouncing; the analysis is per metre of wall.",
}

ASSUMPTIONS = [
    "The FRP bars are unbonded, not prestressed, anchored at the base and the top, linear "
    "elastic up to a brittle rupture at the strain ε_max of section 6.2 (c·ε_u with mean "
    "values, c·η_a·ε_fk/γ_f with design values); they carry no load at rest.",
    "Collapse follows the chosen criterion (section 2.4); the collapse multiplier is the "
    "first one that overturns the wall.",
    "With 7 or more records the mean a_dyn is the design value (EN 1998-1 §4.3.3.4.3, "
    "NTC 2018 §7.3.5); with fewer, the least favourable.",
    "Response spectra by the exact piecewise-linear recurrence at 5 % damping.",
    "Prices and costs are indicative (material price per kg plus installation per metre of "
    "wall and layer of bars); they serve to rank the options, not to estimate the works.",
    "Anchorages, end plates, local crushing and the connection to the rest of the building are "
    "outside the model and must be designed separately.",
]

REFERENCES = [
    "[1] Masonry Walls Retrofitted with Vertical FRP Rebars (journal article; authors and year "
    "are not restated by frp-assess). Source of the model: equation of motion, restitution, "
    "bar rupture, IDA procedure and parametric study.",
    "[2] Housner, G. W. (1963). The behavior of inverted pendulum structures during "
    "earthquakes. Bulletin of the Seismological Society of America, 53(2), 403–417.",
    "[3] EN 1998-1:2004. Eurocode 8: Design of structures for earthquake resistance – Part 1: "
    "General rules, seismic actions and rules for buildings. CEN, Brussels.",
    "[4] NTC 2018. Aggiornamento delle «Norme tecniche per le costruzioni», D.M. 17 gennaio "
    "2018. Gazzetta Ufficiale n. 42, 20 febbraio 2018.",
    "[5] Circolare 21 gennaio 2019, n. 7 C.S.LL.PP. Istruzioni per l'applicazione dell'«"
    "Aggiornamento delle Norme tecniche per le costruzioni» di cui al D.M. 17 gennaio 2018.",
    "[6] Gasparini, D. A., Vanmarcke, E. H. (1976). Simulated earthquake motions compatible "
    "with prescribed response spectra (SIMQKE). MIT Department of Civil Engineering, "
    "Research Report R76-4.",
    "[7] Nigam, N. C., Jennings, P. C. (1969). Calculation of response spectra from "
    "strong-motion earthquake records. Bulletin of the Seismological Society of America, "
    "59(2), 909–922.",
    "[8] CNR-DT 203/2006. Guide for the design and construction of concrete structures "
    "reinforced with fiber-reinforced polymer bars. CNR, Rome (ranges of FRP bar properties).",
]


def fc_text(results: Results) -> str:
    """The confidence factor in the IDA verdict: its value, basis and how to turn it off."""
    fc = results.cases[0].fc
    kc = results.kinematic_checks
    level = kc.knowledge_level if kc is not None else results.code_check.confidence_factor_level
    if fc == 1.0:
        return (
            "Confidence factor: the IDA capacity is not divided by FC (FC = 1 in the verdict: "
            "code_check.fc_in_ida: false, or knowledge level LC3)."
        )
    rule = "Circolare 2019 §C8.7.1.2.1.3: a rigid block whose masonry has infinite compressive "
    basis = (
        f"{level}; {rule}strength uses LC1's FC = 1.35"
        if level == "LC1"
        else f"knowledge level {level}, as asked in the project; note that {rule}strength "
        "would use LC1's FC = 1.35"
    )
    return (
        f"Confidence factor: FC = {fc:g} ({basis}) divides the IDA capacity, capacity/demand = "
        "a_dyn,d / (FC·a_g·S); the improvement, a ratio of a_dyn, does not change. Turn it off "
        "with code_check.fc_in_ida: false."
    )


def method(results: Results) -> list[Flowable]:
    out: list[Flowable] = [PageBreak(), h1("8  Method and references"), h2("8.1  Equations")]
    for title, eq in EQUATIONS:
        out.append(markup(f"<b>{esc(title)}.</b>"))
        out.append(markup(eq, "equation"))
    out.append(
        para(
            "Symbols: B, H thickness and height; R = ½√(B² + H²); m mass per metre; I₀ = "
            "(4/3)·m·R²; E, A elastic modulus and area of the active bars (A = ρ·B per metre); "
            "ü_g ground acceleration scaled by C. The equation is integrated by the "
            "Dormand–Prince 5(4) Runge–Kutta pair with local error control (steps never cross "
            "a record sample); every event (uplift, impact, rupture, collapse) is located "
            "inside the step on the integrator itself and the step restarts there. Under the "
            "'overturning' rule the wall is followed after the record until it has fallen or "
            "its energy is below every barrier it could still reach (it can no longer fall).",
            "small",
        )
    )
    out.append(para(fc_text(results), "small"))
    check = numerical_check_text(results)
    if check is not None:
        out.append(para(check, "small"))
    out.append(h2("8.2  Assumptions"))
    rule = results.cases[0].pivot.rule if results.cases[0].pivot is not None else "edge"
    for a in (PIVOT_ASSUMPTION.get(rule, PIVOT_ASSUMPTION["edge"]), *ASSUMPTIONS):
        out.append(markup("• " + esc(a), "bullet"))
    out.append(h2("8.3  References"))
    for r in REFERENCES:
        out.append(para(r, "reference"))
    sw = results.software
    out.append(gap(6))
    out.append(
        para(
            f"Report generated by {sw.name} {sw.version} from "
            f"results.json of {results.created}; every number in it is read from that "
            "file.",
            "small",
        )
    )
    return out
