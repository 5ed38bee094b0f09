"""The annex's tables of every case (the collapse acceleration under every accelerogram,
the scatter), of the design mode, of the model conventions (sensitivity) and of the anchorage
of the bars, in the report's language.  Words from the catalogue, numbers from the results;
the English free text the run writes (the design mode's note, a convention's label) is
rebuilt from the values (the design mode's note is shown in an English report only)."""

from __future__ import annotations

from collections.abc import Callable

from frp_assess.report.body_front import position_words
from frp_assess.report.formats import TableData, shows_run_prose
from frp_assess.report.lang import Lang, short
from frp_assess.report.verdict_text import (
    collapse_probability,
    convention_cells,
    probability_text,
    variant_words,
)
from frp_assess.results.as_built import AsBuilt
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.text_safety import Markup

Results = AssessmentResult


def case_label(c: CaseResult, lang: Lang) -> str:
    """A case in a table: the wall as it is, or the option's name as the user wrote it (the
    project file's ``interventions[].name``, whatever the report's language; its material,
    position and ρ are in the ranking)."""
    if c.is_unreinforced:
        return lang.t("annex.urm")
    return c.name


def cases(results: Results) -> list[CaseResult]:
    """The wall as it is, then the options by rank."""
    return [results.urm, *results.ranked_options]


def a_dyn_table(
    results: Results, lang: Lang, label: Callable[[CaseResult], str] | None = None
) -> TableData:
    """a_dyn [g] of every case and record, the wall as it is first, then by rank
    (``label(case)`` names a case; default :func:`case_label`)."""
    name_of = label or (lambda c: case_label(c, lang))
    names = [r.name for r in results.records]
    rows = []
    for c in cases(results):
        by_rec = {r.record: r for r in c.records}
        cells = []
        for name in names:
            r = by_rec.get(name)
            if r is None:
                cells.append("—")
            else:
                cells.append(lang.t("annex.nc") if r.a_dyn is None else lang.num(r.a_dyn, 3))
        rows.append([name_of(c), *cells])
    return TableData([lang.t("annex.col.option"), *names], rows)


def scatter_table(
    results: Results, lang: Lang, label: Callable[[CaseResult], str] | None = None
) -> TableData:
    """Record-to-record scatter of a_dyn and the lognormal fragility of every case (the wall
    as it is first, then by rank): mean, median, CoV, least favourable (record), fragility
    median, β and P(collapse) at FC·a_g·S; dashes where no lognormal was fitted.
    ``label(case)`` names a case (default :func:`case_label`)."""
    n = lang.num
    name = label or (lambda c: case_label(c, lang))
    header = [
        lang.t("annex.col.option"),
        Markup(lang.t("annex.col.mean")),
        Markup(lang.t("annex.col.median")),
        lang.t("annex.col.cov"),
        lang.t("annex.col.least"),
        lang.t("annex.col.frag_median"),
        "β [-]",
        Markup(lang.t("annex.col.pcollapse")),
    ]
    rows = []
    for c in cases(results):
        sc = c.scatter
        fr = sc.fragility
        at = collapse_probability(results, c)
        rows.append([name(c), n(c.mean_a_dyn, 3), n(sc.median_a_dyn, 3), n(sc.cov, 2),
                     f"{n(c.min_a_dyn, 3)} ({sc.least_favourable_record})",
                     "—" if fr is None else n(fr.median, 3),
                     "—" if fr is None else n(fr.beta, 2),
                     "—" if at is None else probability_text(at[1], lang)])  # fmt: skip
    return TableData(header, rows)


def design_table(results: Results, lang: Lang) -> TableData | None:
    """Design mode, one row per (material, position): the smallest ratio ρ [‰] that passes
    every deciding check, its capacity/demand, FRP mass [kg] and cost, and in an English report
    the run's one-line note; None when the design mode was not run."""
    if not results.design:
        return None
    n = lang.num
    notes = shows_run_prose(lang)
    header = [
        lang.t("annex.col.material"),
        lang.t("annex.col.position"),
        lang.t("annex.col.smallest"),
        lang.t("col.cd"),
        lang.t("col.mass"),
        lang.t("col.cost", currency=short(results.costs.currency)),
        *([lang.t("annex.col.note")] if notes else []),
    ]
    rows = [
        [
            d.material,
            position_words(d.position, lang, short=True),
            lang.t("annex.design.none") if d.ratio is None else n(d.ratio, 2),
            n(d.capacity_demand, 2),
            n(d.frp_mass, 1),
            n(d.frp_cost, 0, grouping=True),
            *([d.message or ""] if notes else []),
        ]
        for d in results.design
    ]
    return TableData(header, rows)


def sensitivity_table(results: Results, lang: Lang) -> TableData | None:
    """The assessed case under each model convention: design a_dyn [g], its change from the
    case as assessed [%], the IDA's capacity/demand [-], and the verdict of the deciding
    checks with the governing margin (so that a row whose IDA passes but whose verdict flips
    does not read as a pass); None when not computed."""
    sens = results.sensitivity
    if sens is None or not sens.rows:
        return None
    n = lang.num
    base = sens.rows[0].design_a_dyn
    header = [
        lang.t("annex.col.variant"),
        Markup("a<sub>dyn,d</sub> [g]"),
        lang.t("annex.col.change"),
        lang.t("col.cd"),
        lang.t("sens.col.verdict"),
        lang.t("sens.col.governing"),
    ]
    rows = []
    for r in sens.rows:
        ge = "≥ " if r.lower_bound else ""
        change = 100.0 * (r.design_a_dyn / base - 1.0)
        rows.append([
            variant_words(r.variant, lang),
            ge + n(r.design_a_dyn, 3),
            ("+" if change >= 0 else "") + n(change, 1),
            ge + n(r.capacity_demand, 2),
            *convention_cells(results, r.variant, lang),
        ])  # fmt: skip
    return TableData(header, rows)


def built(results: Results, lang: Lang) -> list[tuple[str, AsBuilt]]:
    """(label, bars as built) of every option with bars, then of every design-mode answer."""
    out = [(case_label(c, lang), c.as_built) for c in results.options if c.as_built is not None]
    for d in results.design or ():
        if d.as_built is not None:
            pos = position_words(d.position, lang, short=True)
            out.append((lang.t("annex.design.label", material=d.material, position=pos),
                        d.as_built))  # fmt: skip
    return out


def anchorage_table(results: Results, lang: Lang) -> TableData | None:
    """Per option and design answer: the design force per bar [kN], its bond length [m],
    the masonry pull-out cone [kN] and its verdict (a dash: not checked); None without bars."""
    items = built(results, lang)
    if not items:
        return None
    n = lang.num
    header = [
        lang.t("annex.col.option"),
        lang.t("annex.col.force"),
        lang.t("annex.col.bond"),
        lang.t("annex.col.cone"),
        lang.t("annex.col.cone_ok"),
    ]
    rows = []
    for label, b in items:
        a = b.anchorage
        ok = "—" if a.cone_ok is None else lang.t("ax.cone.ok" if a.cone_ok else "ax.cone.fails")
        rows.append([label, n(a.design_force, 1), n(a.length_required, 3),
                     n(a.cone_resistance, 1), ok])  # fmt: skip
    return TableData(header, rows)
