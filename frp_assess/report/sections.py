"""The detailed sections of the report on its inputs (summary, inputs, seismic input), each a
list of blocks built from the typed results; the results in :mod:`sections_results`."""

from __future__ import annotations

import math

from reportlab.lib.units import mm

from frp_assess.numbers import no_retrofit_caveats
from frp_assess.report import charts, floor_section
from frp_assess.report import tables as tb
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import (
    cond_break,
    esc,
    figure,
    gap,
    grid,
    h1,
    h2,
    keep,
    key_value,
    markup,
    page_break,
    para,
)
from frp_assess.report.tables import EN
from frp_assess.report.verdict_text import (
    governing,
    passes,
    robustness_lines,
    verdict_sentence,
)
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.rules.record_sets import MEAN_OF_RECORDS_FROM

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
    return (
        f"the least favourable record, as there are fewer than {MEAN_OF_RECORDS_FROM} "
        "(EN 1998-1 §4.3.3.4.3)"
    )


def _verdict(ok: bool, text: str) -> Block:
    return markup(text, "verdict_ok" if ok else "verdict_bad")


def _option_sentence(results: Results, c: CaseResult) -> str:
    cur = results.costs.currency
    lb = c.lower_bound
    parts = []
    if c.material is not None:
        parts.append(
            f"{tb.fmt_mass(c.frp_mass)} kg of {esc(c.material)} "
            f"({tb.fmt_mass(c.frp_mass_per_m)} kg per metre of wall)"
        )
    if c.tie is not None:
        parts.append(
            f"tie-rods of {tb.fmt_mass(c.tie.steel_mass)} kg of steel "
            f"({tb.fmt_mass(c.tie.steel_mass_per_m)} kg per metre of wall)"
        )
    return (
        f"<b>{esc(c.name)}</b>: {' and '.join(parts)}, indicative cost "
        f"{tb.fmt_cost(c.option_cost)} {esc(cur)}; capacity/demand "
        f"{esc(tb.bound(tb.fmt_capacity(c, results.model.target), lb))}, improvement "
        f"{esc(tb.bound(tb.fmt_ratio(c.improvement), lb))} × the unreinforced wall"
        + ("" if passes(c) else f" (does <b>not</b> pass every deciding check: {governing(c, EN)})")
        + "."
        + ("" if c.as_built is None else f" Built as {esc(c.as_built.note)}.")
    )


# --- 1 Summary ----------------------------------------------------------------------------


def summary(results: Results) -> list[Block]:
    p = results.project
    w = results.wall
    s = results.seismic
    urm = results.urm
    target = results.model.target
    demand = results.demand.pga
    n_rec = len(results.records)
    out: list[Block] = [
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
                else f", its base reaction at rest acting {x_pivot * 500:.0f} mm inside its "
                f"edge (half the compressed zone under its weight, x<sub>W</sub> = "
                f"{x_pivot * 1000:.0f} mm; section 6.4), against g·tan α = "
                f"{tb.fmt_acc(math.tan(w.alpha))} g about the edge; the reaction then follows "
                "the bars as they stretch."
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
    ok = passes(urm)
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
            + f": it {verdict_sentence(urm, EN)}; the IDA's capacity/demand is "
            + f"{esc(tb.bound(tb.fmt_capacity(urm, target), lb))} (target {target:g}).",
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
                f"It is the cheapest option that passes every deciding check ("
                f"{governing(rec, EN)}; ranking rule: {esc(results.ranking_rule)})",
                "small",
            )
        )
        out += [markup(line, "small") for line in robustness_lines(results, EN)]
        alts = [c for c in ranked if c is not rec][:3]
        if alts:
            out.append(markup("<b>Alternatives</b>, next in the ranking:"))
            for c in alts:
                out.append(markup(_option_sentence(results, c), "bullet"))
    elif ranked:
        out.append(
            _verdict(
                False,
                "No retrofit option examined passes every deciding check. The closest to "
                "passing (the largest governing margin, equal margins by the IDA's) are:",
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
    out.append(page_break())
    return out


# --- 2 Inputs -----------------------------------------------------------------------------


#: results.json ``seismic.records_kind`` in words ("recorded": read from the project's files,
#: which may themselves be artificial; "7 recorded records" said neither)
RECORDS_KIND = {"artificial": "artificial records", "recorded": "records read from files"}


def inputs(results: Results) -> list[Block]:
    w = results.wall
    out: list[Block] = [h1("2  Inputs"), h2("2.1  Project and software")]
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


def seismic(results: Results) -> list[Block]:
    out: list[Block] = [page_break(), h1("3  Seismic input"), h2("3.1  Target spectrum")]
    out.append(key_value(tb.spectrum_rows(results), sub_values=True, verbatim_rows=(0, 1)))
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
        keep(
            [
                figure(charts.spectra_chart(results)),
                para(
                    "Figure 1. Elastic response spectra at 5 % damping: the target, 90 % of it, "
                    "each record's spectrum and their mean (the quantity the code checks compare).",
                    "caption",
                ),
            ]
        )
    )
    comp = results.compliance
    out.append(cond_break(60 * mm))
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
