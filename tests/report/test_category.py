"""The report's category of the intervention (report/body_front.py) from results.json's
``intervention``, in both languages: what NTC 2018 §8.4.1-§8.4.3 ask, with the run's numbers."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.report.body_front import category, category_paragraph
from frp_assess.report.lang import Lang
from frp_assess.report.verdict_text import category_sentence, option_target
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.results.verdict import InterventionResult

FIXTURE = Path(__file__).with_name("data") / "results.json"


def results(category: str, use_class: str | None = None, school: bool = False,
            required: float = 1.0, strict: bool = False) -> AssessmentResult:  # fmt: skip
    base = from_json(FIXTURE.read_text(encoding="utf-8"), file="results.json")
    clause = {"local": "§8.4.1", "improvement": "§8.4.2", "upgrade": "§8.4.3"}[category]
    iv = InterventionResult(category, f"NTC 2018 {clause}", use_class, school, 0.45, required,
                            strict)  # fmt: skip
    return replace(base, intervention=iv)


@pytest.mark.parametrize("code", ["en", "it"])
def test_each_category_names_its_clause_and_what_it_needs(code: str) -> None:
    """Upgrade: §8.4.3 and ζ_E ≥ 1; improvement of class II: §8.4.2, 0.45 + 0.1 = 0.55;
    class IV: 0.6; local: §8.4.1 and the unreinforced 0.45 (decimal comma in Italian)."""
    lang = Lang(code)
    comma = "," if code == "it" else "."
    up = category_paragraph(results("upgrade"), lang)
    assert "§8.4.3" in up and "ζ_E ≥ 1" in up
    ii = category_paragraph(results("improvement", "II", required=0.55), lang)
    assert "§8.4.2" in ii and f"ζ_E ≥ 0{comma}55" in ii and f"0{comma}45" in ii
    assert f"0{comma}1" in ii
    iv = category_paragraph(results("improvement", "IV", required=0.6), lang)
    assert f"ζ_E ≥ 0{comma}60" in iv and f"0{comma}6 " in iv
    school = category_paragraph(results("improvement", "III", True, required=0.6), lang)
    assert ("school" if code == "en" else "scolastico") in school
    local = category_paragraph(results("local", required=0.45, strict=True), lang)
    assert "§8.4.1" in local and f"ζ_E = 0{comma}45" in local


def test_an_older_file_reads_as_the_upgrade_it_was_judged_by() -> None:
    """A results.json without ``intervention`` was decided at ζ_E ≥ 1: the upgrade's words,
    and no paragraph on the time histories' ζ_E."""
    old = replace(results("upgrade"), intervention=None)
    lang = Lang("en")
    assert category_paragraph(old, lang) == category_paragraph(results("upgrade"), lang)
    assert len(category(old, lang)) == 3  # heading, the upgrade, the building's checks


def test_below_one_the_time_history_zeta_is_said_to_be_a_displacement_ratio() -> None:
    blocks = category(results("improvement", "II", required=0.55), Lang("en"))
    assert len(blocks) == 5
    assert len(category(results("upgrade"), Lang("en"))) == 4


@pytest.mark.parametrize("code", ["en", "it"])
def test_the_conclusion_says_how_the_options_were_judged(code: str) -> None:
    """The one verdict source (report/verdict_text.py) names the category and its clause in
    the conclusion; a file without ``intervention`` gets no such sentence."""
    lang = Lang(code)
    sentence = category_sentence(results("improvement", "II", required=0.55), lang)
    assert sentence is not None and "NTC 2018 §8.4.2" in sentence
    assert ("an improvement" if code == "en" else "miglioramento") in sentence
    assert category_sentence(replace(results("upgrade"), intervention=None), lang) is None


def test_the_ranking_rule_states_what_an_option_must_reach() -> None:
    """The upgrade keeps the target (1 in the fixture); an improvement names the category."""
    assert option_target(results("upgrade"), Lang("en")) == "1"
    assert option_target(results("improvement", "II"), Lang("en")) == "the ζ_E an improvement asks"
    it = option_target(results("local"), Lang("it"))
    assert it == "lo ζ_E richiesto per un intervento locale"
