"""A building's summary read back from its results folder (``OUT/results.json`` of a run of
every wall, :func:`frp_assess.app.building_run.write_building_outputs`), for the terminal UI's
building summary view."""

from __future__ import annotations

import json
from pathlib import Path

from frp_assess.errors import InputError
from frp_assess.results.building_summary import BUILDING_KIND, BuildingResults
from frp_assess.results.json_io import from_data


def load_building_summary(out_dir: Path) -> BuildingResults | None:
    """The building summary in ``out_dir/results.json``; None when there is no such file.
    An InputError (one line, naming the file) when it is not a building's results."""
    path = out_dir / "results.json"
    if not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise InputError(f"cannot read the building's results: {exc}", file=str(path)) from None
    if not isinstance(data, dict) or data.get("kind") != BUILDING_KIND:
        raise InputError(
            "expected a building's results (kind: building), found a one-wall project's: "
            "run the building again",
            file=str(path),
            key="kind",
        )
    result: BuildingResults = from_data(BuildingResults, data, file=str(path))
    return result
