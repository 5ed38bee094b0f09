"""A reportlab chart (:class:`~reportlab.graphics.shapes.Drawing`) as a PNG, for the DOCX.

reportlab's own bitmap renderer needs an optional C extension; the charts of the report use
only lines, polylines, rectangles, circles and strings (some in a rotated group), which Pillow
(a dependency of reportlab) draws directly.  Coordinates: the drawing's in pt, y up; the
image's in pixels, y down, ``scale`` pixels per pt.
"""

from __future__ import annotations

import io
import math
from functools import cache

from PIL import Image, ImageDraw, ImageFont
from reportlab.graphics.shapes import Circle, Drawing, Group, Line, PolyLine, Rect, String
from reportlab.lib.colors import Color

from frp_assess.report import styles as st

#: pixels per pt of the PNG (3: about 216 dpi)
SCALE = 3.0

Affine = tuple[float, float, float, float, float, float]
_IDENTITY: Affine = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)


def _mul(a: Affine, b: Affine) -> Affine:
    """The affine map ``a`` after ``b`` (reportlab's (a, b, c, d, e, f) convention)."""
    return (
        a[0] * b[0] + a[2] * b[1],
        a[1] * b[0] + a[3] * b[1],
        a[0] * b[2] + a[2] * b[3],
        a[1] * b[2] + a[3] * b[3],
        a[0] * b[4] + a[2] * b[5] + a[4],
        a[1] * b[4] + a[3] * b[5] + a[5],
    )


def _rgba(c: Color | None) -> tuple[int, int, int, int] | None:
    if c is None:
        return None
    r, g, b, a = c.rgba()
    return (round(255 * r), round(255 * g), round(255 * b), round(255 * a))


@cache
def _font(bold: bool, size_px: int) -> ImageFont.FreeTypeFont:
    name = "DejaVuSans-Bold.ttf" if bold else "DejaVuSans.ttf"
    return ImageFont.truetype(str(st.FONT_DIR / name), size_px)


class _Painter:
    def __init__(self, d: Drawing, scale: float) -> None:
        self.scale = scale
        self.height = float(d.height)
        size = (max(1, math.ceil(d.width * scale)), max(1, math.ceil(d.height * scale)))
        self.image = Image.new("RGBA", size, (255, 255, 255, 255))
        self.draw = ImageDraw.Draw(self.image)

    def px(self, m: Affine, x: float, y: float) -> tuple[float, float]:
        tx = m[0] * x + m[2] * y + m[4]
        ty = m[1] * x + m[3] * y + m[5]
        return tx * self.scale, (self.height - ty) * self.scale

    def width(self, w: float | None) -> int:
        return max(1, round((w or 0.5) * self.scale))

    def shape(self, s: object, m: Affine) -> None:
        if isinstance(s, Group):
            inner = _mul(m, tuple(s.transform))  # type: ignore[arg-type]
            for child in s.contents:
                self.shape(child, inner)
        elif isinstance(s, Line):
            color = _rgba(s.strokeColor)
            if color is not None:
                pts = [self.px(m, s.x1, s.y1), self.px(m, s.x2, s.y2)]
                self.draw.line(pts, fill=color, width=self.width(s.strokeWidth))
        elif isinstance(s, PolyLine):
            color = _rgba(s.strokeColor)
            p = list(s.points)
            pts = [self.px(m, p[i], p[i + 1]) for i in range(0, len(p) - 1, 2)]
            if color is not None and len(pts) > 1:
                self.draw.line(pts, fill=color, width=self.width(s.strokeWidth), joint="curve")
        elif isinstance(s, Rect):
            (x0, y0), (x1, y1) = self.px(m, s.x, s.y), self.px(m, s.x + s.width, s.y + s.height)
            box = (min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))
            fill, line = _rgba(s.fillColor), _rgba(s.strokeColor)
            self.draw.rectangle(box, fill=fill, outline=line, width=self.width(s.strokeWidth))
        elif isinstance(s, Circle):
            cx, cy = self.px(m, s.cx, s.cy)
            r = s.r * self.scale
            fill, line = _rgba(s.fillColor), _rgba(s.strokeColor)
            self.draw.ellipse(
                (cx - r, cy - r, cx + r, cy + r),
                fill=fill,
                outline=line,
                width=self.width(s.strokeWidth),
            )
        elif isinstance(s, String):
            self.text(s, m)

    def text(self, s: String, m: Affine) -> None:
        bold = "Bold" in str(s.fontName)
        font = _font(bold, max(6, round(s.fontSize * self.scale)))
        text = str(s.text)
        w = font.getlength(text)
        left, top, right, bottom = font.getbbox(text)
        shift = {"middle": w / 2, "end": w}.get(s.textAnchor, 0.0)
        ascent = font.getmetrics()[0]
        angle = math.degrees(math.atan2(m[1], m[0]))
        fill = _rgba(s.fillColor) or (0, 0, 0, 255)
        x, y = self.px(m, s.x, s.y)
        if abs(angle) < 0.01:
            self.draw.text((x - shift, y - ascent), text, font=font, fill=fill)
            return
        pad = 2
        tile = Image.new(
            "RGBA", (math.ceil(w) + 2 * pad, math.ceil(bottom) + 2 * pad), (255, 255, 255, 0)
        )
        ImageDraw.Draw(tile).text((pad, pad), text, font=font, fill=fill)
        rotated = tile.rotate(angle, expand=True, resample=Image.Resampling.BICUBIC)
        # the anchor point (shift, baseline) of the tile, rotated with it about its centre
        cx, cy = tile.width / 2, tile.height / 2
        ax, ay = pad + shift - cx, pad + ascent - cy
        rad = math.radians(angle)
        rx = ax * math.cos(rad) + ay * math.sin(rad) + rotated.width / 2
        ry = -ax * math.sin(rad) + ay * math.cos(rad) + rotated.height / 2
        self.image.alpha_composite(rotated, (round(x - rx), round(y - ry)))
        del left, top, right


def drawing_png(d: Drawing, scale: float = SCALE) -> bytes:
    """The PNG bytes of ``d`` at ``scale`` pixels per pt (deterministic)."""
    painter = _Painter(d, scale)
    for s in d.contents:
        painter.shape(s, _IDENTITY)
    out = io.BytesIO()
    painter.image.convert("RGB").save(out, format="PNG", optimize=False)
    return out.getvalue()
