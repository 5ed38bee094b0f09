"""A building's report as a document model (:mod:`frp_assess.report.doc_model`): the summary
of its walls first (ζ_E of every check, the verdicts, the proposed retrofits, the totals and
the governing mechanism), then where each wall's full report is.

Built from the building's results alone (:class:`~frp_assess.results.building_summary.
BuildingResults`), in the report's language; its words are the catalogues
``catalogue/building-<code>.json`` (beside the report's, as the loads' are).
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

from frp_assess.report.doc_model import Block, Document, Gap, Heading, Para, Table, split_sections
from frp_assess.report.document import number_headings
from frp_assess.report.flow import esc
from frp_assess.report.lang import Lang
from frp_assess.report.styles import FRAME_WIDTH
from frp_assess.results.building_summary import CHECK_COLUMNS, BuildingResults, WallSummary
from frp_assess.results.verdict_words import governing_short, in_language

__all__ = ["building_document", "words"]


@cache
def words(code: str) -> dict[str, str]:
    """The strings of a building's report in language ``code`` (key → template)."""
    text = resources.files("frp_assess.report").joinpath("catalogue", f"building-{code}.json")
    data = json.loads(text.read_text(encoding="utf-8"))
    return {k: v for k, v in data.items() if not k.startswith("//")}


def _t(lang: Lang, key: str, **values: object) -> str:
    return words(lang.code)[key].format(**values)


def _num(lang: Lang, x: float | None, decimals: int) -> str:
    return lang.num(x, decimals)


def check_rows(b: BuildingResults, lang: Lang) -> list[tuple[str, ...]]:
    """One row per wall: its name, α₀, a₀* [g], ζ_E of every check and the governing one."""
    rows = []
    for w in b.walls:
        z = w.unreinforced
        rows.append(
            (
                w.name,
                _num(lang, w.alpha0, 3),
                _num(lang, w.a0_star, 3),
                *(_num(lang, getattr(z, key), 2) for key, _ in CHECK_COLUMNS),
                governing_short(z.governing_check),
            )
        )
    return rows


def _proposed(w: WallSummary, lang: Lang) -> str:
    if not w.retrofit_required:
        return _t(lang, "proposed.none_needed")
    if w.proposed is None:
        if w.closest is not None:
            return _t(lang, "proposed.none_passes", closest=w.closest)
        return _t(lang, "proposed.none")
    if w.bars is None:
        return w.proposed
    b = w.bars
    where = _t(lang, "bars.centred" if b.lines == 1 else "bars.external", lines=b.lines)
    bars = _t(
        lang,
        "bars",
        per_line=b.bars_per_line,
        d=lang.gnum(b.diameter),
        where=where,
        s=lang.num(b.spacing, 3),
        total=b.total_bars,
        installed=lang.num(b.ratio_installed, 2),
        asked=lang.num(b.ratio_asked, 2),
    )
    return f"{w.proposed}: {bars}"


def retrofit_rows(b: BuildingResults, lang: Lang) -> list[tuple[str, ...]]:
    """One row per wall (verdict as it is, the proposed retrofit with its bars, verdict
    retrofitted, FRP mass [kg], cost), and the building's totals."""
    rows: list[tuple[str, ...]] = []
    for w in b.walls:
        rows.append(
            (
                w.name,
                _t(lang, f"verdict.{w.verdict_before}"),
                _proposed(w, lang),
                _t(lang, f"verdict.{w.verdict_after}"),
                "—" if w.frp_mass is None else lang.num(w.frp_mass, 1),
                "—" if w.cost is None else lang.num(w.cost, 0, grouping=True),
            )
        )
    tot = b.totals
    rows.append(
        (
            _t(lang, "row.total"),
            "",
            "",
            "",
            lang.num(tot.frp_mass, 1),
            lang.num(tot.cost, 0, grouping=True),
        )
    )
    return rows


def _totals(b: BuildingResults, lang: Lang) -> list[Block]:
    tot = b.totals
    unsolved = ""
    if tot.walls_without_solution:
        unsolved = _t(lang, "totals.unsolved", n=tot.walls_without_solution)
    out: list[Block] = [
        Para(
            _t(
                lang,
                "totals",
                walls=tot.walls,
                failing=tot.walls_failing,
                retrofitted=tot.walls_retrofitted,
                mass=lang.num(tot.frp_mass, 1),
                cost=lang.num(tot.cost, 0, grouping=True),
                currency=esc(tot.currency),
                unsolved=unsolved,
            )
        )
    ]
    if tot.governing_margin is None:
        out.append(Para(_t(lang, "governing.unbounded", wall=esc(tot.governing_wall))))
    else:
        check = in_language(tot.governing_check or "", lang.code)
        out.append(
            Para(
                _t(
                    lang,
                    "governing",
                    wall=esc(tot.governing_wall),
                    check=esc(check),
                    margin=lang.num(tot.governing_margin, 2),
                )
            )
        )
    failing = [esc(w.name) for w in b.walls if not w.input_code_compliant]
    if failing:
        out.append(Para(_t(lang, "noncompliant", walls=", ".join(failing)), "verdict_bad"))
    return out


def building_blocks(b: BuildingResults, lang: Lang) -> list[Block]:
    """The report's blocks: title, the summary (checks, verdicts and retrofits, totals),
    the walls' reports (headings not numbered yet)."""
    p = b.project
    checks_header = (
        _t(lang, "col.wall"),
        _t(lang, "col.alpha0"),
        _t(lang, "col.a0"),
        *(_t(lang, f"col.{key}") for key, _ in CHECK_COLUMNS),
        _t(lang, "col.governing"),
    )
    name_w = 0.22 * FRAME_WIDTH
    governing_w = 0.14 * FRAME_WIDTH
    rest = (FRAME_WIDTH - name_w - governing_w) / (len(checks_header) - 2)
    retrofit_header = (
        _t(lang, "col.wall"),
        _t(lang, "col.before"),
        _t(lang, "col.proposed"),
        _t(lang, "col.after"),
        _t(lang, "col.mass"),
        _t(lang, "col.cost", currency=b.totals.currency),
    )
    small = 0.11 * FRAME_WIDTH
    proposed_w = FRAME_WIDTH - name_w - 4 * small
    return [
        Heading(_t(lang, "doc.title", name=p.name), 0),
        Para(esc(_t(lang, "title.subtitle")), "subtitle"),
        Para(
            esc(
                _t(
                    lang,
                    "title.where",
                    location=p.location or "—",
                    engineer=p.engineer or "—",
                    date=lang.date(b.created),
                )
            ),
            "small",
        ),
        Heading(_t(lang, "h.summary"), 1),
        Para(_t(lang, "summary.lead")),
        Table(
            "grid",
            checks_header,
            tuple(check_rows(b, lang)),
            (name_w, *([rest] * (len(checks_header) - 2)), governing_w),
            wrap=(0,),
            small=True,
        ),
        Para(_t(lang, "summary.cols"), "caption"),
        Gap(),
        Heading(_t(lang, "h2.retrofit"), 2),
        Para(_t(lang, "retrofit.lead")),
        Table(
            "grid",
            retrofit_header,
            tuple(retrofit_rows(b, lang)),
            (name_w, small, proposed_w, small, small, small),
            wrap=(0, 1, 2, 3),
            small=True,
            numeric_from=4,
            highlight_rows=(len(b.walls),),
        ),
        Gap(),
        *_totals(b, lang),
        Heading(_t(lang, "h.walls"), 1),
        Para(_t(lang, "walls.lead")),
        *(
            Para(_t(lang, "walls.item", wall=esc(w.name), folder=esc(w.folder)), "bullet")
            for w in b.walls
        ),
    ]


def building_document(b: BuildingResults, language: str) -> Document:
    """The building's report as a document model, in ``language`` (en, it)."""
    lang = Lang(language)
    sw = b.software
    return Document(
        title=_t(lang, "doc.title", name=b.project.name),
        header=_t(lang, "doc.header"),
        footer=lang.t("doc.footer", software=sw.name, version=sw.version, date=lang.date(b.created))
        + f" · {b.input_file}",
        page_word=lang.t("doc.page", n="{n}", total="{total}"),
        author=b.project.engineer,
        language=lang.code,
        sections=split_sections(number_headings(building_blocks(b, lang))),
    )
