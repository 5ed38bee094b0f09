"""The user's option names are printed as written in the Italian report (issue 36 item 7).

projects/facade-norcia-coordinates.yaml says the report prints the project's own texts, the
names of the options among them, as written; the Italian PDF and DOCX named the options only
by material, position and ρ (report/body_annex.case_label, body_checks' ranking), so the names
appeared 0 times (8 in the English report).  The example is run (``--no-pdf``), its Italian
report rendered as PDF (read back with pdftotext) and DOCX (read back with python-docx), and
every ``interventions[].name`` of the project file looked for in both.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import docx
import pytest
from ruamel.yaml import YAML

from frp_assess.cli import main
from frp_assess.report import build_docx, build_report
from frp_assess.report.document import load_results

NORCIA = Path(__file__).resolve().parents[2] / "projects" / "facade-norcia-coordinates.yaml"


def names_in_project() -> list[str]:
    data = YAML(typ="safe").load(NORCIA.read_text(encoding="utf-8"))
    return [o["name"] for o in data["interventions"]]


def one_line(text: str) -> str:
    return " ".join(text.split())


@pytest.fixture(scope="module")
def rendered(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    out = tmp_path_factory.mktemp("norcia")
    assert main(["run", str(NORCIA), "--out", str(out), "--no-pdf"]) == 0
    r = load_results(out)
    assert r.report is not None and r.report.language == "it"
    build_report(r, out / "report.pdf")
    build_docx(r, out / "report.docx")
    return out / "report.pdf", out / "report.docx"


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler-utils not installed")
def test_option_names_in_the_italian_pdf(rendered: tuple[Path, Path]) -> None:
    pdf, _ = rendered
    text = subprocess.run(
        ["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, check=True, text=True
    ).stdout
    for name in names_in_project():
        # each option: its name in the ranking, the annex's tables, the sentences
        assert one_line(text).count(name) >= 3, (name, one_line(text).count(name))


def test_option_names_in_the_italian_docx(rendered: tuple[Path, Path]) -> None:
    _, path = rendered
    d = docx.Document(str(path))
    cells = [c.text for t in d.tables for row in t.rows for c in row.cells]
    text = one_line("\n".join([p.text for p in d.paragraphs] + cells))
    for name in names_in_project():
        assert text.count(name) >= 3, (name, text.count(name))
