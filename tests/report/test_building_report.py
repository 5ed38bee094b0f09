"""A building's summary and report (issue 41 item 3): the summary of two stored wall results
(tests/golden/expected: the small wall, which passes as it is, and the crushing-pivot gable,
which needs its retrofit), checked by hand against those files; the report in both languages
(catalogue/building-<code>.json), PDF and Word, the same bytes when built again."""

from __future__ import annotations

import json
import string
from importlib import resources
from pathlib import Path

import pytest

from frp_assess.report.building_document import building_document, words
from frp_assess.report.building_pdf import build_building_docx, build_building_pdf
from frp_assess.report.doc_model import plain_texts
from frp_assess.report.lang import LANGUAGES
from frp_assess.results.building_csv import building_csv
from frp_assess.results.building_summary import BuildingResults, building_results
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult
from frp_assess.results.run_inputs import ProjectInfo

EXPECTED = Path(__file__).parents[1] / "golden" / "expected"


def _stored(name: str) -> AssessmentResult:
    path = EXPECTED / name / "results.json"
    return from_json(path.read_text(encoding="utf-8"), file=str(path))


def _walls() -> list[tuple[str, str, AssessmentResult]]:
    return [
        ("Piano terra", "walls/piano-terra", _stored("small")),
        ("Timpano", "walls/timpano", _stored("building-crushing")),
    ]


def _building() -> BuildingResults:
    return building_results(
        ProjectInfo(name="Casa <&> Rossi", location="Norcia"), "b.yaml", _walls()
    )


def test_the_summary_by_hand_from_the_two_results() -> None:
    small = json.loads((EXPECTED / "small" / "results.json").read_text("utf-8"))
    gable = json.loads((EXPECTED / "building-crushing" / "results.json").read_text("utf-8"))
    b = _building()
    first, second = b.walls
    # the small wall passes as it is: nothing proposed (its cheapest option is for margin only)
    assert small["retrofit_required"] is False and small["recommended"] is not None
    assert first.verdict_before == "passes" and first.proposed is None
    assert first.verdict_after == "no retrofit needed" and first.frp_mass is None
    assert first.alpha0 == small["code_check"]["alpha0"]
    # the gable fails and its recommendation passes
    assert gable["retrofit_required"] is True
    rec = next(c for c in gable["cases"] if c["name"] == gable["recommended"])
    assert second.verdict_before == "fails" and second.proposed == rec["name"]
    assert second.verdict_after == "passes" and second.frp_mass == rec["frp_mass"]
    assert second.wall_base == gable["building"]["wall_base"]
    # totals: the gable's proposal alone; governing: the gable (margin 0.0 against 3.27)
    t = b.totals
    assert (t.walls, t.walls_failing, t.walls_retrofitted, t.walls_without_solution) == (2, 1, 1, 0)
    assert t.frp_mass == rec["frp_mass"] and t.frp_cost == rec["frp_cost"]
    urm = gable["cases"][0]
    assert t.governing_wall == "Timpano" and t.governing_margin == urm["governing_margin"] == 0.0
    assert t.governing_check == urm["governing_check"]


def test_the_csv_has_one_row_per_wall_and_case() -> None:
    rows = building_csv(_walls()).removeprefix("\ufeff").splitlines()
    cases = [len(r.cases) for _, _, r in _walls()]
    assert len(rows) == 1 + sum(cases)
    assert rows[1].startswith("Piano terra,walls/piano-terra,Unreinforced,")


def test_the_part_catalogues_agree() -> None:
    """building-en.json and building-it.json: the same keys and placeholders, tags closed."""
    cats = {}
    for code in LANGUAGES:
        path = resources.files("frp_assess.report").joinpath("catalogue", f"building-{code}.json")
        cats[code] = json.loads(path.read_text(encoding="utf-8"))
    fmt = string.Formatter()
    for code, cat in cats.items():
        assert set(cat) == set(cats["en"]), code
        for key, text in cat.items():
            names = sorted(f[1] for f in fmt.parse(text) if f[1] is not None)
            assert names == sorted(f[1] for f in fmt.parse(cats["en"][key]) if f[1]), key
            assert text.count("<sub>") == text.count("</sub>"), key
            assert text.count("<b>") == text.count("</b>"), key


@pytest.mark.parametrize(
    ("code", "heading"), [("en", "Summary of the mechanisms"), ("it", "Riepilogo dei meccanismi")]
)
def test_the_report_opens_with_the_summary(code: str, heading: str) -> None:
    doc = building_document(_building(), code)
    texts = plain_texts(doc)
    assert texts[0] == words(code)["doc.title"].format(name="Casa <&> Rossi")
    first_section = doc.sections[1]
    assert first_section.heading is not None and first_section.heading.text == f"1  {heading}"
    assert "Piano terra" in texts and "Timpano" in texts
    assert any("walls/timpano/report.pdf" in t for t in texts)  # points to each wall's report


def test_pdf_and_docx_are_the_same_bytes_built_again(tmp_path: Path) -> None:
    b = _building()
    for name, build in (("r.pdf", build_building_pdf), ("r.docx", build_building_docx)):
        build(b, tmp_path / f"1{name}", "it")
        build(b, tmp_path / f"2{name}", "it")
        first = (tmp_path / f"1{name}").read_bytes()
        assert first == (tmp_path / f"2{name}").read_bytes() and len(first) > 1000
