"""The opening sections of the report, in the order Italian reviewers expect (the same for
every language): title, introduction and scope, codes, the wall, the category of the
intervention, knowledge level and confidence factor, materials.  Every word comes from the
language's catalogue (:mod:`frp_assess.report.lang`); every number from the results."""

from __future__ import annotations

from reportlab.lib.units import mm

from frp_assess.report.doc_model import Block, Heading
from frp_assess.report.flow import esc, grid, h1, h2, key_value, markup
from frp_assess.report.formats import TableData, design_strain
from frp_assess.report.lang import Lang, short
from frp_assess.results.carried_loads import TieOptionResult, TieResult
from frp_assess.results.model import AssessmentResult
from frp_assess.rules.intervention import (
    IMPROVEMENT_INCREASE,
    IMPROVEMENT_MINIMUM,
    UPGRADE_ZETA,
    improvement_has_minimum,
)
from frp_assess.text_safety import Markup

Results = AssessmentResult


def mechanism_words(results: Results, lang: Lang) -> str:
    """The rocking mechanism of the wall in words."""
    key = "mech." + results.wall.mechanism
    return lang.t(key) if lang.has(key) else esc(results.wall.mechanism)


def position_words(position: str | None, lang: Lang, *, short: bool = False) -> str:
    """Where the bars are, in words (``short``: for a table column)."""
    key = f"pos.short.{position}" if short else f"pos.{position}"
    return lang.t(key) if position and lang.has(key) else esc(position or "—")


def tie_words(tie: TieResult, lang: Lang) -> str:
    """Tie-rods in words: their bar (Ø, else A_s), spacing and height."""
    bar = (
        f"Ø{lang.gnum(tie.diameter)} mm"
        if tie.diameter is not None
        else f"A<sub>s</sub> = {lang.num(tie.area, 1)} mm²"
    )
    return lang.t("option.words.tie", bar=bar, s=lang.gnum(tie.spacing), h=lang.gnum(tie.height))


def option_words(c: object, lang: Lang) -> str:
    """An option by its name as the user wrote it, then described from its fields:
    ``<name> (material, position of the bars, ratio ρ [‰])``; tie-rods (``tie``) by their
    bar, spacing and height, alone or after the bars."""
    material = esc(getattr(c, "material", None) or "")
    pos = position_words(getattr(c, "position", None), lang)
    words = lang.t("option.words", material=material, position=pos,
                   ratio=lang.num(float(getattr(c, "ratio", 0.0)), 2))  # fmt: skip
    tie = getattr(c, "tie", None)
    if isinstance(tie, TieOptionResult):
        ties = tie_words(tie.tie, lang)
        words = ties if not material else lang.t("option.words.both", bars=words, tie=ties)
    name = getattr(c, "name", None)
    return f"{esc(name)} ({words})" if name else words


def masonry_words(results: Results, lang: Lang) -> str:
    """The masonry in the report's language: the type of Circolare 2019 Tab. C8.5.I by its
    name in the catalogue (never the library key), else the description the run wrote."""
    key = results.wall.masonry
    if key and lang.has(f"masonry:{key}"):
        return lang.t("masonry.table", name=lang.t(f"masonry:{key}"))
    return results.wall.masonry_description or lang.t("wall.masonry_typed")


def knowledge(results: Results) -> tuple[str, float]:
    """(knowledge level, FC) of the run."""
    if results.masonry_strength is not None:
        ms = results.masonry_strength
        return ms.knowledge_level, ms.confidence_factor
    if results.kinematic_checks is not None:
        return results.kinematic_checks.knowledge_level, results.kinematic_checks.fc
    return results.code_check.confidence_factor_level, results.code_check.FC


def title(results: Results, lang: Lang) -> list[Block]:
    p = results.project
    who = " · ".join(esc(x) for x in (p.location, p.engineer) if x)
    return [
        Heading(p.name or lang.t("title.unnamed"), 0),
        markup(
            lang.t("title.subtitle")
            + "<br/>"
            + (who + " · " if who else "")
            + lang.t("title.results_of", date=esc(lang.date(results.created))),
            "subtitle",
        ),
    ]


def introduction(results: Results, lang: Lang) -> list[Block]:
    p = results.project
    out: list[Block] = [h1(lang.t("h.intro"))]
    out.append(
        markup(
            lang.t(
                "intro.object",
                wall=esc(p.name or lang.t("title.unnamed")),
                location=esc(p.location) if p.location else lang.t("intro.no_location"),
                n_options=len(results.options),
                kinds=lang.t(
                    "intro.kinds.ties"
                    if any(c.tie is not None for c in results.options)
                    else "intro.kinds.bars"
                ),
            )
        )
    )
    out.append(markup(lang.t("intro.scope")))
    if p.notes:
        out.append(markup(lang.t("intro.notes", notes=esc(p.notes, limit=4800))))
    return out


def codes(results: Results, lang: Lang) -> list[Block]:
    out: list[Block] = [h1(lang.t("h.codes")), markup(lang.t("codes.lead"))]
    for i in range(1, 6):
        out.append(markup("• " + lang.t(f"codes.{i}"), "bullet"))
    return out


def wall(results: Results, lang: Lang) -> list[Block]:
    w = results.wall
    n = lang.num
    masonry = masonry_words(results, lang)
    rows = [
        [lang.t("wall.B"), f"{n(w.thickness)} m"],
        [lang.t("wall.H"), f"{n(w.height)} m"],
        [lang.t("wall.L"), f"{n(w.length)} m"],
        [lang.t("wall.masonry"), masonry],
        [lang.t("wall.gamma"), f"{lang.gnum(w.unit_weight)} kN/m³"],
        [lang.t("wall.mass"), f"{n(w.mass, 0, grouping=True)} kg/m"],
        [lang.t("wall.mechanism"), mechanism_words(results, lang)],
        [lang.t("wall.alpha"), f"{n(w.alpha_deg)}°"],
        [lang.t("wall.a_rm"), f"{n(w.a_rm, 3)} g"],
    ]
    if results.building is not None:
        b = results.building
        rows.append([lang.t("wall.base"), f"Z = {n(b.wall_base)} m, H_b = {n(b.height)} m"])
    return [
        h1(lang.t("h.wall")),
        markup(lang.t("wall.lead", mechanism=mechanism_words(results, lang))),
        key_value(rows, sub_values=True, verbatim_rows=(3, 6)),
    ]


def category_paragraph(results: Results, lang: Lang) -> str:
    """What the category of the intervention (results.json ``intervention``, NTC 2018 §8.4)
    asks of an option, in the report's language; a file written before the key was judged
    as an upgrade."""
    iv = results.intervention
    if iv is None or iv.category == "upgrade":
        return lang.t("category.upgrade", required=lang.gnum(UPGRADE_ZETA),
                      target=lang.gnum(results.model.target))  # fmt: skip
    as_is = lang.num(iv.as_is_zeta, 2)
    if iv.category == "local":
        return lang.t("category.local", as_is=as_is)
    school = lang.t("category.school") if iv.school else ""
    if improvement_has_minimum(iv.use_class or "", iv.school):
        rule = lang.t("category.improvement.minimum", minimum=lang.gnum(IMPROVEMENT_MINIMUM))
    else:
        rule = lang.t("category.improvement.increase", as_is=as_is,
                      increase=lang.gnum(IMPROVEMENT_INCREASE))  # fmt: skip
    return lang.t("category.improvement", use_class=esc(iv.use_class or "—"), school=school,
                  required=lang.num(iv.required_zeta, 2), rule=rule)  # fmt: skip


def category(results: Results, lang: Lang) -> list[Block]:
    """The category of the intervention: what an option must reach, how the wall as it is
    is judged, and (local, improvement) what a time history's ζ_E is."""
    out: list[Block] = [h1(lang.t("h.category")), markup(category_paragraph(results, lang))]
    iv = results.intervention
    if iv is not None:
        out.append(markup(lang.t("category.as_is")))
    if iv is not None and iv.category != "upgrade":
        out.append(markup(lang.t("category.th_zeta")))
    out.append(markup(lang.t("category.global")))
    return out


def knowledge_section(results: Results, lang: Lang) -> list[Block]:
    level, fc = knowledge(results)
    out: list[Block] = [h1(lang.t("h.knowledge"))]
    out.append(markup(lang.t("knowledge.level", level=esc(level), fc=lang.gnum(fc))))
    ida_fc = results.urm.fc
    if ida_fc == 1.0 and fc != 1.0:
        out.append(markup(lang.t("knowledge.ida_without_fc")))
    else:
        out.append(markup(lang.t("knowledge.ida_with_fc", fc=lang.gnum(ida_fc))))
    piv = results.urm.pivot
    edge = piv is None or piv.model_pivot == "edge"
    key = "knowledge.rigid_block_edge" if edge and level != "LC1" else "knowledge.rigid_block"
    out.append(markup(lang.t(key, fc=lang.gnum(fc), level=esc(level)), "small"))
    return out


def materials(results: Results, lang: Lang) -> list[Block]:
    n = lang.num
    w = results.wall
    out: list[Block] = [h1(lang.t("h.materials")), h2(lang.t("h.materials.masonry"))]
    rows = [
        [lang.t("wall.masonry"), masonry_words(results, lang)],
        [lang.t("wall.gamma"), f"{lang.gnum(w.unit_weight)} kN/m³"],
    ]
    ms = results.masonry_strength
    if ms is not None:
        rows += [
            [lang.t("mat.f_m"), f"{n(ms.f_m)} MPa"],
            [lang.t("mat.fc"), f"{lang.gnum(ms.confidence_factor)} ({esc(ms.knowledge_level)})"],
            [lang.t("mat.f_d"), f"{n(ms.f_d)} MPa"],
        ]
    out.append(key_value(rows, verbatim_rows=(0,)))
    out.append(h2(lang.t("h.materials.frp")))
    cur = short(results.costs.currency)
    header = [
        lang.t("mat.col.name"),
        lang.t("mat.col.E"),
        Markup(lang.t("mat.col.eps_u")),
        lang.t("mat.col.density"),
        lang.t("mat.col.price", currency=cur),
    ]
    body = [
        [
            name,
            n(m.elastic_modulus, 0),
            n(1e3 * m.ultimate_strain, 1),
            n(m.density, 0, grouping=True),
            n(m.price, 2),
        ]
        for name, m in results.materials.items()
    ]
    out.append(
        grid(TableData(header, body), [60 * mm, 26 * mm, 26 * mm, 30 * mm, 32 * mm], wrap=(0,))
    )
    rs = rupture_strain_text(results, lang)
    out.append(markup(lang.t("mat.note", rupture=rs), "caption"))
    return out


def rupture_strain_text(results: Results, lang: Lang) -> str:
    """The rupture strain of the model as the run computed it: ε_max = c·ε_u (mean values)
    or c·η_a·ε_fk/γ_f (design values), with c of the run."""
    c = lang.gnum(results.model.strain_factor)
    key = "mat.rupture.design" if design_strain(results) else "mat.rupture.mean"
    return lang.t(key, c=c)
