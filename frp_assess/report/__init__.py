"""The assessment report, built from results.json only (docs/results-json.md): one document
model (:mod:`frp_assess.report.doc_model`, built by :mod:`frp_assess.report.document`) drawn
as PDF (:mod:`frp_assess.report.pdf_document`) and as editable DOCX, in English or Italian
(results.json ``report.language``).

The public names are imported when first used (PEP 562), so that importing the document
model alone loads no renderer."""

from __future__ import annotations

from importlib import import_module
from typing import Any

#: public name -> the module that defines it
_PUBLIC = {
    "build_document": "frp_assess.report.document",
    "build_docx": "frp_assess.report.document",
    "load_results": "frp_assess.report.document",
    "build_report": "frp_assess.report.pdf_document",
    "build_story": "frp_assess.report.pdf_document",
}
__all__ = sorted(_PUBLIC)


def __getattr__(name: str) -> Any:
    if name in _PUBLIC:
        return getattr(import_module(_PUBLIC[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
