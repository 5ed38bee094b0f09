"""The report section "The retrofit as built" and its subsection "The masonry at the pivot".

Issue 16 §1–2, docs/model.md §1.1 and §2.1: per option (and design-mode answer) the bars as
they will be built (``cases[i].as_built``, ``design[j].as_built``), the rupture strain rule,
the anchorage, then the masonry strength behind the pivot (``masonry_strength``) and the
pivot check of every case (``cases[i].pivot``), with the options it drops and why.

Table contents are pure functions of the typed results (:class:`TableData`, plain text);
:func:`section` lays them out.  Formats: lengths of bar in m with 1 decimal, spacings in m
with 3, forces in kN (per bar) or kN/m (per metre of wall) with 1 and 0 decimals, the depth x
in mm, ratios in ‰ as :func:`~frp_assess.report.tables.fmt_permille`.
"""

from __future__ import annotations

from collections.abc import Sequence

from reportlab.lib.units import mm

from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, grid, h1, h2, markup, page_break, para
from frp_assess.report.tables import DASH, TableData, fmt_cost, fmt_mass, fmt_permille, head
from frp_assess.results.as_built import AsBuilt, BarStrain
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult

LAYOUT_HEADER = [
    "option",
    "layout",
    "ρ installed / asked [‰]",
    "ρ model [‰]",
    "bar length [m]",
    "metres [m]",
    "mass [kg]",
    "cost [{cur}]",
]
STRAIN_HEADER = [
    "material",
    "ε_u mean [-]",
    "ε_fk [-]",
    "exposure",
    "η_a [-]",
    "γ_f [-]",
    "c [-]",
    "ε rupture [-]",
]
ANCHORAGE_HEADER = [
    "option",
    "force per bar [kN]",
    "bond length [m]",
    "pull-out cone [kN]",
    "cone",
]
PIVOT_HEADER = ["case", "N [kN/m]", "x [mm]", "x/B [-]", "pivot shift [mm]", "pivot", "verdict"]


def layout_text(b: AsBuilt) -> str:
    """``n × Ød per line at s m`` (centred: one line; external: per face, two faces)."""
    where = "in one line" if b.lines == 1 else f"per face ({b.lines} faces)"
    return f"{b.bars_per_line} × Ø{b.diameter:g} {where} at {b.spacing:.3f} m ({b.total_bars} bars)"


def built_items(results: Results) -> list[tuple[str, AsBuilt]]:
    """(label, as built) of every option with bars, then every design-mode answer."""
    out = [(c.name, c.as_built) for c in results.options if c.as_built is not None]
    for d in results.design or ():
        if d.as_built is not None:
            out.append((f"design: {d.material} {d.position}", d.as_built))
    return out


def layout_table(results: Results) -> TableData:
    """Per option and design answer: the bars, the ratio installed for the ratio asked, the
    metres, mass and cost of the bars as built."""
    cur = results.costs.currency
    rows = [
        [
            label,
            layout_text(b),
            f"{fmt_permille(b.ratio_installed)} / {fmt_permille(b.ratio_asked)}",
            fmt_permille(b.ratio_model),
            f"{b.bar_length:.2f}",
            f"{b.metres:.1f}",
            fmt_mass(b.mass),
            fmt_cost(b.cost),
        ]
        for label, b in built_items(results)
    ]
    return TableData([head(h, cur=cur) for h in LAYOUT_HEADER], rows)


def _opt(x: float | None, fmt: str) -> str:
    return DASH if x is None else format(x, fmt)


def strain_table(results: Results) -> TableData:
    """One row per material: the rupture strain the model uses and its factors."""
    seen: dict[str, BarStrain] = {}
    for _, b in built_items(results):
        seen.setdefault(b.material, b.strain)
    rows = [
        [
            mat,
            f"{s.mean:.4f}",
            _opt(s.characteristic, ".4f"),
            s.exposure or DASH,
            _opt(s.eta_a, ".2f"),
            _opt(s.partial_factor, ".2f"),
            f"{s.cyclic_factor:.2f}",
            f"{s.rupture_strain:.4f}",
        ]
        for mat, s in seen.items()
    ]
    return TableData(list(STRAIN_HEADER), rows)


def strain_rule(results: Results) -> str:
    """The rule of the rupture strain in words (design values or mean values)."""
    strains = [b.strain for _, b in built_items(results)]
    if not strains:
        return ""
    if all(s.design_values for s in strains):
        return (
            "Rupture strain of the bars: design value ε = c·η_a·ε_fk/γ_f (CNR-DT 200 R1/2013 "
            "§3.5: environmental conversion factor η_a of Table 3.2 for the fibre and the "
            "exposure, partial factor γ_f of Table 3.1; c = analysis.strain_factor, the "
            "cyclic factor)."
        )
    if not any(s.design_values for s in strains):
        return (
            "Rupture strain of the bars: mean producer values, ε = c·ε_u, without partial or "
            "environmental factors (bars.design_values: false); c = analysis.strain_factor."
        )
    return "Rupture strain of the bars: " + "; ".join(sorted({s.rule for s in strains})) + "."


def anchorage_table(results: Results) -> TableData:
    """Per option and design answer: the design force per bar, its bond length and the
    masonry pull-out cone (OK/FAILS, a dash when not checked)."""
    rows = []
    for label, b in built_items(results):
        a = b.anchorage
        cone = DASH if a.cone_ok is None else ("OK" if a.cone_ok else "FAILS")
        rows.append(
            [
                label,
                f"{a.design_force:.1f}",
                _opt(a.length_required, ".3f"),
                _opt(a.cone_resistance, ".1f"),
                cone,
            ]
        )
    return TableData(list(ANCHORAGE_HEADER), rows)


def pivot_table(cases: Sequence[CaseResult]) -> TableData:
    """Per case: N = W + T_u, the compressed depth x, x/B, the pivot's shift, the pivot the
    IDA used and the verdict (kept / dropped)."""
    rows = []
    for c in cases:
        p = c.pivot
        if p is None:
            continue
        rows.append(
            [
                c.name,
                f"{p.force:.0f}",
                f"{p.depth * 1e3:.0f}",
                f"{p.depth_ratio:.3f}",
                f"{p.pivot_shift * 1e3:.0f}",
                p.model_pivot,
                "dropped" if p.dropped else "holds",
            ]
        )
    return TableData(list(PIVOT_HEADER), rows)


def masonry_text(results: Results) -> str:
    """f_m and its source, FC, f_d and the pivot rule, one paragraph (plain text)."""
    m = results.masonry_strength
    if m is None:
        return "The masonry strength is not in these results (written before the pivot check)."
    pivot = next((c.pivot for c in results.cases if c.pivot is not None), None)
    rule = pivot.rule if pivot is not None else None
    limit = f"{pivot.limit:.2f}" if pivot is not None else "the limit"
    rule_text = {
        "edge": (
            "pivot: edge — the wall rocks about its compressed edge; an option is dropped "
            f"when the compressed zone is deeper than x/B = {limit}"
        ),
        "crushing": (
            "pivot: crushing — each case's pivot sits x/2 inside the compressed edge, x of "
            "its N, held for the whole time history (the lever arms of gravity and bars "
            "shrink by x/2; conservative below rupture, when the bar force is less than "
            "T_u); an option is dropped only when there is no mechanism (the bar inside the "
            "compressed zone, or x ≥ B)"
        ),
    }.get(rule or "", f"pivot: {rule}")
    kind = f"Masonry {m.masonry}" if m.masonry else "Masonry given by the project"
    return (
        f"{kind}, knowledge level {m.knowledge_level}: f_m = {m.f_m:.2f} MPa ({m.source}); "
        f"FC = {m.confidence_factor:.2f}; f_d = f_m/FC = {m.f_d:.2f} MPa; stress block "
        f"{m.stress_block_factor:.2f}·f_d over a depth x = N/({m.stress_block_factor:.2f}·f_d·1 m),"
        f" N = W + T_u with the bar at its rupture strain. {rule_text}."
    )


def dropped_reasons(results: Results) -> list[str]:
    """The check line of every option the pivot check dropped (its reason at the end)."""
    return [c.pivot.reason for c in results.options if c.pivot is not None and c.pivot.dropped]


def section(results: Results) -> list[Block]:
    """The flowables of "The retrofit as built" (none when there is nothing to show)."""
    items = built_items(results)
    has_pivot = any(c.pivot is not None for c in results.cases)
    if not items and not has_pivot:
        return []
    out: list[Block] = [page_break(), h1("6  The retrofit as built")]
    if items:
        out.append(h2("6.1  Bars, quantities and cost"))
        out.append(
            grid(
                layout_table(results),
                [x * mm for x in (32, 52, 20, 14, 14, 14, 14, 16)],
                wrap=(0, 1),
                small=True,
                numeric_from=2,
            )
        )
        bars = items[0][1]
        out.append(
            para(
                "Whole bars of a catalogue diameter over the wall length, spacing between "
                f"{bars.min_spacing:g} m and {bars.max_spacing:g} m (docs/model.md §2.1); the "
                "end bars sit half a spacing from the wall's ends. ρ installed = n·A_b/(B·L) "
                "per line; ρ model is the ratio the IDA used. Metres, mass and cost count "
                "the bond length at both ends when it is known; costs indicative.",
                "caption",
            )
        )
        out.append(cond_break(45 * mm))
        out.append(h2("6.2  Rupture strain of the bars"))
        out.append(para(strain_rule(results)))
        out.append(grid(strain_table(results), [x * mm for x in (26, 22, 22, 22, 18, 18, 16, 26)]))
        out.append(cond_break(45 * mm))
        out.append(h2("6.3  Anchorage"))
        out.append(
            grid(
                anchorage_table(results),
                [x * mm for x in (52, 30, 30, 34, 20)],
                wrap=(0,),
                numeric_from=1,
            )
        )
        out.append(
            para(
                "Design force per bar A_b·E·ε at the rupture strain above (an end plate or any "
                "mechanical anchorage must carry it); bond length the larger of "
                "F/(π·d·τ_b) (bar to grout) and F/(π·d_h·τ_m) (grout to masonry); pull-out "
                "cone: f_t times the projected area of a 45° cone clipped by the faces and "
                "the neighbouring bars. Dashes: not checked (no bars.anchorage, or no masonry "
                "tensile strength).",
                "caption",
            )
        )
        if any(b.anchorage.length_required is None for _, b in items):
            out.append(
                para(
                    "The project gives no bars.anchorage: the force per bar is for an end "
                    "plate or anchorage; give bars.anchorage for the bond length and the "
                    "pull-out cone.",
                    "small",
                )
            )
    out.append(cond_break(60 * mm))
    out.append(h2("6.4  The masonry at the pivot"))
    out.append(para(masonry_text(results)))
    if has_pivot:
        out.append(
            grid(
                pivot_table(results.cases),
                [x * mm for x in (44, 20, 18, 18, 24, 20, 20)],
                wrap=(0,),
                numeric_from=1,
            )
        )
        out.append(
            para(
                "N: largest compression at the pivot per metre of wall (weight and the acting "
                "bar at rupture); x: depth of the compressed zone; pivot shift: how far the "
                "model's pivot sits from the compressed edge (x/2 with pivot: crushing).",
                "caption",
            )
        )
    reasons = dropped_reasons(results)
    if reasons:
        out.append(
            markup(
                "<b>Dropped from the ranking</b> (the rigid-block premise does not hold):",
                "body",
            )
        )
        out += [para(r, "small") for r in reasons]
    elif has_pivot:
        out.append(para("No option is dropped: every case passes the pivot check."))
    return out
