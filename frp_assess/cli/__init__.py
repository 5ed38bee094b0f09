"""The `frp-assess` command line: a thin layer over the application API.

Each subcommand ``<name>`` lives in its own module of this package, ``cmd_<name>.py``, and
exposes ``register(subparsers) -> None``, which adds its parser and sets ``handler`` (a
callable taking the parsed namespace and returning the exit code).  Errors a user can fix
(:class:`~frp_assess.errors.InputError`) are printed as one line and give exit code 2.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence
from typing import NoReturn

from frp_assess import __version__
from frp_assess.errors import Cancelled, InputError, NumericalError
from frp_assess.io_utils import source_date
from frp_assess.text_safety import plain

#: The subcommands, in the order `--help` lists them, with their one-line help: a command's
#: module (``frp_assess.cli.cmd_<name>``) is imported only when that command runs, so that
#: ``frp-assess run`` of an unchanged project starts in a fraction of a second.
COMMANDS: dict[str, str] = {
    "new": "create a project file from the commented template",
    "validate": "check a project or study file and print a short summary",
    "run": "assess a project file (IDA of every option, ranking, report)",
    "tui": "interactive terminal interface: edit, run, read results, export",
    "simulate": "time history of a wall under one record",
    "ida": "incremental dynamic analysis under a set of records",
    "records": "generate artificial accelerograms, check record sets against a code spectrum",
    "site": "NTC 2018 seismic parameters of a site from its coordinates",
    "report": "rebuild report.pdf from a results directory (no analysis is rerun)",
    "schema": "print the JSON Schema of project files",
    "study": "run a parametric study (cross product of wall, retrofit and spectrum axes)",
}
COMMAND_MODULES: tuple[str, ...] = tuple(COMMANDS)


class OneLineParser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are a single line on stderr and exit code 2."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{plain(self.prog)}: error: {plain(message)}\n")


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The parser of ``frp-assess``.  Without ``argv`` every command's module is imported;
    with it only that of the command ``argv`` names (the others get a parser that only
    lists them in ``--help``)."""
    wanted = None if argv is None else _command_of(argv)
    parser = OneLineParser(
        prog="frp-assess",
        description="Seismic assessment of rocking masonry walls retrofitted with vertical "
        "FRP rebars, by incremental dynamic analysis.",
    )
    parser.add_argument("--version", action="version", version=f"frp-assess {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=OneLineParser)
    sub.required = True
    for name, text in COMMANDS.items():
        if argv is None or name == wanted:
            importlib.import_module(f"frp_assess.cli.cmd_{name}").register(sub)
        else:
            sub.add_parser(name, help=text)
    return parser


def _command_of(argv: Sequence[str]) -> str | None:
    """The subcommand ``argv`` names: its first word that is not an option."""
    return next((a for a in argv if not a.startswith("-")), None)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the console script; returns the process exit code.

    Every error a user can cause ends as ONE line on stderr (control characters in it
    replaced, :func:`frp_assess.text_safety.plain`) and exit code 2: an
    :class:`~frp_assess.errors.InputError`, or an ``OSError`` of the file system (disk full,
    permission denied, ...).  A closed output pipe (``frp-assess schema | head``) ends the
    command quietly (exit 0; stdout is pointed at /dev/null so the interpreter's final flush
    does not fail again).
    """
    from frp_assess.cli.output import setup_streams

    setup_streams()  # a console that is not UTF-8 prints what it can, never crashes
    try:
        source_date()  # malformed: one line, before a library (numpy.f2py) reads it on import
    except InputError as exc:
        return _fail(str(exc))
    try:
        words = sys.argv[1:] if argv is None else list(argv)
        parser = build_parser(words)  # imports the command's module: Ctrl-C may land here
        args = parser.parse_args(words)
    except KeyboardInterrupt:
        print("frp-assess: interrupted", file=sys.stderr)
        return 130
    try:
        code = int(args.handler(args))
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
        return code
    except BrokenPipeError:
        return _closed_pipe()
    except InputError as exc:  # every problem of a file, one line each
        from frp_assess.app.project import problems_of

        for problem in problems_of(exc)[:-1]:
            _fail(str(problem))
        return _fail(str(problems_of(exc)[-1]))
    except (KeyboardInterrupt, Cancelled):
        print("frp-assess: interrupted; finished results are kept in the cache", file=sys.stderr)
        return 130
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename is not None else ""
        return _fail(f"{where}{exc.strerror or exc}")
    except NumericalError as exc:  # not the input's fault: one line, exit 1
        _fail(str(exc), kind="numerical error")
        return 1


def _fail(message: str, kind: str = "error") -> int:
    try:
        print(f"frp-assess: {kind}: {plain(message)}", file=sys.stderr)
    except BrokenPipeError:
        pass
    return 2


def _closed_pipe() -> int:
    """The reader of stdout went away: stop writing, say nothing, exit 0."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
