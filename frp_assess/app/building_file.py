"""Whether a project file holds a building (``walls:``), told cheaply: ``frp-assess run`` asks
before it imports the schema or the numerics, so that an unchanged one-wall rerun stays as
fast as before (a file in block style is read with the standard library only; one in flow
style, ``{...}``, is parsed)."""

from __future__ import annotations

import re
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.io_utils import read_regular

#: a top-level ``walls:`` key in block style: at the start of a line (the text of a block
#: scalar is indented, so a ``walls:`` in a project's notes is not one)
_WALLS_KEY = re.compile(r"""^["']?walls["']?[ \t]*:""", re.MULTILINE)
#: a file in flow style (JSON-like, ``{...}``): its keys are found by parsing it
_FLOW = re.compile(r"""\A(?:[ \t]*(?:#[^\n]*)?\n)*[ \t]*\{""")
#: the largest project file (as frp_assess.config.yaml_source.MAX_FILE_BYTES)
_MAX_BYTES = 2_000_000


def is_building_file(path: Path, wall: str | None = None) -> bool:
    """Whether ``path`` is to be run as a building: ``--wall`` given, or a ``walls:`` key in
    the file (a file that cannot be read is not: the one-wall path says why, in one line)."""
    if wall is not None:
        return True
    try:
        data = read_regular(path, "project file", _MAX_BYTES)
        text = data.decode("utf-8", "replace").removeprefix("\ufeff")
    except (InputError, OSError):
        return False
    if _FLOW.match(text):
        from frp_assess.config.walls_file import is_building
        from frp_assess.config.yaml_source import parse_yaml

        try:
            return is_building(parse_yaml(text, str(path))[0])
        except InputError:
            return False  # the one-wall path reports the YAML's problem
    return _WALLS_KEY.search(text) is not None
