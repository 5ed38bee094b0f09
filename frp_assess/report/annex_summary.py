"""The annex's summary (B.1) in the report's language: the wall, the site and the demand, the
wall as it is against the dynamic and the code's checks, the retrofit recommended (or the
closest), its alternatives and the short table.  Words from the catalogue (keys
``ax.sum.*``), numbers from the typed results."""

from __future__ import annotations

import math

from reportlab.lib.units import mm

from frp_assess.numbers import no_retrofit_caveats
from frp_assess.report.annex_design_tables import case_label
from frp_assess.report.annex_floor import checks_verdict_lines, floor_sentence, linear_check
from frp_assess.report.annex_input_tables import masonry_text, mechanism_text
from frp_assess.report.annex_result_tables import summary_table
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import esc, gap, grid, h1, markup, page_break
from frp_assess.report.formats import (
    bound,
    capacity_text,
    case_by_name,
    crushing_shift,
    ranked_options,
    run_words,
    shows_run_prose,
)
from frp_assess.report.lang import Lang
from frp_assess.report.verdict_text import governing, passes, robustness_lines, verdict_sentence
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.rules.record_sets import MEAN_OF_RECORDS_FROM

Results = AssessmentResult


def statistic_words(results: Results, lang: Lang) -> str:
    """What the design a_dyn is: the mean of the records or the least favourable one."""
    if results.design_is_mean:
        return lang.t("ax.sum.stat.mean")
    return lang.t("ax.sum.stat.least", n=MEAN_OF_RECORDS_FROM)


def _verdict(ok: bool, text: str) -> Block:
    return markup(text, "verdict_ok" if ok else "verdict_bad")


def option_sentence(results: Results, c: CaseResult, lang: Lang) -> str:
    """One option in a sentence: FRP, cost, capacity/demand, improvement, its checks and the
    bars as built."""
    n = lang.num
    lb = c.lower_bound
    target = float(results.model.target)
    parts = []
    if c.material is not None:
        parts.append(lang.t("ax.sum.option.frp", mass=n(c.frp_mass, 1), material=esc(c.material),
                            per_m=n(c.frp_mass_per_m, 1)))  # fmt: skip
    if c.tie is not None:
        parts.append(lang.t("ax.sum.option.tie", mass=n(c.tie.steel_mass, 1),
                            per_m=n(c.tie.steel_mass_per_m, 1)))  # fmt: skip
    text = lang.t(
        "ax.sum.option",
        name=esc(case_label(c, lang)),
        what=lang.t("ax.sum.option.and").join(parts),
        cost=n(c.option_cost, 0, grouping=True),
        cur=esc(results.costs.currency),
        cd=esc(bound(capacity_text(c, target, lang), lb)),
        improvement=esc(bound(n(c.improvement, 2), lb)),
    )
    if not passes(c):
        text += lang.t("ax.sum.option.fails", governing=governing(c, lang))
    text += "."
    note = run_words(c.as_built.note, lang) if c.as_built is not None else None
    if note is not None:
        text += " " + lang.t("ax.sum.option.built", note=esc(note))
    return text


def _wall(results: Results, lang: Lang) -> str:
    w = results.wall
    n = lang.num
    x_pivot = crushing_shift(results)
    if x_pivot is None:
        pivot = "."
    else:
        pivot = lang.t("ax.sum.wall.pivot", rest=n(x_pivot * 500, 0), x=n(x_pivot * 1000, 0),
                       tan=n(math.tan(w.alpha), 3))  # fmt: skip
    masonry = masonry_text(results, lang) if w.masonry_description or w.masonry else None
    masonry = masonry or lang.t("ax.sum.wall.masonry")
    if not shows_run_prose(lang):  # the catalogue's name of the type, inside a sentence
        masonry = masonry[:1].lower() + masonry[1:]
    return lang.t("ax.sum.wall", b=n(w.thickness, 2), h=n(w.height, 2), l=n(w.length, 2),
                  masonry=esc(masonry), w=lang.gnum(w.unit_weight),
                  mechanism=esc(mechanism_text(w.mechanism, lang)), alpha=n(w.alpha_deg, 2),
                  a_rm=n(w.a_rm, 3), pivot=pivot)  # fmt: skip


def _site(results: Results, lang: Lang) -> str:
    p = results.project
    s = results.seismic
    spectrum = s.spectrum.name
    kind = f"ax.records.{s.records_kind}"
    records = lang.t(kind) if lang.has(kind) else esc(s.records_kind)
    comp = "ax.sum.site.compliant" if results.compliance.passed else "ax.sum.site.not_compliant"
    return lang.t("ax.sum.site", site=esc(p.location) if p.location else lang.t("ax.sum.the_site"),
                  spectrum=esc(spectrum or ""), ags=lang.num(results.demand.pga, 3),
                  n=len(results.records), records=records) + lang.t(comp)  # fmt: skip


def _as_is(results: Results, lang: Lang) -> list[Block]:
    urm = results.urm
    n = lang.num
    target = results.model.target
    lb = urm.lower_bound
    cd = esc(bound(capacity_text(urm, float(target), lang), lb))
    ok = passes(urm)
    fc = lang.t("ax.sum.as_is.fc", fc=lang.gnum(urm.fc)) if urm.fc != 1.0 else "."
    out = [
        markup(
            lang.t(
                "ax.sum.as_is",
                n=len(results.records),
                a=esc(bound(n(urm.design_a_dyn, 3), lb)),
                stat=statistic_words(results, lang),
                cd=cd,
                fc=fc,
            )
        ),  # fmt: skip
        _verdict(
            ok,
            lang.t(
                "ax.sum.verdict.ok" if ok else "ax.sum.verdict.bad",
                sentence=verdict_sentence(urm, lang),
                cd=cd,
                target=lang.gnum(target),
            ),
        ),  # fmt: skip
    ]
    k = linear_check(results)
    verdict = lang.t("ax.sum.linear.pass" if k.passed else "ax.sum.linear.fail")
    out.append(markup(lang.t("ax.sum.linear", a0=n(k.a0_star, 3), demand=n(k.demand, 3),
                             ratio=n(k.ratio, 2), verdict=verdict), "small"))  # fmt: skip
    return out


def _retrofit(results: Results, lang: Lang) -> list[Block]:
    rec = case_by_name(results, results.recommended)
    ranked = [c for c in ranked_options(results) if c.rank is not None]  # not the dropped
    rule = run_words(results.ranking_rule, lang)
    out: list[Block] = []
    if not results.input_code_compliant:
        out.append(_verdict(False, lang.t("ax.sum.not_compliant")))
    if rec is not None and not results.input_code_compliant:
        out.append(markup(lang.t("ax.sum.best_ranked") + option_sentence(results, rec, lang)))
        if rule is not None:
            out.append(markup(lang.t("ax.sum.rule.first", rule=esc(rule)), "small"))
    elif rec is not None:
        if passes(results.urm):
            caveats = "".join(
                lang.t("ax.sum.caveat", caveat=esc(c))
                for c in no_retrofit_caveats(results)
                if run_words(c, lang) is not None
            )
            out.append(markup(lang.t("ax.sum.no_retrofit", caveats=caveats)
                              + option_sentence(results, rec, lang)))  # fmt: skip
        else:
            out.append(markup(lang.t("ax.sum.recommended") + option_sentence(results, rec, lang)))
        rule_words = lang.t("ax.sum.rule.words", rule=esc(rule)) if rule is not None else ""
        out.append(markup(lang.t("ax.sum.cheapest", governing=governing(rec, lang),
                                 rule=rule_words), "small"))  # fmt: skip
        out += [markup(line, "small") for line in robustness_lines(results, lang)]
        alts = [c for c in ranked if c is not rec][:3]
        if alts:
            out.append(markup(lang.t("ax.sum.alternatives")))
            out += [markup(option_sentence(results, c, lang), "bullet") for c in alts]
    elif ranked:
        out.append(_verdict(False, lang.t("ax.sum.none_passes")))
        out += [markup(option_sentence(results, c, lang), "bullet") for c in ranked[:3]]
    elif not results.options:
        out.append(markup(lang.t("ax.sum.no_options")))
    n_dropped = sum(1 for c in results.options if c.rank is None)
    if n_dropped:
        key = "ax.sum.dropped.one" if n_dropped == 1 else "ax.sum.dropped.many"
        out.append(markup(lang.t(key, n=n_dropped, total=len(results.options)), "small"))
    return out


def summary(results: Results, lang: Lang) -> list[Block]:
    """B.1: the summary of the calculation details."""
    out: list[Block] = [h1("1  " + lang.t("ax.h.summary")), markup(_wall(results, lang))]
    out.append(markup(_site(results, lang)))
    floor = floor_sentence(results, lang)
    if floor is not None:
        out.append(markup(floor))
    out += _as_is(results, lang)
    out += checks_verdict_lines(results, lang)
    out += _retrofit(results, lang)
    out.append(gap(4))
    rec = case_by_name(results, results.recommended)
    widths = [x * mm for x in (24, 31, 17, 17, 20, 17, 20, 24)]
    out.append(grid(summary_table(results, lang), widths, wrap=(0, 1), numeric_from=2,
                    highlight_rows=[1] if rec is not None else []))  # fmt: skip
    out.append(markup(lang.t("ax.sum.caption", cur=esc(results.costs.currency)), "caption"))
    out.append(page_break())
    return out
