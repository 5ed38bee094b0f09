"""Exceptions shared by every layer.

`InputError` is what a user can fix: a bad argument, a malformed record file, an invalid
project file.  Its ``str()`` is the one line the CLI prints (``file:line: key: message``);
the CLI maps it to exit code 2 without a traceback.
"""

from __future__ import annotations


class FrpAssessError(Exception):
    """Base class of every error raised on purpose by frp_assess."""


class InputError(FrpAssessError):
    """Invalid user input; carries where it came from (file, line, key path)."""

    def __init__(
        self,
        message: str,
        *,
        file: str | None = None,
        line: int | None = None,
        key: str | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.file = file
        self.line = line
        self.key = key

    def __str__(self) -> str:
        where = ""
        if self.file is not None:
            where = str(self.file)
            if self.line is not None:
                where += f":{self.line}"
            where += ": "
        key = f"{self.key}: " if self.key else ""
        return f"{where}{key}{self.message}"


class NumericalError(FrpAssessError):
    """The integrator could not finish a time history as specified (e.g. the wall's fate
    still undecided after the longest free vibration followed).  Not the user's input: the
    message says which run, and the CLI gives exit code 1 with that one line."""


class Cancelled(FrpAssessError):
    """A long computation was cancelled by the caller (Ctrl-C, Cancel button)."""
