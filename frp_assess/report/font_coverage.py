"""What the PDF's font cannot show of the project's own texts (issue 36 item 7).

The PDF embeds DejaVu Sans (:mod:`frp_assess.report.styles`): Latin, Greek, Cyrillic and the
symbols of the report, but no CJK ideographs and only some emoji, so such characters in a
name, a place or a note print as empty boxes; and reportlab neither joins Arabic letters nor
orders right-to-left text, so Arabic and Hebrew print unjoined, left to right.  The DOCX
leaves the shaping to Word and shows them right.  No font is embedded for them: a CJK font
is megabytes (Debian's fonts-droid-fallback installs 7.3 MB, fonts-noto-cjk 91 MB), colour
emoji fonts (fonts-noto-color-emoji) are bitmaps reportlab cannot embed, and no font shapes
Arabic without a shaping engine.  :func:`font_gaps` says which characters are affected, for
a one-line warning at report time (frp_assess/app/report.py) and the README's limits.
"""

from __future__ import annotations

import dataclasses
import unicodedata
from collections.abc import Iterator
from functools import cache

from reportlab.pdfbase.ttfonts import TTFont

from frp_assess.report.styles import FONT_DIR
from frp_assess.results.model import AssessmentResult

#: how many characters a warning names at most
SHOWN = 6


@cache
def _covered() -> frozenset[int]:
    """The code points DejaVu Sans has a glyph for (regular; the other faces match)."""
    face = TTFont("coverage", str(FONT_DIR / "DejaVuSans.ttf")).face
    return frozenset(face.charToGlyph)


def _strings(value: object) -> Iterator[str]:
    """Every string in the results (the texts the report may print)."""
    if isinstance(value, str):
        yield value
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        for f in dataclasses.fields(value):
            yield from _strings(getattr(value, f.name))
    elif isinstance(value, dict):
        for k, v in value.items():
            yield from _strings(k)
            yield from _strings(v)
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _strings(v)


def _named(chars: list[str]) -> str:
    """``U+4E2D (CJK UNIFIED IDEOGRAPH-4E2D), …``: plain ASCII, any console prints it."""
    shown = [f"U+{ord(c):04X} ({unicodedata.name(c, 'unnamed')})" for c in chars[:SHOWN]]
    more = len(chars) - SHOWN
    return ", ".join(shown) + (f" and {more} more" if more > 0 else "")


def font_gaps(results: AssessmentResult) -> str | None:
    """One sentence naming the characters of the results the PDF cannot show as written
    (no glyph in the font; right-to-left letters, printed unjoined and left to right), or
    None when every character prints."""
    covered = _covered()
    missing: set[str] = set()
    rtl: set[str] = set()
    for text in _strings(results):
        for c in text:
            if unicodedata.category(c)[0] == "C" or c.isspace():
                continue  # controls and spaces are never drawn
            if ord(c) not in covered:
                missing.add(c)
            elif unicodedata.bidirectional(c) in ("R", "AL"):
                rtl.add(c)
    parts = []
    if missing:
        parts.append(
            "the PDF font (DejaVu Sans) has no glyph for "
            + _named(sorted(missing))
            + ": they print as empty boxes"
        )
    if rtl:
        parts.append(
            "right-to-left letters " + _named(sorted(rtl)) + " print unjoined and left to right"
        )
    if not parts:
        return None
    return "report.pdf: " + "; ".join(parts) + " (report.docx shows them as written)"
