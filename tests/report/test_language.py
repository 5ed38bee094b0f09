"""The project file's ``report:`` block (language, Word template) reaches results.json, and
``frp-assess report DIR`` rebuilds the report in that language, as PDF or DOCX."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import docx
import pytest

from frp_assess.assess.from_project import inputs_from_project
from frp_assess.cli import main
from frp_assess.config import load_project_text, validate_data
from frp_assess.errors import InputError
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import ReportSettings
from tests.report.test_report import DATA

MINIMAL = """\
wall: {thickness: 0.3, height: 2.5, masonry: rubble-stone, mechanism: two-sided}
seismic:
  spectrum: {type: preset, name: A2}
"""


def test_the_report_block_defaults_to_english_and_maps_onto_the_inputs(tmp_path: Path) -> None:
    project = load_project_text(MINIMAL, "mini.yaml").project
    assert (project.report.language, project.report.template) == ("en", None)
    assert inputs_from_project(project, Path(".")).report == ReportSettings("en", None)
    text = MINIMAL + "report: {language: it, template: firm.docx}\n"
    given = load_project_text(text, "mini.yaml").project
    with pytest.raises(InputError, match="no such file") as err:
        inputs_from_project(given, tmp_path)
    assert err.value.key == "report.template"
    docx.Document().save(str(tmp_path / "firm.docx"))
    inputs = inputs_from_project(given, tmp_path)
    assert inputs.report == ReportSettings("it", str(tmp_path / "firm.docx"))


@pytest.mark.parametrize(
    ("block", "said"),
    [("{language: fr}", "report.language"), ("{langauge: it}", "report.langauge")],
)
def test_a_wrong_report_block_is_one_line_naming_the_key(block: str, said: str) -> None:
    with pytest.raises(InputError) as err:
        load_project_text(MINIMAL + f"report: {block}\n", "mini.yaml")
    assert said in str(err.value) and "\n" not in str(err.value)


def test_the_json_schema_documents_the_report_block() -> None:
    from frp_assess.config import Project

    schema = Project.model_json_schema()
    assert "report" in schema["properties"]
    spec = schema["$defs"]["ReportSpec"]
    assert spec["properties"]["language"]["enum"] == ["en", "it"]
    assert (
        validate_data(
            {
                "wall": {
                    "thickness": 0.3,
                    "height": 2.5,
                    "unit_weight": 18,
                    "mechanism": "one-sided",
                },
                "seismic": {"spectrum": {"type": "preset", "name": "A2"}},
                "report": {"language": "it"},
            }
        ).report.language
        == "it"
    )


def _results_dir(tmp_path: Path, language: str) -> Path:
    d = tmp_path / "results"
    d.mkdir()
    data = json.loads(DATA.read_text(encoding="utf-8"))
    data["report"] = {"language": language, "template": None}
    text = json.dumps(data, ensure_ascii=False, indent=1) + "\n"
    assert from_json(text).report == ReportSettings(language, None)
    (d / "results.json").write_text(to_json(from_json(text)), encoding="utf-8")
    return d


def test_report_command_rebuilds_in_the_language_of_the_results(tmp_path: Path) -> None:
    d = _results_dir(tmp_path, "it")
    assert main(["report", str(d), "--docx"]) == 0
    body = [p.text for p in docx.Document(str(d / "report.docx")).paragraphs]
    assert any(t.startswith("1  Premessa e oggetto") for t in body)
    assert any(t.startswith("11  Analisi e verifiche svolte con l'ausilio") for t in body)
    assert main(["report", str(d), "--out", str(tmp_path / "again.docx")]) == 0
    assert (tmp_path / "again.docx").read_bytes() == (d / "report.docx").read_bytes()
    assert main(["report", str(d)]) == 0
    pdf = (d / "report.pdf").read_bytes()
    assert pdf.startswith(b"%PDF")
    shutil.copy(d / "report.pdf", tmp_path / "first.pdf")
    assert main(["report", str(d)]) == 0
    assert (d / "report.pdf").read_bytes() == (tmp_path / "first.pdf").read_bytes()


@pytest.mark.parametrize("recorded", [False, True])
def test_every_compliance_phrase_reads_in_italian(recorded: bool) -> None:
    """The compliance table's requirement and found columns are the run's English phrases
    (motions/compliance.py); the Italian annex shows each in Italian with decimal commas
    (a dash before).  Every phrase check_compliance writes — passing and failing sets, an
    artificial and a recorded set — has a pattern, so a new phrase fails here first."""
    from frp_assess.motions.compliance import check_compliance
    from frp_assess.motions.record import Record
    from frp_assess.motions.spectra import preset_spectrum
    from frp_assess.report.formats import DASH, run_text
    from frp_assess.report.lang import Lang
    from tests.conftest import synthetic_record

    it = Lang("it")
    sets = [
        [Record(f"n{i}", 0.01, synthetic_record(i, duration=30.0, pga_g=0.3)) for i in range(7)],
        [Record(f"s{i}", 0.01, synthetic_record(i, duration=8.0)) for i in range(2)],
    ]
    phrases = set()
    for records in sets:
        report = check_compliance(records, preset_spectrum("A2"), recorded=recorded)
        phrases |= {p for c in report.checks for p in (c.requirement, c.found)}
    assert len(phrases) >= 6
    for phrase in phrases:
        words = run_text(phrase, it)
        assert words != DASH, phrase
        assert words != phrase and "." not in words.replace("min.", "").replace("max.", ""), (
            phrase,
            words,
        )
    assert run_text("min 96.4% at T = 0.377 s", it) == "min. 96,4% a T = 0,377 s"
    assert run_text("at least 3 records", it) == "almeno 3 accelerogrammi"
    assert run_text("min 96.4% at T = 0.377 s", Lang("en")) == "min 96.4% at T = 0.377 s"


def test_material_sources_read_in_italian_and_the_users_as_written() -> None:
    """A material's source in the Italian annex: the library's English phrases
    (config/library.py) and the project file's defaults in Italian (a dash before); a source
    the user wrote is shown as written."""
    from frp_assess.config.library import FRP_MATERIALS
    from frp_assess.report.formats import source_text
    from frp_assess.report.lang import Lang

    it = Lang("it")
    sources = {m.source for m in FRP_MATERIALS.values()} | {
        "user input",
        "user input (overrides the library)",
    }
    for source in sources:
        words = source_text(source, it)
        assert words not in (source, "—"), source
        assert "dati" in words or "dato" in words, (source, words)
    own = "scheda tecnica del produttore, 2024"
    assert source_text(own, it) == own
    assert source_text("typical producer data", Lang("en")) == "typical producer data"
