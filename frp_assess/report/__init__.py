"""The PDF assessment report, built from results.json only (docs/results-json.md)."""

from __future__ import annotations

from frp_assess.report.document import build_report, build_story, load_results

__all__ = ["build_report", "build_story", "load_results"]
