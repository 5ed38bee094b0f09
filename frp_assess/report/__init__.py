"""The assessment report, built from results.json only (docs/results-json.md): one document
model (:mod:`frp_assess.report.doc_model`) drawn as PDF and as editable DOCX, in English or
Italian (results.json ``report.language``)."""

from __future__ import annotations

from frp_assess.report.document import (
    build_document,
    build_docx,
    build_report,
    build_story,
    load_results,
)

__all__ = ["build_docx", "build_document", "build_report", "build_story", "load_results"]
