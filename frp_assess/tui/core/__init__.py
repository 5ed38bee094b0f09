"""The TUI's logic without Textual: what the screens show and do, testable headless.

Nothing here imports Textual (tests/tui/test_imports.py checks it); the widgets of
:mod:`frp_assess.tui` call these modules.
"""
