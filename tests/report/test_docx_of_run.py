"""The run writes report.docx beside report.pdf (frp_assess.app.report.write_outputs): the
same document, kept when results.json is unchanged, left out with one warning line (the rest
of the set written) when it cannot be made."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from types import SimpleNamespace
from typing import cast

import docx
import pytest

from frp_assess.app.report import build_word, write_outputs
from frp_assess.assess.seismic import SeismicInput
from frp_assess.report import load_results
from frp_assess.results.model import ReportSettings

DATA = Path(__file__).with_name("data")


def _no_records() -> SeismicInput:
    """A seismic input with no records to write (write_outputs only reads ``records``)."""
    return cast(SeismicInput, SimpleNamespace(records=[], state_records={}))


def test_the_set_holds_both_reports_kept_while_the_results_are_the_same(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    results = load_results(DATA)
    out = tmp_path / "out"
    write_outputs(results, _no_records(), out, pdf=True)
    assert (out / "report.pdf").read_bytes().startswith(b"%PDF")
    assert (out / "report.docx").read_bytes().startswith(b"PK")
    stored = (out / "report.docx").read_bytes()
    # the same results again: the stored reports are copied, not rebuilt
    import frp_assess.app.report as app_report

    def not_rebuilt(*args: object) -> bool:
        raise AssertionError("a report of the same results was rebuilt")

    with monkeypatch.context() as m:
        m.setattr(app_report, "build_word", not_rebuilt)
        m.setattr(app_report, "build_pdf", not_rebuilt)
        write_outputs(results, _no_records(), out, pdf=True)
    assert (out / "report.docx").read_bytes() == stored
    # other results whose DOCX cannot be made: no report.docx (not the stale one), the rest
    bad = tmp_path / "firm.docx"
    bad.write_text("not a zip", encoding="utf-8")
    other = dataclasses.replace(results, report=ReportSettings(language="en", template=str(bad)))
    capsys.readouterr()
    write_outputs(other, _no_records(), out, pdf=True)
    assert "report.docx not written" in capsys.readouterr().err
    assert not (out / "report.docx").exists()
    assert (out / "report.pdf").is_file() and (out / "results.json").is_file()
    # --no-pdf: neither report
    write_outputs(results, _no_records(), out, pdf=False)
    assert not (out / "report.pdf").exists() and not (out / "report.docx").exists()


def test_a_docx_template_that_cannot_be_read_is_a_warning_not_a_failure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "firm.docx"
    bad.write_text("not a zip", encoding="utf-8")
    results = dataclasses.replace(
        load_results(DATA), report=ReportSettings(language="it", template=str(bad))
    )
    assert build_word(results, tmp_path / "report.docx") is False
    err = capsys.readouterr().err
    assert err.startswith("frp-assess: warning: report.docx not written: ")
    assert err.count("\n") == 1 and "the other results are complete" in err
    assert not (tmp_path / "report.docx").exists()


def test_the_docx_is_the_reports_document(tmp_path: Path) -> None:
    results = load_results(DATA)
    assert build_word(results, tmp_path / "report.docx") is True
    doc = docx.Document(str(tmp_path / "report.docx"))
    text = "\n".join(p.text for p in doc.paragraphs)
    assert results.project.name in text
