"""Several problems of one input file, reported together.

`frp-assess validate` prints every problem of a file, one line each (``file:line: key:
message``); code that wants only the first (``run``, the TUI) keeps catching
:class:`~frp_assess.errors.InputError`, which :class:`InputErrors` is.
"""

from __future__ import annotations

from collections.abc import Sequence

from frp_assess.errors import InputError


class InputErrors(InputError):
    """Every problem found in one input, in file order; it *is* its first problem.

    ``str()``, ``message``, ``file``, ``line`` and ``key`` are those of the first problem, so
    that code catching :class:`InputError` shows one line as before; :attr:`problems` holds
    them all.
    """

    def __init__(self, problems: Sequence[InputError]) -> None:
        if not problems:
            raise ValueError("InputErrors needs at least one problem")
        first = problems[0]
        super().__init__(first.message, file=first.file, line=first.line, key=first.key)
        self.problems: tuple[InputError, ...] = tuple(problems)


def problems_of(error: InputError) -> tuple[InputError, ...]:
    """The problems an error stands for: all of an :class:`InputErrors`, else itself."""
    return error.problems if isinstance(error, InputErrors) else (error,)


#: most problems reported for one file (the output stays readable and bounded)
MAX_REPORTED = 50


def raise_all(problems: Sequence[InputError]) -> None:
    """Raise the problems (one: itself; several: :class:`InputErrors`); nothing if empty.

    Beyond :data:`MAX_REPORTED` problems, the last line says how many more there are.
    """
    if len(problems) == 1:
        raise problems[0]
    if len(problems) > MAX_REPORTED:
        more = len(problems) - MAX_REPORTED
        problems = [
            *problems[:MAX_REPORTED],
            InputError(f"{more} more problem(s) not shown; fix these first", file=problems[0].file),
        ]
    if problems:
        raise InputErrors(problems)
