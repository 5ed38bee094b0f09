"""The masonry at the base, in the report's language (the English and the Italian annex alike):
the masonry strength, the base reaction the model ran (docs/model.md §1.1: the wall turns
about its corner; N(θ) = W + T(θ) acts at x/2, x = N/(0.85·f_d), following the bars; the toe
crushes when x reaches the acting bar), every case's compression with the bar at rupture, how
each accelerogram's collapse ended, and, where a higher ratio is weaker, why (crushing).
Words from the catalogue, numbers from the results."""

from __future__ import annotations

from collections import Counter
from itertools import pairwise

from frp_assess.report.body_front import masonry_words
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup

Results = AssessmentResult
#: failure modes that end in crushing of the toe (results.json ``failure_mode``)
CRUSHING = ("crushing", "rupture then crushing")


def masonry_text(results: Results, lang: Lang) -> str:
    """f_m, its source, FC, f_d and the base reaction the model ran, one paragraph."""
    m = results.masonry_strength
    if m is None:
        return lang.t("pivot.none")
    pivot = next((c.pivot for c in results.cases if c.pivot is not None), None)
    rule = pivot.rule if pivot is not None else "crushing"
    kind = (
        lang.t("pivot.kind", name=masonry_words(results, lang))
        if m.masonry
        else lang.t("pivot.kind.given")
    )
    head = lang.t("pivot.masonry", kind=kind, lc=m.knowledge_level, fm=lang.num(m.f_m, 2),
                  source=m.source, fc=lang.gnum(m.confidence_factor),
                  fd=lang.num(m.f_d, 2))  # fmt: skip
    if rule == "edge":
        limit = lang.num(pivot.limit, 2) if pivot is not None else "—"
        return head + " " + lang.t("pivot.rule.edge", limit=limit)
    return head + " " + lang.t("pivot.rule.crushing", k=lang.num(m.stress_block_factor, 2))


def modes_text(case: CaseResult, lang: Lang) -> str:
    """How the records' collapses ended: ``7 × crushing``, ``5 × overturning, 2 × …``."""
    modes = Counter(r.failure_mode for r in case.records if r.failure_mode)
    if not modes:
        return lang.t("pivot.no_collapse")
    parts = []
    for mode, k in sorted(modes.items(), key=lambda kv: (-kv[1], str(kv[0]))):
        key = f"failure:{mode}"
        parts.append(f"{k} × {lang.t(key) if lang.has(key) else mode}")
    return ", ".join(parts)


def pivot_table(results: Results, lang: Lang, label: object = None) -> TableData:
    """Per case: N = W + T_u [kN/m], x [mm], x/B, x_W/2 at rest [mm] and how the collapses
    ended; ``label(case)`` names a case (default its name)."""
    header = [
        lang.t("pivot.col.case"),
        "N [kN/m]",
        "x [mm]",
        "x/B [-]",
        Markup(lang.t("pivot.col.rest")),
        lang.t("pivot.col.modes"),
    ]
    rows = []
    for c in results.cases:
        p = c.pivot
        if p is None:
            continue
        name = label(c) if callable(label) else c.name
        rows.append([name, lang.num(p.force, 0), lang.num(p.depth * 1e3, 0),
                     lang.num(p.depth_ratio, 3), lang.num(p.pivot_shift * 1e3, 1),
                     modes_text(c, lang)])  # fmt: skip
    return TableData(header, rows)


def weaker_notes(results: Results, lang: Lang, label: object = None) -> list[str]:
    """One sentence for every option weaker than the one with the next lower ratio (same
    material and position) whose records end mostly in crushing: why more bars gave less."""
    groups: dict[tuple[str | None, str | None], list[CaseResult]] = {}
    for c in results.options:
        groups.setdefault((c.material, c.position), []).append(c)
    out = []
    for cases in groups.values():
        cases.sort(key=lambda c: c.ratio)
        for low, high in pairwise(cases):
            crushed = sum(1 for r in high.records if r.failure_mode in CRUSHING)
            if high.design_a_dyn < low.design_a_dyn and 2 * crushed > len(high.records):
                name = label if callable(label) else (lambda c: c.name)
                out.append(lang.t("pivot.weaker", high=name(high), low=name(low),
                                  a_high=lang.num(high.design_a_dyn, 3),
                                  a_low=lang.num(low.design_a_dyn, 3), n=crushed,
                                  m=len(high.records)))  # fmt: skip
    return out
