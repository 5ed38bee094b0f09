"""Every font, colour, paragraph and table style of the report, in one place.

The base-14 PDF fonts cannot draw θ, α, ρ, ε, ‰, ² or ³, so the report embeds DejaVu Sans
(shipped in ``fonts/`` with its licence). :func:`register_fonts` is idempotent.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

from reportlab.lib import colors
from reportlab.lib.enums import TA_CENTER, TA_LEFT
from reportlab.lib.pagesizes import A4
from reportlab.lib.styles import ParagraphStyle
from reportlab.lib.units import mm
from reportlab.pdfbase import pdfmetrics
from reportlab.pdfbase.ttfonts import TTFont
from reportlab.platypus import TableStyle

FONT_DIR = Path(__file__).with_name("fonts")
FONT = "DejaVuSans"
FONT_BOLD = "DejaVuSans-Bold"
FONT_ITALIC = "DejaVuSans-Oblique"
FONT_BOLD_ITALIC = "DejaVuSans-BoldOblique"

PAGE_SIZE = A4
MARGIN_X = 18 * mm
MARGIN_TOP = 20 * mm
MARGIN_BOTTOM = 18 * mm
FRAME_WIDTH = PAGE_SIZE[0] - 2 * MARGIN_X

# colours
INK = colors.HexColor("#1a1a1a")
MUTED = colors.HexColor("#5f6368")
RULE = colors.HexColor("#9aa0a6")
HEADER_BG = colors.HexColor("#dde4ee")
ZEBRA = colors.HexColor("#f4f6f9")
HIGHLIGHT = colors.HexColor("#e3f1e0")
PASS = colors.HexColor("#1e7b34")
FAIL = colors.HexColor("#b3261e")
TARGET = colors.HexColor("#c0392b")
RECORD_LINE = colors.HexColor("#b0b7c3")
MEAN_LINE = colors.HexColor("#1a1a1a")
#: one colour per FRP material in the charts (others cycle through SERIES)
MATERIAL_COLOURS = {
    "GFRP": colors.HexColor("#2e7d32"),
    "BFRP": colors.HexColor("#8d6e63"),
    "CFRP": colors.HexColor("#1f4e9c"),
}
SERIES = [
    colors.HexColor("#1f4e9c"),
    colors.HexColor("#c0392b"),
    colors.HexColor("#2e7d32"),
    colors.HexColor("#8e44ad"),
    colors.HexColor("#d68910"),
    colors.HexColor("#17a589"),
]
COLLAPSE_RUN = colors.HexColor("#c0392b")
BELOW_RUN = colors.HexColor("#1f4e9c")

BODY_SIZE = 9.5
TABLE_SIZE = 8.0
SMALL_TABLE_SIZE = 7.0
CHART_FONT_SIZE = 7.5


@cache
def register_fonts() -> None:
    """Register DejaVu Sans (regular, bold, oblique, bold oblique) as one font family."""
    for name, file in (
        (FONT, "DejaVuSans.ttf"),
        (FONT_BOLD, "DejaVuSans-Bold.ttf"),
        (FONT_ITALIC, "DejaVuSans-Oblique.ttf"),
        (FONT_BOLD_ITALIC, "DejaVuSans-BoldOblique.ttf"),
    ):
        pdfmetrics.registerFont(TTFont(name, str(FONT_DIR / file)))
    pdfmetrics.registerFontFamily(
        FONT, normal=FONT, bold=FONT_BOLD, italic=FONT_ITALIC, boldItalic=FONT_BOLD_ITALIC
    )


def _style(name: str, **kw: object) -> ParagraphStyle:
    base: dict[str, object] = {
        "fontName": FONT,
        "fontSize": BODY_SIZE,
        "leading": BODY_SIZE * 1.3,
        "textColor": INK,
        "alignment": TA_LEFT,
    }
    base.update(kw)
    return ParagraphStyle(name, **base)  # type: ignore[arg-type]


@cache
def paragraph_styles() -> dict[str, ParagraphStyle]:
    """Named paragraph styles: title, h1, h2, body, small, caption, cell, head, ..."""
    register_fonts()
    return {
        "title": _style("title", fontName=FONT_BOLD, fontSize=17, leading=22, spaceAfter=4),
        "subtitle": _style("subtitle", fontSize=10.5, leading=14, textColor=MUTED, spaceAfter=8),
        "h1": _style(
            "h1", fontName=FONT_BOLD, fontSize=13.5, leading=17, spaceBefore=4, spaceAfter=6
        ),
        "h2": _style(
            "h2", fontName=FONT_BOLD, fontSize=10.5, leading=13.5, spaceBefore=8, spaceAfter=4
        ),
        "body": _style("body", spaceAfter=5),
        "verdict_ok": _style("verdict_ok", fontName=FONT_BOLD, textColor=PASS, spaceAfter=5),
        "verdict_bad": _style("verdict_bad", fontName=FONT_BOLD, textColor=FAIL, spaceAfter=5),
        "bullet": _style("bullet", leftIndent=12, bulletIndent=2, spaceAfter=2),
        "small": _style("small", fontSize=8, leading=10.5, textColor=MUTED, spaceAfter=4),
        "caption": _style(
            "caption", fontSize=8, leading=10.5, textColor=MUTED, spaceBefore=2, spaceAfter=8
        ),
        "equation": _style(
            "equation", fontSize=9, leading=12.5, leftIndent=14, spaceBefore=1, spaceAfter=4
        ),
        "reference": _style(
            "reference", fontSize=8.5, leading=11, leftIndent=14, firstLineIndent=-14, spaceAfter=3
        ),
        "cell": _style("cell", fontSize=TABLE_SIZE, leading=TABLE_SIZE * 1.22),
        "cell_right": _style(
            "cell_right", fontSize=TABLE_SIZE, leading=TABLE_SIZE * 1.22, alignment=2
        ),
        "head": _style("head", fontName=FONT_BOLD, fontSize=TABLE_SIZE, leading=TABLE_SIZE * 1.22),
        "head_center": _style(
            "head_center",
            fontName=FONT_BOLD,
            fontSize=TABLE_SIZE,
            leading=TABLE_SIZE * 1.22,
            alignment=TA_CENTER,
        ),
        "cell_small": _style(
            "cell_small", fontSize=SMALL_TABLE_SIZE, leading=SMALL_TABLE_SIZE * 1.22
        ),
        "head_small": _style(
            "head_small",
            fontName=FONT_BOLD,
            fontSize=SMALL_TABLE_SIZE,
            leading=SMALL_TABLE_SIZE * 1.22,
            alignment=TA_CENTER,
        ),
    }


def grid_table_style(
    n_rows: int, *, font_size: float = TABLE_SIZE, header_rows: int = 1, numeric_from: int = 1
) -> TableStyle:
    """Header shading, zebra rows, thin rules; columns from ``numeric_from`` right-aligned."""
    register_fonts()
    cmds: list[tuple] = [
        ("FONT", (0, 0), (-1, -1), FONT, font_size, font_size * 1.22),
        ("FONT", (0, 0), (-1, header_rows - 1), FONT_BOLD, font_size, font_size * 1.22),
        ("TEXTCOLOR", (0, 0), (-1, -1), INK),
        ("BACKGROUND", (0, 0), (-1, header_rows - 1), HEADER_BG),
        ("LINEABOVE", (0, 0), (-1, 0), 0.8, INK),
        ("LINEBELOW", (0, header_rows - 1), (-1, header_rows - 1), 0.6, INK),
        ("LINEBELOW", (0, -1), (-1, -1), 0.8, INK),
        ("VALIGN", (0, 0), (-1, -1), "MIDDLE"),
        ("ALIGN", (numeric_from, header_rows), (-1, -1), "RIGHT"),
        ("ALIGN", (0, 0), (-1, header_rows - 1), "CENTER"),
        ("TOPPADDING", (0, 0), (-1, -1), 1.6),
        ("BOTTOMPADDING", (0, 0), (-1, -1), 2.0),
        ("LEFTPADDING", (0, 0), (-1, -1), 3),
        ("RIGHTPADDING", (0, 0), (-1, -1), 3),
    ]
    for r in range(header_rows + 1, n_rows, 2):
        cmds.append(("BACKGROUND", (0, r), (-1, r), ZEBRA))
    return TableStyle(cmds)


def key_value_table_style(n_rows: int) -> TableStyle:
    """Two-column 'quantity | value' tables: no header, light rules."""
    register_fonts()
    cmds: list[tuple] = [
        ("FONT", (0, 0), (-1, -1), FONT, TABLE_SIZE, TABLE_SIZE * 1.22),
        ("TEXTCOLOR", (0, 0), (0, -1), MUTED),
        ("VALIGN", (0, 0), (-1, -1), "TOP"),
        ("LINEABOVE", (0, 0), (-1, 0), 0.6, INK),
        ("LINEBELOW", (0, -1), (-1, -1), 0.6, INK),
        ("TOPPADDING", (0, 0), (-1, -1), 1.4),
        ("BOTTOMPADDING", (0, 0), (-1, -1), 1.8),
        ("LEFTPADDING", (0, 0), (-1, -1), 3),
    ]
    for r in range(1, n_rows, 2):
        cmds.append(("BACKGROUND", (0, r), (-1, r), ZEBRA))
    return TableStyle(cmds)
