"""The annex's section "The retrofit as built" and its subsection "The masonry at the base",
in the report's language.

Issue 16 §1–2, docs/model.md §1.1 and §2.1: per option (and design-mode answer) the bars as
they will be built (``cases[i].as_built``, ``design[j].as_built``), the rupture strain rule,
the anchorage, then the masonry strength behind the pivot (``masonry_strength``) and the
pivot check of every case (``cases[i].pivot``), with the options it drops and why.

Table contents are pure functions of the typed results (:class:`TableData`, plain text);
:func:`section` lays them out.  Formats: lengths of bar in m with 2 decimals, spacings in m
with 3, forces in kN per bar with 1 decimal, the ratio installed in ‰ with 3 (1.001 ‰ for
1 ‰ asked), the other ratios as :func:`~frp_assess.report.formats.permille`.
"""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report import pivot_section
from frp_assess.report.annex_design_tables import anchorage_table, built, case_label
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, grid, h1, h2, markup, page_break, para
from frp_assess.report.formats import DASH, TableData, permille, run_words, shows_run_prose
from frp_assess.report.lang import Lang
from frp_assess.results.as_built import AsBuilt, BarStrain
from frp_assess.results.model import AssessmentResult
from frp_assess.text_safety import Markup, pdf

Results = AssessmentResult


def layout_text(b: AsBuilt, lang: Lang) -> str:
    """``n × Ød per line at s m`` (centred: one line; external: per face, two faces)."""
    where = lang.t("ax.layout.one_line") if b.lines == 1 else lang.t("ax.layout.faces", n=b.lines)
    return lang.t("ax.layout", n=b.bars_per_line, d=lang.gnum(b.diameter), where=where,
                  s=lang.num(b.spacing, 3), total=b.total_bars)  # fmt: skip


def layout_table(results: Results, lang: Lang) -> TableData:
    """Per option and design answer: the bars, the ratio installed for the ratio asked, the
    metres, mass and cost of the bars as built."""
    n = lang.num
    header = [
        lang.t("ax.col.option"),
        lang.t("ax.col.layout"),
        lang.t("ax.col.rho_installed"),
        lang.t("ax.col.rho_model"),
        lang.t("annex.col.length"),
        lang.t("ax.col.metres"),
        lang.t("ax.col.mass"),
        Markup(lang.t("ax.col.cost", cur=pdf(results.costs.currency))),
    ]
    rows = [
        [label, layout_text(b, lang),
         f"{n(b.ratio_installed, 3)} / {permille(b.ratio_asked, lang)}",
         permille(b.ratio_model, lang), n(b.bar_length, 2), n(b.metres, 1), n(b.mass, 1),
         n(b.cost, 0, grouping=True)]
        for label, b in built(results, lang)
    ]  # fmt: skip
    return TableData(header, rows)


def strain_table(results: Results, lang: Lang) -> TableData:
    """One row per material: the rupture strain the model uses and its factors."""
    seen: dict[str, BarStrain] = {}
    for _, b in built(results, lang):
        seen.setdefault(b.material, b.strain)
    n = lang.num
    header = [lang.t("ax.col.material"), lang.t("ax.col.eps_mean"), "ε_fk [-]",
              lang.t("ax.col.exposure"), "η_a [-]", "γ_f [-]", "c [-]",
              lang.t("ax.col.eps_rupture")]  # fmt: skip
    rows = [
        [mat, n(s.mean, 4), n(s.characteristic, 4), exposure_words(s.exposure, lang),
         n(s.eta_a, 2), n(s.partial_factor, 2), n(s.cyclic_factor, 2), n(s.rupture_strain, 4)]
        for mat, s in seen.items()
    ]  # fmt: skip
    return TableData(header, rows)


def exposure_words(exposure: str | None, lang: Lang) -> str:
    """The exposure class of the bars (CNR-DT 200 Table 3.2) in the report's language."""
    if not exposure:
        return DASH
    key = f"ax.exposure.{exposure}"
    return lang.t(key) if lang.has(key) else exposure


def strain_rule(results: Results, lang: Lang) -> str:
    """The rule of the rupture strain in words (design values or mean values)."""
    strains = [b.strain for _, b in built(results, lang)]
    if not strains:
        return ""
    if all(s.design_values for s in strains):
        return lang.t("ax.strain.design")
    if not any(s.design_values for s in strains):
        return lang.t("ax.strain.mean")
    if shows_run_prose(lang):
        return lang.t("ax.strain.mixed", rules="; ".join(sorted({s.rule for s in strains})))
    return lang.t("ax.strain.mixed.values")


def dropped_reasons(results: Results, lang: Lang) -> list[str]:
    """The check line of every option the pivot check dropped (its reason at the end; in
    another language than English the option and the rule broken, without the run's words)."""
    out = []
    for c in results.options:
        if c.pivot is not None and c.pivot.dropped:
            out.append(run_words(c.pivot.reason, lang) or lang.t(
                "ax.dropped.reason", case=case_label(c, lang)))  # fmt: skip
    return out


def _bars(results: Results, lang: Lang) -> list[Block]:
    items = built(results, lang)
    out: list[Block] = [h2("6.1  " + lang.t("ax.h.bars"))]
    out.append(grid(layout_table(results, lang), [x * mm for x in (32, 52, 20, 14, 14, 14, 14, 16)],
                    wrap=(0, 1), small=True, numeric_from=2))  # fmt: skip
    bars = items[0][1]
    out.append(markup(lang.t("ax.bars.caption", smin=lang.gnum(bars.min_spacing),
                             smax=lang.gnum(bars.max_spacing)), "caption"))  # fmt: skip
    out.append(cond_break(45 * mm))
    out.append(h2("6.2  " + lang.t("ax.h.strain")))
    out.append(markup(strain_rule(results, lang)))
    widths = [x * mm for x in (26, 22, 22, 22, 18, 18, 16, 26)]
    out.append(grid(strain_table(results, lang), widths))
    out.append(cond_break(45 * mm))
    out.append(h2("6.3  " + lang.t("annex.h.anchorage")))
    anchorage = anchorage_table(results, lang)
    assert anchorage is not None  # there are bars
    out.append(grid(anchorage, [x * mm for x in (52, 30, 30, 34, 20)], wrap=(0,),
                    numeric_from=1))  # fmt: skip
    out.append(markup(lang.t("ax.anchorage.caption"), "caption"))
    if any(b.anchorage.length_required is None for _, b in items):
        out.append(markup(lang.t("ax.anchorage.none"), "small"))
    return out


def section(results: Results, lang: Lang) -> list[Block]:
    """The blocks of "The retrofit as built" (none when there is nothing to show)."""
    items = built(results, lang)
    has_pivot = any(c.pivot is not None for c in results.cases)
    if not items and not has_pivot:
        return []
    out: list[Block] = [page_break(), h1("6  " + lang.t("ax.h.as_built"))]
    if items:
        out += _bars(results, lang)
    out.append(cond_break(60 * mm))
    out.append(h2("6.4  " + lang.t("annex.h.pivot")))
    out.append(markup(pivot_section.masonry_text(results, lang)))
    label = lambda c: case_label(c, lang)  # noqa: E731
    if has_pivot:
        out.append(grid(pivot_section.pivot_table(results, lang, label),
                        [x * mm for x in (40, 18, 16, 16, 24, 60)], wrap=(0, 5),
                        numeric_from=1))  # fmt: skip
        out.append(markup(lang.t("pivot.caption"), "caption"))
        out += [markup(line) for line in pivot_section.weaker_notes(results, lang, label)]
    reasons = dropped_reasons(results, lang)
    if reasons:
        out.append(markup(lang.t("ax.dropped.lead"), "body"))
        out += [para(r, "small") for r in reasons]
    elif has_pivot:
        out.append(markup(lang.t("ax.dropped.none")))
    return out
