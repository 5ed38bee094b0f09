"""Small character plots for the terminal: braille lines, marker scatter, axes and ticks.

:func:`render_plot` is a pure function from data to lines of :class:`rich.text.Text`
(unit-tested); :class:`PlotView` is the Textual widget that redraws it at its own size.
No plotting dependency is needed: a braille cell holds 2 × 4 dots, so a 40 × 10 cell area
has 80 × 40 dots, plenty for a spectrum or a time history.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from rich.text import Text
from textual.app import RenderResult
from textual.widget import Widget

from frp_assess.tui.core.text import printable

#: bit of the braille dot at (column 0-1, row 0-3) of a cell (Unicode U+2800 block)
_DOT_BITS = ((0x01, 0x02, 0x04, 0x40), (0x08, 0x10, 0x20, 0x80))
BRAILLE_BASE = 0x2800


@dataclass(frozen=True)
class Series:
    """One data series.

    Attributes:
        x, y: the points (NaN or None breaks a line and is skipped).
        style: Rich style of the series.
        label: legend text (empty: not in the legend).
        kind: ``line`` (braille segments between points) or ``points`` (one marker per point).
        marker: the character of a ``points`` series.
    """

    x: Sequence[float | None]
    y: Sequence[float | None]
    style: str = "cyan"
    label: str = ""
    kind: Literal["line", "points"] = "line"
    marker: str = "●"


@dataclass(frozen=True)
class Rule:
    """A horizontal (``axis="y"``) or vertical (``axis="x"``) reference line at ``value``."""

    value: float
    axis: Literal["x", "y"] = "y"
    style: str = "grey50"
    label: str = ""


@dataclass
class _Canvas:
    width: int  #: cells
    height: int  #: cells
    bits: list[list[int]] = field(default_factory=list)
    styles: list[list[str]] = field(default_factory=list)
    chars: list[list[str | None]] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.bits = [[0] * self.width for _ in range(self.height)]
        self.styles = [[""] * self.width for _ in range(self.height)]
        self.chars = [[None] * self.width for _ in range(self.height)]

    def dot(self, px: int, py: int, style: str) -> None:
        """Set the dot at pixel (px, py), py = 0 at the top."""
        if 0 <= px < 2 * self.width and 0 <= py < 4 * self.height:
            cx, cy = px // 2, py // 4
            self.bits[cy][cx] |= _DOT_BITS[px % 2][py % 4]
            self.styles[cy][cx] = style

    def line(self, p0: tuple[int, int], p1: tuple[int, int], style: str) -> None:
        """Bresenham segment between two pixels."""
        x0, y0 = p0
        x1, y1 = p1
        dx, dy = abs(x1 - x0), -abs(y1 - y0)
        sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
        err = dx + dy
        for _ in range(4 * (self.width + self.height) * 4 + 8):
            self.dot(x0, y0, style)
            if x0 == x1 and y0 == y1:
                break
            e2 = 2 * err
            if e2 >= dy:
                err += dy
                x0 += sx
            if e2 <= dx:
                err += dx
                y0 += sy

    def mark(self, cx: int, cy: int, char: str, style: str) -> None:
        if 0 <= cx < self.width and 0 <= cy < self.height:
            self.chars[cy][cx] = char
            self.styles[cy][cx] = style

    def rows(self) -> list[Text]:
        out = []
        for cy in range(self.height):
            t = Text()
            for cx in range(self.width):
                ch = self.chars[cy][cx]
                if ch is None:
                    b = self.bits[cy][cx]
                    ch = chr(BRAILLE_BASE + b) if b else " "
                t.append(ch, self.styles[cy][cx] or None)
            out.append(t)
        return out


def _finite(v: float | None) -> bool:
    return v is not None and isinstance(v, int | float) and math.isfinite(v)


def data_range(values: Sequence[float | None], pad: float = 0.0) -> tuple[float, float]:
    """(min, max) of the finite values, widened by ``pad`` of the span; (0, 1) if none."""
    finite = [float(v) for v in values if v is not None and _finite(v)]
    if not finite:
        return 0.0, 1.0
    lo, hi = min(finite), max(finite)
    if hi - lo < 1e-12 * max(1.0, abs(hi)):
        half = max(abs(hi) * 0.1, 1e-9)
        return lo - half, hi + half
    span = hi - lo
    return lo - pad * span, hi + pad * span


def tick(value: float) -> str:
    """A short tick label: 3 significant figures, no exponent for ordinary values."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    mag = abs(value)
    if 1e-3 <= mag < 1e5:
        text = f"{value:.3g}"
    else:
        text = f"{value:.1e}".replace("e-0", "e-").replace("e+0", "e")
    return text


def _header(
    series: Sequence[Series], rules: Sequence[Rule], y_label: str, legend: bool, width: int
) -> list[Text]:
    """The y label and the legend, wrapped onto as many lines as ``width`` needs."""
    items: list[Text] = []
    if legend:
        for s in series:
            if s.label:
                mark = s.marker if s.kind == "points" else "━"
                items.append(Text.assemble((mark, s.style), printable(f" {s.label}")))
        for r in rules:
            if r.label:
                items.append(Text.assemble(("┄", r.style), printable(f" {r.label}")))
    if not y_label and not items:
        return []
    lines = [Text(printable(y_label), style="bold")]
    for item in items:
        line = lines[-1]
        if line.cell_len and line.cell_len + 2 + item.cell_len > width:
            lines.append(Text("  "))
            line = lines[-1]
        elif line.cell_len:
            line.append("  ")
        line.append_text(item)
    for line in lines:
        line.truncate(width)
    return lines


def render_plot(
    series: Sequence[Series],
    width: int,
    height: int,
    *,
    x_range: tuple[float, float] | None = None,
    y_range: tuple[float, float] | None = None,
    rules: Sequence[Rule] = (),
    x_label: str = "",
    y_label: str = "",
    legend: bool = True,
) -> list[Text]:
    """The plot as ``height`` lines of at most ``width`` cells.

    Layout: an optional first line with the y label and the legend, the plot area with y
    ticks on the left, an axis line and a line of x ticks ending with the x label.
    """
    width = max(width, 12)
    height = max(height, 4)
    xs = [v for s in series for v in s.x]
    ys = [v for s in series for v in s.y]
    x0, x1 = x_range if x_range is not None else data_range(xs)
    y0, y1 = y_range if y_range is not None else data_range(ys, pad=0.05)
    if x1 <= x0:
        x1 = x0 + 1.0
    if y1 <= y0:
        y1 = y0 + 1.0
    y_ticks = [y1, 0.5 * (y0 + y1), y0]
    labels = [tick(v) for v in y_ticks]
    tw = max(len(s) for s in labels)
    header = _header(series, rules, y_label, legend, width)
    ph = height - 2 - len(header)
    pw = width - tw - 1
    if ph < 1 or pw < 2:
        return [Text("(too small)")]
    canvas = _Canvas(pw, ph)
    npx, npy = 2 * pw - 1, 4 * ph - 1

    def to_px(x: float) -> int:
        return round((x - x0) / (x1 - x0) * npx)

    def to_py(y: float) -> int:
        return round((y1 - y) / (y1 - y0) * npy)

    for r in rules:
        if r.axis == "y" and y0 <= r.value <= y1:
            py = to_py(r.value)
            for px in range(0, npx + 1, 2):
                canvas.dot(px, py, r.style)
        elif r.axis == "x" and x0 <= r.value <= x1:
            px = to_px(r.value)
            for py in range(0, npy + 1, 2):
                canvas.dot(px, py, r.style)
    for s in series:
        prev: tuple[int, int] | None = None
        for x, y in zip(s.x, s.y, strict=False):
            if not (_finite(x) and _finite(y)):
                prev = None
                continue
            p = (to_px(float(x)), to_py(float(y)))  # type: ignore[arg-type]
            if s.kind == "points":
                canvas.mark(p[0] // 2, p[1] // 4, s.marker, s.style)
                continue
            if prev is None:
                canvas.dot(*p, s.style)
            else:
                canvas.line(prev, p, s.style)
            prev = p
    out: list[Text] = list(header)
    rows = canvas.rows()
    tick_rows = {0: labels[0], ph // 2: labels[1], ph - 1: labels[2]}
    for i, row in enumerate(rows):
        line = Text(tick_rows.get(i, "").rjust(tw), style="grey62")
        line.append("┤" if i in tick_rows else "│", style="grey50")
        line.append_text(row)
        out.append(line)
    axis = Text(" " * tw + "└" + "─" * pw, style="grey50")
    out.append(axis)
    xt = [tick(x0), tick(0.5 * (x0 + x1)), tick(x1)]
    cells = [" "] * (tw + 1 + pw)
    positions = [tw + 1, tw + 1 + pw // 2 - len(xt[1]) // 2, tw + 1 + pw - len(xt[2])]
    for text, pos in zip(xt, positions, strict=True):
        for k, ch in enumerate(text):
            if 0 <= pos + k < len(cells):
                cells[pos + k] = ch
    last = "".join(cells)
    if x_label:
        # the x label goes between the middle and right ticks when there is room
        start = positions[1] + len(xt[1]) + 2
        room = positions[2] - 2 - start
        if room >= 3:
            label = printable(x_label)[:room]
            last = last[:start] + label.center(room) + last[start + room :]
    out.append(Text(last, style="grey62"))
    return out


class PlotView(Widget):
    """A plot that redraws at the widget's size; set its data with :meth:`show`."""

    DEFAULT_CSS = """
    PlotView { height: 1fr; min-height: 6; }
    """

    def __init__(self, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self._series: Sequence[Series] = ()
        self._plot_options: dict[str, Any] = {}
        self._message = ""

    def show(self, series: Sequence[Series], **options: Any) -> None:
        """Plot ``series`` with the keyword options of :func:`render_plot`."""
        self._series, self._plot_options, self._message = list(series), options, ""
        self.refresh()

    def show_message(self, message: str) -> None:
        """Show a line of text instead of a plot (no data, invalid input...)."""
        self._series, self._message = (), message
        self.refresh()

    def render(self) -> RenderResult:
        if self._message or not self._series:
            return Text(self._message or "(nothing to plot)", style="dim")
        w, h = self.content_size.width, self.content_size.height
        return Text("\n").join(render_plot(self._series, w, h, **self._plot_options))
