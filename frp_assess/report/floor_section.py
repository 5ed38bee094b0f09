"""The report's parts for issue 15: the wall above ground, its floor spectra, the code's
kinematic checks and their verdicts in the summary.

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

from frp_assess.numbers import checks_summary
from frp_assess.report import charts
from frp_assess.report import styles as st
from frp_assess.report.checks_section import checks_section
from frp_assess.report.doc_model import Block
from frp_assess.report.flow import cond_break, esc, figure, h2, keep, key_value, markup, para
from frp_assess.report.tables import fmt_acc
from frp_assess.results.model import AssessmentResult

Results = AssessmentResult
#: the code's floor spectrum line (and the ground spectrum, lighter and dotted)
CODE_FLOOR = st.TARGET
GROUND = st.MUTED


def floor_sentence(results: Results) -> str | None:
    """One paragraph (report markup): the wall was shaken by the floor motion at Z, and
    a_dyn and capacity/demand are in ground terms; None at ground level."""
    b = results.building
    if b is None:
        return None
    text = f"<b>Wall above ground.</b> {esc(b.shaken_by[:1].upper() + b.shaken_by[1:])}."
    ratios = [
        r.floor_pga / r.pga
        for r in results.cases[0].records
        if r.floor_pga is not None and r.pga > 0.0
    ]
    if ratios:
        text += (
            f" The floor motions' PGA is {min(ratios):.2f}–{max(ratios):.2f} times the ground "
            "records'."
        )
    return text


def floor_rows(results: Results) -> list[list[str]]:
    """'quantity | value' rows of the building (empty at ground level)."""
    b = results.building
    if b is None:
        return []
    period_note = (
        " (default C1·H_b^0.75, Circolare 2019 eq. C7.3.2)"
        if abs(b.period - b.period_default) <= 1e-9 * b.period_default
        else f" (given; the default C1·H_b^0.75 would be {b.period_default:.3f} s)"
    )
    return [
        ["building height H_b", f"{b.height:g} m"],
        ["storeys n", f"{b.storeys}"],
        ["height of the wall's base Z", f"{b.wall_base:g} m (Z/H_b = {b.z_over_h:.3f})"],
        ["first-mode period T_1", f"{b.period:.3f} s{period_note}"],
        ["first-mode damping ξ_1", f"{100 * b.damping:g} %"],
        ["participation factor γ_1 = 3n/(2n+1)", f"{b.gamma1:.3f}"],
        ["mode shape ψ_1(Z) = Z/H_b", f"{b.psi1:.3f}"],
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
    results: Results, *, width: float = st.FRAME_WIDTH, height: float = 220
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
            ("code floor spectrum at Z", {"color": CODE_FLOOR, "width": 1.6}),
            (
                f"mean of {len(records)} floor motions",
                {"color": st.MEAN_LINE, "width": 1.4, "dash": [5, 2]},
            ),
            ("each floor motion", {"color": st.RECORD_LINE, "width": 0.8}),
            ("ground spectrum (target)", {"color": GROUND, "width": 0.9, "dash": [1.5, 2]}),
        ],
    )
    return d


def floor_motion_part(results: Results, number: str = "3.4") -> list[Block]:
    """The subsection on the floor motion (heading, sentence, building, chart); [] at ground
    level."""
    sentence = floor_sentence(results)
    if sentence is None:
        return []
    out: list[Block] = [
        cond_break(70 * mm),
        h2(f"{number}  The motion at the wall's base: the floor at Z"),
        markup(sentence),
        key_value(floor_rows(results), sub_values=True),
    ]
    chart = floor_spectra_chart(results)
    if chart is not None:
        out.append(
            keep(
                [
                    figure(chart),
                    para(
                        "Figure 1b. Floor spectra at 5 % damping: each record's floor motion at Z "
                        "(first mode, as the IDA received it), their mean, the code's floor "
                        "spectrum at Z of the target ground spectrum (Circolare 2019 "
                        "eqs. C7.2.5–C7.2.9, a = 0.8, b = 1.1) and the ground spectrum.",
                        "caption",
                    ),
                ]
            )
        )
    return out


def checks_part(results: Results, number: str = "4.4") -> list[Block]:
    """The subsection of the code's kinematic checks of every case (Circolare 2019 §C8.7.1):
    heading and :func:`~frp_assess.report.checks_section.checks_section`; [] without them."""
    kc = results.kinematic_checks
    if kc is None:
        return []
    return [
        cond_break(90 * mm),
        h2(f"{number}  The code's kinematic checks of every case"),
        *checks_section(kc),
    ]


def checks_verdict_lines(results: Results) -> list[Block]:
    """For the summary: which code checks pass and which fail, for the unreinforced wall and
    the rank-1 option (linear, nonlinear SLV/SLC, time history, IDA); [] without them."""
    rows = checks_summary(results)
    if not rows:
        return []
    kc = results.kinematic_checks
    assert kc is not None
    out: list[Block] = [
        markup(
            "<b>The code's checks</b> (Circolare 2019 §C8.7.1, FC = "
            f"{kc.fc:g}, a<sub>g</sub>·S = {fmt_acc(kc.a_g)} g; section 4.4):"
        )
    ]
    for label, line in rows:
        out.append(markup(f"<b>{esc(label)}</b>: {esc(line)}.", "bullet"))
    return out
