"""A record set that fails the code's spectrum-compatibility checks gives results marked
"input not code-compliant" and no option called "recommended" (issue 15 §3)."""

from __future__ import annotations

import copy

from frp_assess.numbers import recommendation_label
from frp_assess.report import build_story
from tests.report.test_report import raw, story_text, typed

load = raw


def test_label_follows_the_compliance_of_the_records():
    r = load()
    r["input_code_compliant"] = True
    assert recommendation_label(typed(r)) == "Recommended"
    r["input_code_compliant"] = False
    assert recommendation_label(typed(r)) == "Best ranked (input not code-compliant)"


def test_report_on_non_compliant_input_recommends_nothing():
    compliant = load()
    compliant["input_code_compliant"] = True
    failing = copy.deepcopy(compliant)
    failing["input_code_compliant"] = False
    failing["compliance"]["passed"] = False
    assert compliant["recommended"] is not None
    ok_text = story_text(build_story(typed(compliant)))
    bad_text = story_text(build_story(typed(failing)))
    assert "Input not code-compliant" not in ok_text
    assert "Recommended retrofit." in ok_text or "No retrofit is needed" in ok_text
    assert "Input not code-compliant" in bad_text
    assert "Best ranked retrofit." in bad_text
    said = bad_text.replace("no option is recommended", "").replace("nothing is recommended", "")
    assert "recommended" not in said.lower()


def test_label_names_no_recommendation_when_the_decision_names_none():
    """Nothing to install (the wall passes as it is, or no option passes): the console's
    line is the decision's, never "Recommended: …" (issue 39)."""
    r = load()
    r["input_code_compliant"] = True
    r["retrofit_required"] = False
    assert recommendation_label(typed(r)) == "Decision"
    r["retrofit_required"] = True
    r["recommended"] = None
    assert recommendation_label(typed(r)) == "Decision"
    r["input_code_compliant"] = False
    assert recommendation_label(typed(r)) == "Decision (input not code-compliant)"
