"""`frp-assess new NAME.yaml`: start a project file from the commented template."""

from __future__ import annotations

import argparse
from pathlib import Path

from frp_assess.app.project import new_project_text
from frp_assess.cli.output import plain_line
from frp_assess.errors import InputError
from frp_assess.io_utils import atomic_write_text
from frp_assess.output_set import check_parent


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "new",
        help="create a project file from the commented template",
        description="Copy the template, which documents every key with its units and allowed "
        "values, to NAME.yaml; the project name is taken from the file name.",
    )
    p.add_argument("file", metavar="NAME.yaml", help="project file to create")
    p.add_argument("--force", action="store_true", help="overwrite an existing file")
    p.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    path = Path(args.file)
    if path.exists() and not args.force:
        raise InputError(f"{path} already exists; use --force to overwrite it")
    if path.is_dir():
        raise InputError(f"{path} is a directory")
    check_parent(path, key="NAME.yaml")
    text = new_project_text(path)
    try:
        atomic_write_text(path, text)
    except OSError as exc:
        raise InputError(f"cannot write {path}: {exc.strerror}") from None
    shown = plain_line(path)
    print(
        f"created {shown}: edit it, then 'frp-assess validate {shown}' and 'frp-assess run {shown}'"
    )
    return 0
