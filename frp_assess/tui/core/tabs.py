"""The main tabs of the TUI and which tab edits which key of the project."""

from __future__ import annotations

from frp_assess.config.messages import Loc

#: (DOM id, title) of the tabs, in order (F2 … F10, or alt+1 … alt+9)
TABS: tuple[tuple[str, str], ...] = (
    ("tab-wall", "Wall"),
    ("tab-site", "Site"),
    ("tab-records", "Records"),
    ("tab-materials", "Materials"),
    ("tab-retrofits", "Retrofits"),
    ("tab-analysis", "Analysis"),
    ("tab-run", "Run"),
    ("tab-results", "Results"),
    ("tab-history", "Time history"),
)


def tab_of(path: Loc) -> str:
    """The tab where the field of a key path is edited."""
    head = path[0] if path else "wall"
    if head in ("project", "wall", "building"):
        return "tab-wall"
    if head == "seismic":
        return "tab-records" if path[1:2] == ("records",) else "tab-site"
    if head == "materials":
        return "tab-materials"
    if head == "interventions":
        return "tab-retrofits"
    return "tab-analysis"


def tab_title(tab_id: str) -> str:
    """The title of a tab (``tab-wall`` -> ``Wall``)."""
    return dict(TABS)[tab_id]
