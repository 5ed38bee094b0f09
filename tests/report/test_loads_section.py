"""The report's loads part (docs/model.md §12): every load with its lever and whether its mass
moves with the wall, α₀ term by term, the assumptions §12 does not model, in English and
Italian, PDF and Word alike; nothing of it without loads."""

from __future__ import annotations

import json
import string
from dataclasses import replace
from importlib import resources
from pathlib import Path

import pytest

from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.loads_record import loads_result
from frp_assess.report.doc_model import plain_texts
from frp_assess.report.document import build_document
from frp_assess.report.lang import LANGUAGES
from frp_assess.results.json_io import from_json
from frp_assess.results.model import AssessmentResult, ReportSettings

DATA = Path(__file__).parent / "data" / "results.json"
FIXTURE = Path(__file__).parents[1] / "fixtures" / "facade-loads.yaml"


def _results(code: str, loads: bool = True) -> AssessmentResult:
    base = from_json(DATA.read_text(encoding="utf-8"), file=str(DATA))
    record = loads_result(load_inputs(FIXTURE, warn=None)) if loads else None
    return replace(base, report=ReportSettings(language=code), loads=record)


def test_the_part_catalogues_agree() -> None:
    """loads-en.json and loads-it.json: the same keys, the same placeholders, tags closed."""
    cats = {}
    for code in LANGUAGES:
        path = resources.files("frp_assess.report").joinpath("catalogue", f"loads-{code}.json")
        cats[code] = json.loads(path.read_text(encoding="utf-8"))
    fmt = string.Formatter()
    for code, cat in cats.items():
        assert set(cat) == set(cats["en"]), code
        for key, text in cat.items():
            names = sorted(f[1] for f in fmt.parse(text) if f[1] is not None)
            assert names == sorted(f[1] for f in fmt.parse(cats["en"][key]) if f[1]), key
            assert text.count("<sub>") == text.count("</sub>"), key


@pytest.mark.parametrize(
    ("code", "heading", "carried", "restrained", "assumption"),
    [
        ("en", "Loads on the wall", "carried", "restrained", "Masses that push on the wall"),
        ("it", "Carichi sulla parete", "trascinata", "trattenuta", "Le masse che spingono"),
    ],
)
def test_every_load_its_lever_its_mass_and_alpha0_term_by_term(
    code: str, heading: str, carried: str, restrained: str, assumption: str
) -> None:
    """The fixture's floor (10 kN/m at d = 0.3 m, carried), roof (restrained), thrust
    (h = 5.5 m) and tie (h_t = 5.8 m); α₀'s terms W·B/2 = 43.2·0.2 = 8.640 kNm/m and the
    tie's work 24.61·5.8 = 142.733 kNm/m; the sum line with α₀."""
    texts = plain_texts(build_document(_results(code)))
    start = next(i for i, t in enumerate(texts) if t.endswith(heading))
    part = texts[start : start + 80]
    sep = "," if code == "it" else "."
    for cell in (f"d = 0{sep}300", f"h = 5{sep}500", f"h = 5{sep}800", carried, restrained,
                 f"8{sep}640", f"142{sep}733", "first floor", "rafters", "catena"):  # fmt: skip
        assert cell in part, cell
    record = loads_result(load_inputs(FIXTURE, warn=None))
    assert record is not None
    alpha0 = f"{record.overturning.alpha0:.4f}".replace(".", sep)
    assert any(t.startswith("α0 = (") and alpha0 in t for t in part)
    assert sum(t.startswith("• " + assumption) for t in texts) == 1


def test_no_loads_no_part() -> None:
    """A results.json without loads: the report has no loads heading and no loads assumption
    (the golden reports are byte-identical, tests/golden)."""
    for code, word in (("en", "Loads on the wall"), ("it", "Carichi sulla parete")):
        texts = plain_texts(build_document(_results(code, loads=False)))
        assert not any(word in t for t in texts)


@pytest.mark.parametrize("code", LANGUAGES)
def test_pdf_and_docx_show_the_loads_alike(code: str, tmp_path: Path) -> None:
    """The loads part reads the same in the PDF story, the Word file and the document model."""
    from tests.report.test_document_model import renderers_agree

    texts = renderers_agree(_results(code), tmp_path)
    assert any(t.endswith(("Loads on the wall", "Carichi sulla parete")) for t in texts)
