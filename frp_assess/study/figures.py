"""Figures of a study like the paper's Figs. 8–16, and the study PDF (reportlab graphics).

Each figure plots a summary quantity (mean q, or the improvement) against H [m], one line per
value of one axis, the other axes held at the paper's reference case (one-sided, external,
α = 7.5°, spectrum A2, ρ = 1 ‰, CFRP) or at the first value the study has.  Every figure is
written as SVG (always) and PNG (when reportlab's renderPM backend, ``rlPyCairo``, is
installed), and all of them, with the comparison table, into ``study.pdf``; each file is
written atomically (:func:`frp_assess.io_utils.atomic_path`: a full disk leaves the old file
or none, never a half-written one).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from reportlab.graphics import renderSVG
from reportlab.graphics.charts.legends import LineLegend
from reportlab.graphics.charts.lineplots import LinePlot
from reportlab.graphics.shapes import Drawing, String
from reportlab.lib import colors
from reportlab.lib.pagesizes import A4
from reportlab.lib.styles import getSampleStyleSheet
from reportlab.lib.units import cm
from reportlab.platypus import Paragraph, SimpleDocTemplate, Spacer, Table, TableStyle

from frp_assess.io_utils import atomic_path
from frp_assess.study.comparison import compare
from frp_assess.study.rows import Row, read_summary

#: the reference value of each axis when it is held fixed (the paper's headline case)
REFERENCE: dict[str, str] = {
    "mechanism": "one-sided",
    "position": "external",
    "alpha_deg": "7.5",
    "spectrum": "A2",
    "ratio_permille": "1.0",
    "material": "CFRP",
}
LABELS = {
    "alpha_deg": "α = {}°",
    "spectrum": "{}",
    "mechanism": "{}",
    "ratio_permille": "ρ = {} ‰",
    "position": "{}",
    "material": "{}",
}
PALETTE = [
    colors.HexColor(c)
    for c in ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#17becf")
]


@dataclass(frozen=True)
class FigureSpec:
    """y against H, one line per value of ``by``; ``fixed`` axes held at the reference."""

    name: str
    title: str
    y: str  #: summary column
    y_label: str
    by: str
    reinforced: bool
    fixed: tuple[str, ...] = field(default=())


FIGURES: tuple[FigureSpec, ...] = (
    FigureSpec(
        "fig08-q-urm-alpha",
        "Unreinforced wall: q against H by α (cf. Fig. 8)",
        "mean_q",
        "mean q = a_dyn / a_RM [-]",
        "alpha_deg",
        False,
        ("mechanism", "spectrum"),
    ),
    FigureSpec(
        "fig09-q-urm-spectrum",
        "Unreinforced wall: q against H by spectrum (cf. Fig. 9)",
        "mean_q",
        "mean q [-]",
        "spectrum",
        False,
        ("mechanism", "alpha_deg"),
    ),
    FigureSpec(
        "fig10-q-urm-mechanism",
        "Unreinforced wall: q against H by mechanism (cf. Fig. 10)",
        "mean_q",
        "mean q [-]",
        "mechanism",
        False,
        ("alpha_deg", "spectrum"),
    ),
    FigureSpec(
        "fig11-q-rebars-ratio",
        "Restrained wall (CFRP external): q by ρ (cf. Fig. 11)",
        "mean_q",
        "mean q [-]",
        "ratio_permille",
        True,
        ("mechanism", "alpha_deg", "spectrum", "material", "position"),
    ),
    FigureSpec(
        "fig12-q-rebars-position",
        "Restrained wall (CFRP, ρ = 1 ‰): q by position (cf. Fig. 12)",
        "mean_q",
        "mean q [-]",
        "position",
        True,
        ("mechanism", "alpha_deg", "spectrum", "material", "ratio_permille"),
    ),
    FigureSpec(
        "fig13-improvement-ratio",
        "Improvement against H by ρ (GFRP external; cf. Fig. 13)",
        "improvement",
        "improvement I [-]",
        "ratio_permille",
        True,
        ("mechanism", "alpha_deg", "spectrum", "position", "material:GFRP"),
    ),
    FigureSpec(
        "fig14-improvement-alpha",
        "Improvement against H by α (CFRP external, ρ = 1 ‰; cf. Fig. 14)",
        "improvement",
        "improvement I [-]",
        "alpha_deg",
        True,
        ("mechanism", "spectrum", "position", "material", "ratio_permille"),
    ),
    FigureSpec(
        "fig15-improvement-spectrum",
        "Improvement against H by spectrum (CFRP external, ρ = 1 ‰; cf. Fig. 15)",
        "improvement",
        "improvement I [-]",
        "spectrum",
        True,
        ("mechanism", "alpha_deg", "position", "material", "ratio_permille"),
    ),
    FigureSpec(
        "fig16-improvement-material",
        "Improvement against H by material (external, ρ = 1 ‰; cf. Fig. 16)",
        "improvement",
        "improvement I [-]",
        "material",
        True,
        ("mechanism", "alpha_deg", "spectrum", "position", "ratio_permille"),
    ),
)


def _same(a: str, b: str) -> bool:
    try:
        return abs(float(a) - float(b)) < 1e-9
    except ValueError:
        return a == b


def figure_series(rows: Sequence[Row], spec: FigureSpec) -> dict[str, list[tuple[float, float]]]:
    """{line label: [(H [m], y)]} for ``spec``; fixed axes at the reference or first value."""
    pool = [r for r in rows if bool(r["material"]) == spec.reinforced]
    for item in spec.fixed:
        axis, _, forced = item.partition(":")
        values = [r[axis] for r in pool]
        if not values:
            return {}
        want = forced or REFERENCE.get(axis, values[0])
        if not any(_same(v, want) for v in values):
            want = values[0]
        pool = [r for r in pool if _same(r[axis], want)]
    lines: dict[str, list[tuple[float, float]]] = {}
    for r in pool:
        label = LABELS[spec.by].format(
            f"{float(r[spec.by]):g}" if spec.by.endswith(("_deg", "_permille")) else r[spec.by]
        )
        lines.setdefault(label, []).append((float(r["height_m"]), float(r[spec.y])))
    for pts in lines.values():
        pts.sort()
    return {k: v for k, v in lines.items() if len(v) >= 2}


def _nice_max(v: float) -> float:
    for step in (0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0):
        if v <= step * 6:
            return step * (int(v / step) + 1)
    return v * 1.1


def draw_figure(spec: FigureSpec, series: dict[str, list[tuple[float, float]]]) -> Drawing:
    """A reportlab Drawing of one figure (480 × 300 pt), axes labelled with units."""
    d = Drawing(480, 300)
    lp = LinePlot()
    lp.x, lp.y, lp.width, lp.height = 60, 50, 290, 210
    names = list(series)
    lp.data = [series[n] for n in names]
    xs = [x for pts in lp.data for x, _ in pts]
    ys = [y for pts in lp.data for _, y in pts]
    lp.xValueAxis.valueMin = min(xs)
    lp.xValueAxis.valueMax = max(xs)
    lp.xValueAxis.valueStep = 1.0
    lp.yValueAxis.valueMin = 0.0
    lp.yValueAxis.valueMax = _nice_max(max(ys))
    lp.yValueAxis.labelTextFormat = "%g"
    lp.xValueAxis.labelTextFormat = "%g"
    for i in range(len(names)):
        lp.lines[i].strokeColor = PALETTE[i % len(PALETTE)]
        lp.lines[i].strokeWidth = 1.5
        lp.lines[i].symbol = None
    d.add(lp)
    d.add(String(240, 285, spec.title, fontSize=10, textAnchor="middle"))
    d.add(String(205, 18, "wall height H [m]", fontSize=9, textAnchor="middle"))
    ylab = String(0, 0, spec.y_label, fontSize=9, textAnchor="middle")
    from reportlab.graphics.shapes import Group

    g = Group(ylab)
    g.translate(22, 155)
    g.rotate(90)
    d.add(g)
    legend = LineLegend()
    legend.x, legend.y = 365, 250
    legend.fontSize = 8
    legend.dx, legend.dy = 14, 2
    legend.deltay = 14
    legend.columnMaximum = 10
    legend.colorNamePairs = [(PALETTE[i % len(PALETTE)], n) for i, n in enumerate(names)]
    d.add(legend)
    return d


def _png(drawing: Drawing, path: Path) -> bool:
    try:
        from reportlab.graphics import renderPM

        with atomic_path(path) as tmp:
            renderPM.drawToFile(drawing, str(tmp), fmt="PNG", dpi=144)
        return True
    except Exception:  # renderPM needs the rlPyCairo backend, an optional package
        path.unlink(missing_ok=True)
        return False


def write_figures(rows: Sequence[Row], fig_dir: Path) -> list[tuple[FigureSpec, Drawing]]:
    """Every figure the study's axes allow, as SVG (and PNG when possible) in ``fig_dir``."""
    fig_dir.mkdir(parents=True, exist_ok=True)
    out = []
    for spec in FIGURES:
        series = figure_series(rows, spec)
        if len(series) < 1:
            continue
        d = draw_figure(spec, series)
        with atomic_path(fig_dir / f"{spec.name}.svg") as tmp:
            renderSVG.drawToFile(d, str(tmp))
        _png(d, fig_dir / f"{spec.name}.png")
        out.append((spec, d))
    return out


def write_study_pdf(out_dir: Path) -> list[Path]:
    """figures/*.svg|png and study.pdf (figures + comparison with the paper) from summary.csv."""
    rows = read_summary(out_dir / "summary.csv")
    figs = write_figures(rows, out_dir / "figures")
    styles = getSampleStyleSheet()
    small = styles["BodyText"].clone("small", fontSize=7, leading=8.5)
    story: list = [
        Paragraph("Parametric study: figures and comparison with the paper", styles["Title"])
    ]
    table = [["claim", "paper", "reproduction", "verdict", "deviation", "why"]]
    for c in compare(rows):
        table.append(
            [
                Paragraph(x, small)
                for x in (c.claim, c.paper, c.reproduction, c.verdict, c.deviation, c.reason)
            ]
        )
    t = Table(table, colWidths=[4 * cm, 2 * cm, 4.2 * cm, 1.5 * cm, 2.3 * cm, 4 * cm], repeatRows=1)
    t.setStyle(
        TableStyle(
            [
                ("GRID", (0, 0), (-1, -1), 0.3, colors.grey),
                ("FONTSIZE", (0, 0), (-1, 0), 8),
                ("VALIGN", (0, 0), (-1, -1), "TOP"),
            ]
        )
    )
    story += [t, Spacer(1, 12)]
    for _, d in figs:
        story += [d, Spacer(1, 8)]
    pdf = out_dir / "study.pdf"
    with atomic_path(pdf) as tmp:  # a full disk leaves no half-written (0-byte) study.pdf
        SimpleDocTemplate(
            str(tmp),
            pagesize=A4,
            leftMargin=1.2 * cm,
            rightMargin=1.2 * cm,
            title="frp-assess study",
        ).build(story)
    return [pdf, out_dir / "figures"]
