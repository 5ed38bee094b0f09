"""The table builders' shared pieces (plain text, not markup): :class:`TableData`, the
cutting of a table with a column per record, and the helpers every annex and body table
uses.  Numbers in the language's format come from :class:`~frp_assess.report.lang.Lang`
(accelerations in g with 3 decimals, ratios with 2, masses in kg with 1, costs with 0 and
grouped thousands); here only what needs more: ρ in ‰ (:func:`permille`), capacity/demand
against its verdict (:func:`capacity_text`), and the run's English prose
(:func:`run_text`: shown in an English report only).
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.numbers import fmt_against
from frp_assess.report.lang import Lang
from frp_assess.results.model import AssessmentResult, CaseResult

Results = AssessmentResult

DASH = "—"


@dataclass(frozen=True)
class TableData:
    """Header (plain text or :class:`Markup`) and body rows (plain text)."""

    header: list[str]
    rows: list[list[str]]


#: most record columns one table of a page's width holds; more are split into several tables
RECORD_COLUMNS = 10


def column_blocks(
    table: TableData, keep: int = 1, per_block: int = RECORD_COLUMNS
) -> list[TableData]:
    """``table`` cut into tables of at most ``per_block`` columns after its first ``keep``
    (repeated in each): a table with a column per record stays readable for any number of
    records (100 records made one table of 101 columns that no page could hold)."""
    rest = len(table.header) - keep
    if rest <= per_block:
        return [table]
    blocks = []
    for start in range(keep, len(table.header), per_block):
        cols = list(range(keep)) + list(range(start, min(start + per_block, len(table.header))))
        blocks.append(
            TableData(
                [table.header[c] for c in cols], [[row[c] for c in cols] for row in table.rows]
            )
        )
    return blocks


# --- number formats -----------------------------------------------------------------------


def fmt_capacity(case: CaseResult, target: float) -> str:
    """capacity/demand of a case with enough decimals to agree with its verdict against
    ``target`` (0.997 → '0.997', not '1.00', when it does not meet 1)."""
    return fmt_against(case.capacity_demand, target, case.meets_target)


def fmt_permille(x: float | None) -> str:
    """ρ in ‰: at most 2 decimals, trailing zeros dropped (2 → '2', 1.579 → '1.58')."""
    if x is None:
        return DASH
    return f"{x:.2f}".rstrip("0").rstrip(".")


# --- helpers on the results ---------------------------------------------------------------


def ranked_options(results: Results) -> list[CaseResult]:
    """Retrofit options by rank (1 first); unranked options last, in file order."""
    opts = list(results.options)
    return sorted(opts, key=lambda c: (c.rank is None, c.rank or 0))


def bound(text: str, lower: bool) -> str:
    return f"≥ {text}" if lower and text != DASH else text


def case_by_name(results: Results, name: str | None) -> CaseResult | None:
    for c in results.cases:
        if c.name == name:
            return c
    return None


def crushing_shift(results: Results) -> float | None:
    """x [m] of the unreinforced wall's crushing pivot, None when its model turns about the
    edge (docs/model.md §1.1): results.json ``wall.a_rm`` is about that pivot."""
    piv = results.urm.pivot
    if piv is None or piv.model_pivot != "crushing" or piv.pivot_shift <= 0.0:
        return None
    return piv.depth


def design_strain(results: Results) -> bool:
    """True when the bars' rupture strain is the design value c·η_a·ε_fk/γ_f (some option
    has bars as built with ``bars.design_values``), False for the mean c·ε_u (docs/model.md
    §2.1)."""
    return any(c.as_built is not None and c.as_built.strain.design_values for c in results.cases)


def rupture_strain_words(results: Results) -> str:
    """ε_max in symbols, as the model used it: c·η_a·ε_fk/γ_f or c·ε_u."""
    return "c·η_a·ε_fk/γ_f" if design_strain(results) else "c·ε_u"


def permille(x: float | None, lang: Lang) -> str:
    """ρ in ‰: at most 2 decimals, trailing zeros dropped (2 → '2', 1.579 → '1.58'), the
    language's decimal separator."""
    return lang.numbers_in(fmt_permille(x))


def capacity_text(case: CaseResult, target: float, lang: Lang) -> str:
    """:func:`fmt_capacity` with the language's decimal separator."""
    return lang.numbers_in(fmt_capacity(case, target))


def shows_run_prose(lang: Lang) -> bool:
    """The prose the run writes into results.json is English: a report in English shows it,
    one in another language rebuilds its words from the values or leaves it out."""
    return lang.code == "en"


def run_text(text: str | None, lang: Lang) -> str:
    """Prose the run wrote in English into results.json (a compliance requirement, a pivot
    reason, the ranking rule...): shown as written in an English report; in another language
    the phrase of the catalogue when it has one (:meth:`Lang.run_phrase`), else a dash (the
    annex rebuilds what it can from the values)."""
    translated = lang.run_phrase(text) if text and not shows_run_prose(lang) else None
    return run_words(text, lang) or translated or DASH


def source_text(text: str | None, lang: Lang) -> str:
    """Where a value comes from, as results.json says it: the library's and the run's own
    phrases in the language (:meth:`Lang.run_phrase`); anything else is the user's own text
    (a material's ``source`` in the project file), shown as written."""
    if not text:
        return DASH
    if shows_run_prose(lang):
        return text
    return lang.run_phrase(text) or text


def run_words(text: str | None, lang: Lang) -> str | None:
    """:func:`run_text` for a paragraph: the run's English prose, None in another language
    or when there is none."""
    return text if text and shows_run_prose(lang) else None
