"""The report's part for the loads a wall carries (docs/model.md §12, both languages): every
load with its lever arm and whether its mass moves with the wall, each tie's per-metre values,
α₀ of Circolare 2019 eq. C8.7.1.1 term by term, so that a reviewer recomputes it by hand, and
the assumptions §12 does not model.

Pure functions of results.json's ``loads`` (:class:`~frp_assess.results.carried_loads.
LoadsResult`); each returns nothing without loads.  The words are in this part's own
catalogues, ``catalogue/loads-<code>.json``, beside the report's.
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

from reportlab.lib.units import mm

from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, grid, h1, h2, markup
from frp_assess.report.formats import TableData
from frp_assess.report.lang import Lang
from frp_assess.results.carried_loads import (
    BASE_REACTION,
    WALL_WEIGHT,
    LoadsResult,
    MomentTerm,
    TieResult,
)
from frp_assess.results.model import AssessmentResult

#: how many assumptions this part adds (loads.assume.1 ...)
ASSUMPTIONS = 4


@cache
def words(code: str) -> dict[str, str]:
    """The strings of this part in language ``code`` (key → template)."""
    text = resources.files("frp_assess.report").joinpath("catalogue", f"loads-{code}.json")
    data = json.loads(text.read_text(encoding="utf-8"))
    return {k: v for k, v in data.items() if not k.startswith("//")}


def t(lang: Lang, key: str, **values: object) -> str:
    """The string ``key`` of this part in ``lang``, ``values`` (escaped already) filled in."""
    return words(lang.code)[key].format(**values)


def _rows(loads: LoadsResult, lang: Lang) -> list[list[str]]:
    """The loads' table rows (cells are plain text: the table escapes them)."""
    n = lang.num
    rows = [
        [p.name, t(lang, "loads.kind.top"), n(p.load, 2),
         t(lang, "loads.lever.top", d=n(p.distance, 3)), t(lang, f"loads.mass.{p.inertia}")]
        for p in loads.top
    ]  # fmt: skip
    rows += [
        [f.name, t(lang, "loads.kind.thrust"), n(f.force, 2),
         t(lang, "loads.lever.height", h=n(f.height, 3)), t(lang, "loads.mass.none")]
        for f in loads.thrust
    ]  # fmt: skip
    rows += [
        [x.name, t(lang, "loads.kind.tie"), n(x.capacity, 2),
         t(lang, "loads.lever.height", h=n(x.height, 3)), t(lang, "loads.mass.none")]
        for x in loads.ties
    ]  # fmt: skip
    return rows


def tie_paragraph(x: TieResult, lang: Lang) -> Block:
    """One tie as given and per metre of wall (k_t, F_y, F_a/i_t), ductile or brittle."""
    n = lang.num
    anchorage = (
        t(lang, "loads.tie.no_anchorage")
        if x.anchorage is None
        else t(lang, "loads.tie.anchorage", Fa=lang.gnum(x.anchorage))
    )
    per_metre = "∞" if x.anchorage_force is None else f"{n(x.anchorage_force, 2)} kN/m"
    return markup(
        t(lang, "loads.tie", name=esc(x.name), area=n(x.area, 1), spacing=lang.gnum(x.spacing),
          length=lang.gnum(x.length), fy=lang.gnum(x.yield_strength),
          E=lang.gnum(x.elastic_modulus), anchorage=anchorage, k=n(x.stiffness, 0, grouping=True),
          Fy=n(x.yield_force, 2), Fa=per_metre,
          kind=t(lang, "loads.tie.ductile" if x.ductile else "loads.tie.brittle"))
    )  # fmt: skip


def _term_name(term: MomentTerm, lang: Lang) -> str:
    if term.name == WALL_WEIGHT:
        return t(lang, "loads.term.weight")
    if term.name == BASE_REACTION:
        return t(lang, "loads.term.base")
    return term.name


def section(results: AssessmentResult, lang: Lang) -> list[Block]:
    """'Loads on the wall': the loads, the ties, α₀ term by term; nothing without loads."""
    loads = getattr(results, "loads", None)
    if loads is None:
        return []
    n = lang.num
    header = [t(lang, f"loads.col.{c}") for c in ("load", "kind", "force", "lever", "mass")]
    out: list[Block] = [
        h1(t(lang, "h.loads")),
        markup(t(lang, "loads.lead")),
        grid(TableData(header, _rows(loads, lang)), [x * mm for x in (40, 38, 26, 30, 30)],
             numeric_from=2),
    ]  # fmt: skip
    out += [tie_paragraph(x, lang) for x in loads.ties]
    if loads.ties:
        out.append(markup(t(lang, "loads.tie.dynamics")))
    o = loads.overturning
    terms = [
        [_term_name(x, lang), t(lang, f"loads.role.{x.role}"), n(x.force, 2),
         n(x.lever, 3), n(x.moment, 3)]
        for x in o.terms
    ]  # fmt: skip
    header = [t(lang, f"loads.col.{c}") for c in ("term", "role", "force", "lever", "moment")]
    out += [
        h2(t(lang, "h.loads.alpha0")),
        markup(t(lang, "loads.alpha0.lead")),
        grid(TableData(header, terms), [x * mm for x in (52, 30, 26, 24, 32)], wrap=(0,),
             numeric_from=2),
        markup(t(lang, "loads.alpha0.sum", stab=n(o.stabilising, 3), over=n(o.overturning, 3),
                 work=n(o.internal_work, 3), inertia=n(o.inertia, 3), alpha0=n(o.alpha0, 4),
                 bare=n(o.alpha0_without_ties, 4), e=n(o.e_star, 3),
                 m=n(o.m_star, 0, grouping=True))),
    ]  # fmt: skip
    return out


def assumptions(results: AssessmentResult, lang: Lang) -> list[Block]:
    """The bullets of what docs/model.md §12 does not model; nothing without loads."""
    if getattr(results, "loads", None) is None:
        return []
    return [
        markup("• " + t(lang, f"loads.assume.{i}"), "bullet") for i in range(1, ASSUMPTIONS + 1)
    ]
