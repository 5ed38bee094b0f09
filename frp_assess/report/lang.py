"""The report's language: one keyed catalogue of strings per language (package data,
``report/catalogue/<code>.json``) and the one number format (decimal comma in Italian).

Catalogue strings are trusted markup (``<b>``, ``<sub>``...) with ``{name}`` placeholders;
what fills a placeholder is already escaped or a number formatted by :meth:`Lang.num`.
Chart labels are looked up by their English text (``chart:`` keys) and numbers in them are
re-formatted (:func:`frp_assess.report.charts.localize_drawing`).
"""

from __future__ import annotations

import json
import re
from functools import cache
from importlib import resources

#: languages with a catalogue
LANGUAGES = ("en", "it")
_NUMBER = re.compile(r"(?<![\w.,])(-?\d+(?:,\d{3})*(?:\.\d+)?)(?![\w]|\.\d)")


@cache
def catalogue(code: str) -> dict[str, str]:
    """The strings of language ``code`` (key → template)."""
    if code not in LANGUAGES:
        raise ValueError(f"no report language {code!r} (expected one of {', '.join(LANGUAGES)})")
    text = resources.files("frp_assess.report").joinpath("catalogue", f"{code}.json")
    data = json.loads(text.read_text(encoding="utf-8"))
    return {k: v for k, v in data.items() if not k.startswith("//")}


def short(text: str, limit: int = 16) -> str:
    """User text for a column header: at most ``limit`` characters, an ellipsis when cut."""
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1] + "…"


def swap_separators(text: str) -> str:
    """``1,234.5`` → ``1.234,5``: English number separators as in Italian."""
    return text.replace(",", "\x00").replace(".", ",").replace("\x00", ".")


#: an ISO calendar date, as the results store their date
_ISO_DATE = re.compile(r"(\d{4})-(\d{2})-(\d{2})")


class Lang:
    """The strings and number format of one language."""

    def __init__(self, code: str = "en") -> None:
        self.code = code if code in LANGUAGES else "en"
        self.strings = catalogue(self.code)

    def t(self, key: str, **values: object) -> str:
        """The string ``key`` with ``values`` filled in (they must be escaped already)."""
        return self.strings[key].format(**values)

    def has(self, key: str) -> bool:
        return key in self.strings

    def num(self, x: float | None, decimals: int = 2, *, grouping: bool = False) -> str:
        """``x`` with ``decimals`` decimals (a dash for None), the language's separators."""
        if x is None:
            return "—"
        text = f"{x:,.{decimals}f}" if grouping else f"{x:.{decimals}f}"
        return swap_separators(text) if self.code == "it" else text

    def date(self, iso: str) -> str:
        """The results' date (ISO ``YYYY-MM-DD``) as the language writes it: ISO in English,
        ``DD/MM/YYYY`` in Italian; any other text unchanged."""
        m = _ISO_DATE.fullmatch(iso.strip())
        if m is None or self.code != "it":
            return iso
        year, month, day = m.groups()
        return f"{day}/{month}/{year}"

    def gnum(self, x: float) -> str:
        """``x`` in the shortest form (``:g``), the language's decimal separator."""
        text = f"{x:g}"
        return swap_separators(text) if self.code == "it" else text

    def numbers_in(self, text: str) -> str:
        """Every plain number in ``text`` (``0.25``, ``1,234``) with the language's
        separators; dotted versions (``1.2.3``) and words with digits are left alone."""
        if self.code == "en":
            return text
        return _NUMBER.sub(lambda m: swap_separators(m.group(1)), text)

    def chart_label(self, text: str) -> str:
        """A chart label in the language: its catalogue entry (``chart:<English>``) or a
        known pattern, numbers re-formatted."""
        key = "chart:" + text
        if key in self.strings:
            return self.strings[key]
        return self._by_pattern("chart:", _CHART_PATTERNS, text) or self.numbers_in(text)

    def run_phrase(self, text: str) -> str | None:
        """A phrase the run wrote in English with numbers in it (the compliance table's
        requirement and found columns, :mod:`frp_assess.motions.compliance`) in the language:
        its catalogue pattern (``run:`` keys) with the numbers re-formatted, or None for a
        phrase without a pattern.  A phrase without numbers (a material's source in the
        library, config/library.py) is its own key."""
        text = text.strip()
        if ("run:" + text) in self.strings:
            return self.numbers_in(self.strings["run:" + text])
        return self._by_pattern("run:", _RUN_PATTERNS, text)

    def _by_pattern(
        self, prefix: str, patterns: tuple[tuple[re.Pattern[str], str], ...], text: str
    ) -> str | None:
        """``text`` through the first of ``patterns`` it matches whole: the catalogue's entry
        ``prefix`` + its name, filled with the matched numbers in the language; None if none
        matches (or the catalogue has no entry for it)."""
        for pattern, name in patterns:
            m = pattern.fullmatch(text)
            if m is not None and (prefix + name) in self.strings:
                return self.numbers_in(self.strings[prefix + name].format(*m.groups()))
        return None


#: chart labels with a number in them: (English pattern, catalogue key after ``chart:``)
_CHART_PATTERNS = (
    (re.compile(r"mean of (\d+) records"), "mean of {} records"),
    (re.compile(r"target = (.+)"), "target = {}"),
    (re.compile(r"ρ = (.+) ‰ along each line"), "ρ = {} ‰ along each line"),
    (re.compile(r"ρ from (.+) to (.+) ‰"), "ρ from {} to {} ‰"),
    (re.compile(r"rupture ε_max = (.+) ‰"), "rupture ε_max = {} ‰"),
    (re.compile(r"C = (.+) \(collapse\)"), "C = {} (collapse)"),
    (re.compile(r"C = (.+) \(survives\)"), "C = {} (survives)"),
    (re.compile(r"(\S+) centred"), "{} centred"),
    (re.compile(r"(\S+) external"), "{} external"),
)

#: the run's phrases with numbers in them (motions/compliance.py): (English pattern, catalogue
#: key after ``run:``); matched whole, so "at least 3 records" is not "{} records"
_RUN_PATTERNS = (
    (re.compile(r"stationary part ≥ (\S+) s"), "stationary part ≥ {} s"),
    (re.compile(r"pseudo-stationary part ≥ (\S+) s"), "pseudo-stationary part ≥ {} s"),
    (re.compile(r"total duration ≥ (\S+) s"), "total duration ≥ {} s"),
    (re.compile(r"shortest (\S+) s"), "shortest {} s"),
    (re.compile(r"at least (\d+) records"), "at least {} records"),
    (re.compile(r"(\d+) records"), "{} records"),
    (re.compile(r"mean PGA ≥ a_g·S = (\S+) g"), "mean PGA ≥ a_g·S = {} g"),
    (re.compile(r"mean PGA (\S+) g \((\S+)\)"), "mean PGA {} g ({})"),
    (
        re.compile(r"mean spectrum ≥ (\S+) of target in (\S+) s"),
        "mean spectrum ≥ {} of target in {} s",
    ),  # noqa: E501
    (
        re.compile(r"mean spectrum ≤ (\S+) of target in (\S+) s"),
        "mean spectrum ≤ {} of target in {} s",
    ),  # noqa: E501
    (re.compile(r"min (\S+) at T = (\S+) s"), "min {} at T = {} s"),
    (re.compile(r"max (\S+) at T = (\S+) s"), "max {} at T = {} s"),
)
