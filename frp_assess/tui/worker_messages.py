"""Messages the app's worker threads post to it (run, last results, export)."""

from __future__ import annotations

from pathlib import Path

from textual.message import Message

from frp_assess.tui.core.session import RunEvent, RunOutcome


class RunProgress(Message):
    """A progress event of the run (posted from the worker thread)."""

    def __init__(self, event: RunEvent) -> None:
        super().__init__()
        self.event = event


class RunDone(Message):
    """The run ended: status ``done`` | ``cancelled`` | ``error``."""

    def __init__(self, status: str, outcome: RunOutcome | None, message: str) -> None:
        super().__init__()
        self.status, self.outcome, self.message = status, outcome, message


class PreviousLoaded(Message):
    """The results of the last run at start: as stored when the project file is unchanged
    since, else rebuilt from the cache (None: none match)."""

    def __init__(self, outcome: RunOutcome | None, error: str = "") -> None:
        super().__init__()
        self.outcome, self.error = outcome, error


class ExportDone(Message):
    """The export ended: the files written, or the error (one line)."""

    def __init__(self, files: list[Path], error: str = "") -> None:
        super().__init__()
        self.files, self.error = files, error
