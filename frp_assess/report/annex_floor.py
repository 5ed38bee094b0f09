"""The annex's parts for issue 15, in the report's language: the wall above ground, its floor
spectra, the code's kinematic checks and their verdicts in the summary.

Pure functions of the typed results (:class:`~frp_assess.results.model.AssessmentResult`):
``building`` and ``floor_spectra`` (a wall above ground) and ``kinematic_checks``
(docs/results-json.md).  Each returns nothing when the results lack its part (a results.json
of a wall at ground level, or one written before the checks existed).

Units: accelerations in g, periods in s, heights in m.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from reportlab.graphics.shapes import Drawing
from reportlab.lib.units import mm

from frp_assess.numbers import check_verdicts
from frp_assess.report import charts
from frp_assess.report import styles as st
from frp_assess.report.annex_checks import checks_section
from frp_assess.report.annex_design_tables import case_label
from frp_assess.report.charts import localize_drawing
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, esc, figure, h2, keep, key_value, markup
from frp_assess.report.formats import run_words
from frp_assess.report.lang import Lang
from frp_assess.results.checks import CaseChecks
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult
#: the code's floor spectrum line (and the ground spectrum, lighter and dotted)
CODE_FLOOR = st.TARGET
GROUND = st.MUTED


def floor_sentence(results: Results, lang: Lang) -> str | None:
    """One paragraph (report markup): the wall was shaken by the floor motion at Z, and
    a_dyn and capacity/demand are in ground terms; None at ground level."""
    b = results.building
    if b is None:
        return None
    said = run_words(b.shaken_by, lang)
    if said is not None:
        shaken = esc(said[:1].upper() + said[1:]) + "."
    else:
        shaken = lang.t("ax.floor.shaken", z=lang.gnum(b.wall_base))
    text = lang.t("ax.floor.lead", shaken=shaken)
    ratios = [
        r.floor_pga / r.pga
        for r in results.cases[0].records
        if r.floor_pga is not None and r.pga > 0.0
    ]
    if ratios:
        text += lang.t("ax.floor.ratios", lo=lang.num(min(ratios), 2), hi=lang.num(max(ratios), 2))
    return text


def floor_rows(results: Results, lang: Lang) -> list[list[str]]:
    """'quantity | value' rows of the building (empty at ground level)."""
    b = results.building
    if b is None:
        return []
    n = lang.num
    if abs(b.period - b.period_default) <= 1e-9 * b.period_default:
        period_note = lang.t("ax.floor.period.default")
    else:
        period_note = lang.t("ax.floor.period.given", t=n(b.period_default, 3))
    return [
        [lang.t("ax.floor.height"), f"{lang.gnum(b.height)} m"],
        [lang.t("ax.floor.storeys"), f"{b.storeys}"],
        [lang.t("ax.floor.base"), f"{lang.gnum(b.wall_base)} m (Z/H_b = {n(b.z_over_h, 3)})"],
        [lang.t("ax.floor.period"), f"{n(b.period, 3)} s{period_note}"],
        [lang.t("ax.floor.damping"), f"{lang.gnum(100 * b.damping)} %"],
        [lang.t("ax.floor.gamma"), n(b.gamma1, 3)],
        [lang.t("ax.floor.psi"), n(b.psi1, 3)],
    ]


@dataclass(frozen=True)
class LinearSummary:
    """The linear kinematic check of the unreinforced wall as page 1 states it: a0* and the
    demand [g], their ratio [-], the verdict."""

    a0_star: float
    demand: float
    ratio: float
    passed: bool


def linear_check(results: Results) -> LinearSummary:
    """The unreinforced wall's linear check: from ``kinematic_checks`` when present (the
    demand a_Z/q at the wall's base above ground), else from ``code_check`` (a_g·S/q)."""
    kc = results.kinematic_checks
    if kc is not None and kc.cases:
        lin = kc.cases[0].linear
        return LinearSummary(lin.a0_star, lin.demand, lin.zeta_e, lin.passed)
    k = results.code_check
    return LinearSummary(k.a0_star, k.demand, k.ratio, k.passed)


def floor_spectra_chart(
    results: Results, lang: Lang, *, width: float = st.FRAME_WIDTH, height: float = 220
) -> Drawing | None:
    """The records' floor spectra and their mean beside the code's floor spectrum at Z and
    the ground spectrum, Sa [g] against T [s] (log scale), 5 % damping; None without them."""
    fs = results.floor_spectra
    if fs is None or not fs.periods:
        return None
    keep = [i for i, t in enumerate(fs.periods) if t > 0.0]
    periods = [fs.periods[i] for i in keep]

    def sel(vals: Sequence[float]) -> list[float]:
        return [float(vals[i]) for i in keep]

    records = [sel(r) for r in fs.records]
    mean, code, ground = sel(fs.mean), sel(fs.code), sel(fs.ground)
    d = charts.new_drawing(width, height)
    x0, y0 = 46.0, 34.0
    w, h = width - x0 - 150, height - y0 - 10
    xlim = (min(periods), max(periods))
    top = max([*mean, *code, *ground, *(v for r in records for v in r)], default=1.0)
    ylo, yhi, yticks = charts.nice_range(0.0, top * 1.05)
    ax = charts.Axes(d, x0, y0, w, h, xlim, (ylo, yhi), xlog=True)
    ax.frame(
        "period T [s] (log scale)", "spectral acceleration Sa [g]", charts.log_ticks(*xlim), yticks
    )
    for r in records:
        ax.line(periods, r, color=st.RECORD_LINE, width=0.6)
    ax.line(periods, ground, color=GROUND, width=0.9, dash=[1.5, 2])
    ax.line(periods, code, color=CODE_FLOOR, width=1.6)
    ax.line(periods, mean, color=st.MEAN_LINE, width=1.4, dash=[5, 2])
    charts.legend(
        d,
        x0 + w + 14,
        y0 + h - charts.FS,
        [
            (lang.t("ax.floor.chart.code"), {"color": CODE_FLOOR, "width": 1.6}),
            (
                lang.t("ax.floor.chart.mean", n=len(records)),
                {"color": st.MEAN_LINE, "width": 1.4, "dash": [5, 2]},
            ),
            (lang.t("ax.floor.chart.each"), {"color": st.RECORD_LINE, "width": 0.8}),
            (lang.t("ax.floor.chart.ground"), {"color": GROUND, "width": 0.9, "dash": [1.5, 2]}),
        ],
    )
    return localize_drawing(d, lang)


def floor_motion_part(results: Results, lang: Lang, number: str = "3.4") -> list[Block]:
    """The subsection on the floor motion (heading, sentence, building, chart); [] at ground
    level."""
    sentence = floor_sentence(results, lang)
    if sentence is None:
        return []
    out: list[Block] = [
        cond_break(70 * mm),
        h2(f"{number}  " + lang.t("ax.h.floor")),
        markup(sentence),
        key_value(floor_rows(results, lang), sub_values=True),
    ]
    chart = floor_spectra_chart(results, lang)
    if chart is not None:
        out.append(keep([figure(chart), markup(lang.t("ax.floor.caption"), "caption")]))
    return out


def checks_part(results: Results, lang: Lang, number: str = "4.4") -> list[Block]:
    """The subsection of the code's kinematic checks of every case (Circolare 2019 §C8.7.1):
    heading and :func:`~frp_assess.report.annex_checks.checks_section`; [] without them."""
    blocks = checks_section(results, lang)
    if not blocks:
        return []
    return [cond_break(90 * mm), h2(f"{number}  " + lang.t("ax.h.checks")), *blocks]


def checks_line(checks: CaseChecks, lang: Lang) -> str:
    """ "passes …; fails …" for one case (a list is left out when empty)."""
    verdicts = [(lang.t("ax.check." + name.replace(" ", "_")), ok)
                for name, ok in check_verdicts(checks)]  # fmt: skip
    passed = [name for name, ok in verdicts if ok]
    failed = [name for name, ok in verdicts if not ok]
    parts = []
    if passed:
        parts.append(lang.t("ax.checks.passes", names=", ".join(passed)))
    if failed:
        parts.append(lang.t("ax.checks.fails", names=", ".join(failed)))
    return "; ".join(parts)


def _best_role(results: Results, best: CaseResult) -> str:
    """How the summary names the rank-1 option beside its checks (a catalogue key)."""
    chosen = results.recommended == best.name
    compliant = results.input_code_compliant
    if chosen and not results.retrofit_required:  # the wall passes unreinforced
        return "ax.checks.role.no_retrofit"
    if chosen and compliant:
        return "ax.checks.role.recommended"
    if results.recommended is None and compliant:
        return "ax.checks.role.closest"
    return "ax.checks.role.best" if compliant else "ax.checks.role.not_compliant"


def checks_verdict_lines(results: Results, lang: Lang) -> list[Block]:
    """For the summary: which code checks pass and which fail, for the unreinforced wall and
    the rank-1 option (linear, nonlinear SLV/SLC, time history, IDA); [] without them."""
    kc = results.kinematic_checks
    if kc is None or not kc.cases:
        return []
    by_name = {c.case: c for c in kc.cases}
    rows = [(case_label(results.urm, lang), checks_line(kc.cases[0], lang))]
    best = next((c for c in results.cases if c.rank == 1), None)
    if best is not None and best.name in by_name:
        label = lang.t(_best_role(results, best), case=case_label(best, lang))
        rows.append((label, checks_line(by_name[best.name], lang)))
    out: list[Block] = [
        markup(lang.t("ax.checks.lead", fc=lang.gnum(kc.fc), ags=lang.num(kc.a_g, 3)))
    ]
    out += [markup(f"<b>{esc(label)}</b>: {esc(line)}.", "bullet") for label, line in rows]
    return out
