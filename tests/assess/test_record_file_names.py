"""Record names become file names under records/: a name that would leave the folder (or hide
in it) is refused before anything is written."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from frp_assess.api import write_outputs
from frp_assess.assess.seismic import SeismicInput
from frp_assess.errors import InputError
from frp_assess.motions.record import Record


@pytest.mark.parametrize(
    "name", ["../evil", "/etc/evil", "a/b", "..", ".hidden", "", "a\\b", "bell\x07", "x" * 300]
)
def test_unsafe_record_name_refused(tmp_path: Path, name: str) -> None:
    rec = Record(name, 0.01, np.array([0.0, 1.0, 0.0]))
    seismic = SeismicInput([rec], None, False, 1.0)  # type: ignore[arg-type]
    out = tmp_path / "out"
    with pytest.raises(InputError, match="cannot be a file name"):
        write_outputs({}, seismic, out, pdf=False)
    assert list(tmp_path.iterdir()) == []
