"""`frp-assess tui [FILE]`: edit, run and read an assessment in the terminal."""

from __future__ import annotations

import argparse
from pathlib import Path

from frp_assess.errors import InputError


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "tui",
        help="interactive terminal interface: edit, run, read results, export",
        description="Open FILE (or a new project from the template) in the terminal "
        "interface: edit the wall, site, records, materials, retrofits and analysis "
        "options with live validation, run the assessment with progress and cancel, read "
        "the ranking, plots and time histories, save the YAML and export the PDF report. "
        "FILE may not exist yet: the template is then saved there with ctrl+s.",
    )
    p.add_argument("file", nargs="?", help="project file (YAML); default: a new project")
    p.add_argument("--jobs", type=int, default=None, help="worker threads (default: all cores)")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    if args.jobs is not None and args.jobs < 1:
        raise InputError(f"expected at least 1 job, found {args.jobs}", key="--jobs")
    path = Path(args.file) if args.file else None
    if path is not None and (path.exists() or path.is_symlink()):
        from frp_assess.app.project import ensure_project_file

        # a folder, FIFO, device or oversized file, a YAML syntax error, a study file: one
        # line, exit 2, before the screen opens
        ensure_project_file(path)
    from frp_assess.tui.building_app import run_tui  # Textual is imported only for this command

    return run_tui(path, jobs=args.jobs)
