"""Whether a project file holds a building (``walls:``), told cheaply (standard library only):
``frp-assess run`` asks before it imports the schema or the numerics, so that an unchanged
one-wall rerun stays as fast as before."""

from __future__ import annotations

import re
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.io_utils import read_regular

#: a top-level (or flow-style) ``walls:`` key; no block of a one-wall file has such a key
_WALLS_KEY = re.compile(r"""^\s*[{]?\s*["']?walls["']?\s*:""", re.MULTILINE)
#: the largest project file (as frp_assess.config.yaml_source.MAX_FILE_BYTES)
_MAX_BYTES = 2_000_000


def is_building_file(path: Path, wall: str | None = None) -> bool:
    """Whether ``path`` is to be run as a building: ``--wall`` given, or a ``walls:`` key in
    the file (a file that cannot be read is not: the one-wall path says why, in one line)."""
    if wall is not None:
        return True
    try:
        text = read_regular(path, "project file", _MAX_BYTES).decode("utf-8", "replace")
    except (InputError, OSError):
        return False
    return _WALLS_KEY.search(text) is not None
