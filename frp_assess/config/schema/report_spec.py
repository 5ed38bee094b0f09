"""The ``costs`` block (indicative costs) and the ``report`` block (language, Word
template).
"""

from __future__ import annotations

from typing import Literal

from pydantic import (
    Field,
)

from frp_assess.config.schema.spec_base import (
    FreeText,
    Number,
    _Model,
)

#: the largest price of one item of a tie (a bar, a plate, its installation) [currency]
MAX_TIE_PRICE = 1e6


class CostsSpec(_Model):
    """Indicative costs: bars by weight (material price) plus installation; tie-rods by their
    steel, plates and installation (each tie has two plates, one at each end)."""

    currency: FreeText = Field(
        "EUR", max_length=12, description="Currency of all prices (text, at most 12 characters)."
    )
    installation_per_metre: Number = Field(
        0.0,
        ge=0,
        le=1e6,
        description="Installation [currency per metre of wall length per layer of "
        "bars] (centred: 1 layer, external: 2), 0-1e6; default 0: bars only.",
    )
    tie_steel_per_kg: Number = Field(
        0.0,
        ge=0,
        le=MAX_TIE_PRICE,
        description="A tie's bar [currency/kg of steel], 0-1e6; default 0 (not given).",
    )
    tie_steel_per_metre: Number = Field(
        0.0,
        ge=0,
        le=MAX_TIE_PRICE,
        description="A tie's bar [currency per metre of bar], 0-1e6, added to the price per kg; "
        "default 0 (not given).",
    )
    tie_plate: Number = Field(
        0.0,
        ge=0,
        le=MAX_TIE_PRICE,
        description="An anchorage plate [currency per plate; two per tie], 0-1e6; default 0.",
    )
    tie_installation: Number = Field(
        0.0,
        ge=0,
        le=MAX_TIE_PRICE,
        description="Installing one tie (drilling, threading, tensioning) [currency per tie], "
        "0-1e6; default 0.",
    )


# ---------------------------------------------------------------------------------- report
#: languages of the report (the console and the TUI stay English)
ReportLanguage = Literal["en", "it"]


class ReportSpec(_Model):
    """The written report: its language and, for the Word file, a firm's template."""

    language: ReportLanguage = Field(
        "en", description="Language of the report: en (English) | it (Italian); default en."
    )
    template: FreeText | None = Field(
        None,
        max_length=1000,
        description="Word file (.docx) whose styles, page and header the DOCX report uses, "
        "relative to the project file (optional).",
    )
