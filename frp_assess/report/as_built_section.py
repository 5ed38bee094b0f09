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

from reportlab.lib.units import mm

from frp_assess.report import pivot_section
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, grid, h1, h2, markup, page_break, para
from frp_assess.report.tables import (
    DASH,
    EN,
    TableData,
    fmt_cost,
    fmt_mass,
    fmt_permille,
    head,
)
from frp_assess.results.as_built import AsBuilt, BarStrain
from frp_assess.results.model import AssessmentResult

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


def masonry_text(results: Results) -> str:
    """The masonry strength and the base reaction the model ran (English markup):
    :func:`frp_assess.report.pivot_section.masonry_text`."""
    return pivot_section.masonry_text(results, EN)


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
    out.append(h2("6.4  The masonry at the base"))
    out.append(markup(masonry_text(results)))
    if has_pivot:
        out.append(
            grid(
                pivot_section.pivot_table(results, EN),
                [x * mm for x in (40, 18, 16, 16, 24, 60)],
                wrap=(0, 5),
                numeric_from=1,
            )
        )
        out.append(markup(EN.t("pivot.caption"), "caption"))
        out += [markup(line) for line in pivot_section.weaker_notes(results, EN)]
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
        out.append(
            para(
                "No option is dropped for its base: a toe that crushes is a failure mode of "
                "the IDA."
            )
        )
    return out
