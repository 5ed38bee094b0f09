"""Chart primitives: nice ticks, the axes helper (:class:`Axes`: data to drawing coordinates
on linear or log scales, frame, grid, ticks, labels), markers, text and legends."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from reportlab.graphics.shapes import Circle, Drawing, Line, PolyLine, Rect, String
from reportlab.lib import colors
from reportlab.lib.colors import Color
from reportlab.pdfbase.pdfmetrics import stringWidth

from frp_assess.report import styles as st
from frp_assess.text_safety import pdf_plain

FS = st.CHART_FONT_SIZE
#: longest chart label [characters] (user names in legends)
LABEL_MAX_CHARS = 120
#: width of a legend label beside the chart [pt]
LEGEND_LABEL_WIDTH = 112.0


# --- scales and ticks ---------------------------------------------------------------------


def nice_ticks(lo: float, hi: float, n: int = 6) -> list[float]:
    """Round tick values covering [lo, hi] with about ``n`` intervals."""
    if hi <= lo:
        hi = lo + 1.0
    raw = (hi - lo) / n
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw)
    first = math.floor(lo / step + 1e-9) * step
    ticks = []
    k = 0
    while True:
        v = first + k * step
        if v > hi + step * 1e-6:
            break
        ticks.append(round(v, 12))
        k += 1
    return ticks


def nice_range(lo: float, hi: float, n: int = 6) -> tuple[float, float, list[float]]:
    """Extend [lo, hi] to the enclosing round ticks."""
    ticks = nice_ticks(lo, hi, n)
    if ticks[0] > lo:
        ticks.insert(0, ticks[0] - (ticks[1] - ticks[0]))
    if ticks[-1] < hi:
        ticks.append(ticks[-1] + (ticks[1] - ticks[0]))
    return ticks[0], ticks[-1], ticks


def log_ticks(lo: float, hi: float) -> list[float]:
    """1-2-5 ticks per decade between lo and hi (1 only when many decades)."""
    decades = range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)
    mults = (1, 2, 5) if len(decades) <= 5 else (1,)
    return [m * 10.0**d for d in decades for m in mults if lo * 0.999 <= m * 10.0**d <= hi * 1.001]


def tick_label(v: float) -> str:
    if v == 0:
        return "0"
    return f"{v:g}"


class Axes:
    """One plot area inside a drawing."""

    def __init__(
        self,
        drawing: Drawing,
        x: float,
        y: float,
        w: float,
        h: float,
        xlim: tuple[float, float],
        ylim: tuple[float, float],
        *,
        xlog: bool = False,
        ylog: bool = False,
    ) -> None:
        self.d, self.x, self.y, self.w, self.h = drawing, x, y, w, h
        self.xlim, self.ylim, self.xlog, self.ylog = xlim, ylim, xlog, ylog

    def _f(self, v: float, lim: tuple[float, float], log: bool) -> float:
        if log:
            v = max(v, lim[0] * 1e-3)
            return (math.log10(v) - math.log10(lim[0])) / (math.log10(lim[1]) - math.log10(lim[0]))
        return (v - lim[0]) / (lim[1] - lim[0])

    def tx(self, v: float) -> float:
        return self.x + self.w * self._f(v, self.xlim, self.xlog)

    def ty(self, v: float) -> float:
        return self.y + self.h * self._f(v, self.ylim, self.ylog)

    def frame(
        self, xlabel: str, ylabel: str, xticks: Sequence[float], yticks: Sequence[float]
    ) -> None:
        d = self.d
        for v in xticks:
            px = self.tx(v)
            d.add(Line(px, self.y, px, self.y + self.h, strokeColor=st.ZEBRA, strokeWidth=0.6))
            d.add(Line(px, self.y, px, self.y - 3, strokeColor=st.INK, strokeWidth=0.6))
            d.add(_text(px, self.y - 3 - FS, tick_label(v), anchor="middle"))
        for v in yticks:
            py = self.ty(v)
            d.add(Line(self.x, py, self.x + self.w, py, strokeColor=st.ZEBRA, strokeWidth=0.6))
            d.add(Line(self.x, py, self.x - 3, py, strokeColor=st.INK, strokeWidth=0.6))
            d.add(_text(self.x - 5, py - FS * 0.35, tick_label(v), anchor="end"))
        d.add(
            Rect(
                self.x, self.y, self.w, self.h, fillColor=None, strokeColor=st.INK, strokeWidth=0.7
            )
        )
        d.add(_text(self.x + self.w / 2, self.y - 6 - 2.2 * FS, xlabel, anchor="middle"))
        label_w = max((stringWidth(tick_label(v), st.FONT, FS) for v in yticks), default=10)
        ylab = _text(0, 0, ylabel, anchor="middle")
        from reportlab.graphics.shapes import Group

        g = Group(ylab)
        g.translate(self.x - label_w - 10, self.y + self.h / 2)
        g.rotate(90)
        d.add(g)

    def line(
        self,
        xs: Sequence[float],
        ys: Sequence[float],
        color: Color,
        width: float = 1.0,
        dash: Sequence[float] | None = None,
    ) -> None:
        pts: list[float] = []
        for a, b in zip(xs, ys, strict=True):
            pts += [self.tx(a), self.ty(b)]
        if len(pts) >= 4:
            self.d.add(
                PolyLine(
                    pts,
                    strokeColor=color,
                    strokeWidth=width,
                    strokeDashArray=dash,
                    strokeLineJoin=1,
                    strokeLineCap=1,
                )
            )

    def hline(
        self,
        y: float,
        color: Color,
        width: float = 0.9,
        dash: Sequence[float] = (4, 2),
        label: str | None = None,
    ) -> None:
        py = self.ty(y)
        self.d.add(
            Line(
                self.x,
                py,
                self.x + self.w,
                py,
                strokeColor=color,
                strokeWidth=width,
                strokeDashArray=list(dash),
            )
        )
        if label:
            self.d.add(_text(self.x + self.w - 3, py + 2.5, label, anchor="end", color=color))

    def marker(
        self,
        x: float,
        y: float,
        color: Color,
        *,
        hollow: bool = False,
        shape: str = "o",
        size: float = 2.6,
    ) -> None:
        add_marker(self.d, self.tx(x), self.ty(y), color, hollow=hollow, shape=shape, size=size)


def add_marker(
    d: Drawing,
    px: float,
    py: float,
    color: Color,
    *,
    hollow: bool = False,
    shape: str = "o",
    size: float = 2.6,
) -> None:
    fill = colors.white if hollow else color
    if shape == "s":
        d.add(
            Rect(
                px - size,
                py - size,
                2 * size,
                2 * size,
                fillColor=fill,
                strokeColor=color,
                strokeWidth=0.8,
            )
        )
    elif shape == "^":
        from reportlab.graphics.shapes import Polygon

        d.add(
            Polygon(
                [px - size * 1.1, py - size, px + size * 1.1, py - size, px, py + size * 1.2],
                fillColor=fill,
                strokeColor=color,
                strokeWidth=0.8,
            )
        )
    elif shape == "x":  # a cross (an option dropped by the pivot check)
        r = size * 1.5
        d.add(Line(px - r, py - r, px + r, py + r, strokeColor=color, strokeWidth=1.1))
        d.add(Line(px - r, py + r, px + r, py - r, strokeColor=color, strokeWidth=1.1))
    else:
        d.add(Circle(px, py, size, fillColor=fill, strokeColor=color, strokeWidth=0.8))


def new_drawing(width: float, height: float) -> Drawing:
    """An empty drawing whose default font is the report's (no base-14 font is pulled in)."""
    st.register_fonts()
    return Drawing(width, height, initialFontName=st.FONT, initialFontSize=FS)


def _text(
    x: float,
    y: float,
    text: str,
    *,
    anchor: str = "start",
    size: float = FS,
    color: Color = st.INK,
    bold: bool = False,
) -> String:
    st.register_fonts()
    return String(
        x,
        y,
        pdf_plain(text, limit=LABEL_MAX_CHARS),
        fontName=st.FONT_BOLD if bold else st.FONT,
        fontSize=size,
        fillColor=color,
        textAnchor=anchor,
    )


def legend(
    d: Drawing,
    x: float,
    y: float,
    items: Sequence[tuple[str, dict[str, Any]]],
    *,
    dy: float = FS * 1.55,
) -> None:
    """Vertical legend from (x, y) downwards; item style keys: color, width, dash, marker."""
    for i, (label, sty) in enumerate(items):
        yy = y - i * dy
        if sty.get("width", 0) > 0:
            d.add(
                Line(
                    x,
                    yy + FS * 0.35,
                    x + 16,
                    yy + FS * 0.35,
                    strokeColor=sty["color"],
                    strokeWidth=sty["width"],
                    strokeDashArray=sty.get("dash"),
                )
            )
        if sty.get("marker"):
            add_marker(
                d,
                x + 8,
                yy + FS * 0.35,
                sty["color"],
                shape=sty["marker"],
                hollow=sty.get("hollow", False),
            )
        d.add(_text(x + 20, yy, fit_label(label, LEGEND_LABEL_WIDTH)))


def fit_label(text: str, width: float, size: float = FS) -> str:
    """``text`` (plain) cut with an ellipsis to ``width`` [pt] in the chart font."""
    text = pdf_plain(text, limit=LABEL_MAX_CHARS)
    if stringWidth(text, st.FONT, size) <= width:
        return text
    while len(text) > 1 and stringWidth(text + "…", st.FONT, size) > width:
        text = text[:-1]
    return text + "…"
