"""A building's report, PDF and Word (:mod:`frp_assess.report.building_pdf`): a report that
cannot be made is one warning line and no file, the rest of the set is written (as a wall's
report, :func:`frp_assess.app.report.build_pdf`)."""

from __future__ import annotations

from pathlib import Path

from frp_assess.app.report import report_warning
from frp_assess.results.building_summary import BuildingResults

__all__ = ["build_building_docx", "build_building_pdf"]


def build_building_pdf(b: BuildingResults, path: Path, language: str) -> bool:
    """The building's report.pdf; returns whether it was written."""
    try:
        from frp_assess.report.building_pdf import build_building_pdf as build
    except ImportError as exc:
        report_warning("report.pdf", f"reportlab is not installed: {exc}")
        return False
    try:
        build(b, path, language)
    except (OSError, MemoryError):  # a full disk is not the report's fault: the set fails
        raise
    except Exception as exc:  # reportlab's LayoutError, ...
        report_warning("report.pdf", str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
        return False
    return True


def build_building_docx(
    b: BuildingResults, path: Path, language: str, template: str | None = None
) -> bool:
    """The building's report.docx; returns whether it was written."""
    try:
        from frp_assess.report.building_pdf import build_building_docx as build
    except ImportError as exc:
        report_warning("report.docx", f"python-docx or reportlab is not installed: {exc}")
        return False
    try:
        build(b, path, language, template)
    except (OSError, MemoryError):
        raise
    except Exception as exc:  # a template python-docx cannot read, ...
        report_warning("report.docx", str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
        return False
    return True
