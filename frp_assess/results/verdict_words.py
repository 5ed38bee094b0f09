"""The words every output uses for the decision of a case (the console's ranking, results.csv,
the TUI's ranking): read from results.json's decision only (``passes``, ``recommended``,
``retrofit_required``, ``input_code_compliant``, ``governing_check``), never recomputed.

- :func:`verdict_word`: "recommended", "passes", "fails" or "—" (a file written before the
  decision);
- :func:`governing_short`: the governing check's short name for a narrow column, with
  :data:`GOVERNING_LEGEND` saying what each short name is;
- :func:`in_language`: a word or check in Italian for results.csv of an Italian report;
- :func:`category_line`: what "passes" asks of an option under the category of the
  intervention (results.json ``intervention``, NTC 2018 §8.4).
"""

from __future__ import annotations

from frp_assess.results.model import AssessmentResult, CaseResult

__all__ = [
    "FAILS",
    "GOVERNING_LEGEND",
    "PASSES",
    "RECOMMENDED",
    "UNDECIDED",
    "ITALIAN",
    "category_line",
    "governing_short",
    "in_language",
    "is_recommendation",
    "verdict_word",
]

RECOMMENDED = "recommended"
PASSES = "passes"
FAILS = "fails"
UNDECIDED = "—"

#: short names of the deciding checks (results.json ``governing_check``) for narrow columns
_SHORT = {
    "IDA capacity/demand": "IDA",
    "time history SLV": "TH SLV",
    "time history SLC": "TH SLC",
    "pivot check": "pivot",
}

#: what the short names of :func:`governing_short` stand for, one line
GOVERNING_LEGEND = (
    "IDA: design a_dyn/(FC·a_g·S) against the target; TH SLV, TH SLC: time-history check "
    "of Circolare 2019 §C8.7.1.2.1.9 at SLV, SLC"
)


def is_recommendation(results: AssessmentResult, case: CaseResult) -> bool:
    """``case`` is the option the decision tells the engineer to install: the recommended
    option (results.json ``recommended``) of a wall that needs a retrofit
    (``retrofit_required``), with code-compliant records.  The cheapest passing option of a
    wall that passes unreinforced is optional margin, not a recommendation."""
    return (
        case.passes is True
        and not case.is_unreinforced
        and case.name == results.recommended
        and results.retrofit_required
        and results.input_code_compliant
    )


def verdict_word(results: AssessmentResult, case: CaseResult) -> str:
    """The decision on ``case`` in one word: :data:`RECOMMENDED` (:func:`is_recommendation`),
    :data:`PASSES` (every deciding check passes), :data:`FAILS`, or :data:`UNDECIDED` for a
    file written before the decision (``passes`` null)."""
    if case.passes is None:
        return UNDECIDED
    if not case.passes:
        return FAILS
    return RECOMMENDED if is_recommendation(results, case) else PASSES


#: the verdict words and deciding checks in Italian (results.csv of an Italian report); the
#: words of the report itself are report/catalogue/it.json's
ITALIAN = {
    RECOMMENDED: "proposta",
    PASSES: "supera",
    FAILS: "non supera",
    "IDA capacity/demand": "capacità/domanda IDA",
    "time history SLV": "verifica dinamica non lineare SLV",
    "time history SLC": "verifica dinamica non lineare SLC",
    "pivot check": "verifica alla cerniera",
}


def in_language(word: str, language: str) -> str:
    """A verdict word or deciding check of this module in ``language`` ("it": Italian,
    :data:`ITALIAN`; else, or a word it does not know, as it is)."""
    return ITALIAN.get(word, word) if language == "it" else word


def governing_short(check: str | None) -> str:
    """The governing check's short name (:data:`GOVERNING_LEGEND`); another name as it is,
    "—" for none."""
    if check is None:
        return UNDECIDED
    return _SHORT.get(check, check)


def category_line(results: AssessmentResult) -> str:
    """What an option's "passes" means under the category of the intervention (results.json
    ``intervention``; a file without it was judged as an upgrade), one line: the category,
    its clause and the ζ_E every deciding check must reach; the wall as it is is judged by
    the assessment."""
    iv = results.intervention
    if iv is None or iv.category == "upgrade":
        return (
            "options judged as an upgrade (NTC 2018 §8.4.3): every deciding check ζ_E ≥ 1 "
            f"(the IDA's ≥ the target {results.model.target:g})"
        )
    if iv.category == "local":
        return (
            f"options judged as a local intervention ({iv.clause}): the check governing the "
            f"wall as it is above its ζ_E {iv.as_is_zeta:.2f}, no other below its own or the "
            "assessment's; margin: ζ_E over that; the wall as it is by the assessment (ζ_E ≥ 1)"
        )
    school = " school" if iv.school else ""
    return (
        f"options judged as an improvement ({iv.clause}, use class {iv.use_class}{school}): "
        f"every deciding check ζ_E ≥ {iv.required_zeta:.2f} (the wall as it is: "
        f"{iv.as_is_zeta:.2f}); margin: ζ_E over {iv.required_zeta:.2f}; the wall as it is by "
        "the assessment (ζ_E ≥ 1)"
    )
