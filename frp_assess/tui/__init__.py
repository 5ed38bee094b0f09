"""`frp-assess tui`: the terminal user interface (Textual).

Only this package imports Textual; the numerics (:mod:`frp_assess.dynamics`), the ground
motions (:mod:`frp_assess.motions`) and the project file (:mod:`frp_assess.config`) never do
(``tests/tui/test_imports.py``).

:mod:`frp_assess.tui.core` holds the TUI's logic without Textual (the session that runs,
loads and saves; the editing model; progress counts; text made safe to show); the other
modules are the widgets, one per file, and the app that composes them.
"""

from __future__ import annotations

__all__ = ["FrpAssessApp", "run_tui"]


def __getattr__(name: str) -> object:
    if name in __all__:
        from frp_assess.tui import building_app  # run_tui opens a building file too

        return getattr(building_app, name)
    raise AttributeError(name)
