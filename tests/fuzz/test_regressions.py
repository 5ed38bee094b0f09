"""What the long fuzz profile found (``HYPOTHESIS_PROFILE=long``), kept as plain tests.

1. A record file holding 1e308 read in g: the conversion to m/s² overflowed (a numpy
   RuntimeWarning on stderr, then "the record holds non-finite values" about a file whose
   every value is finite).  Now one line: the peak is beyond 1e4 g.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.fuzz.test_fuzz import check_answer, cli

pytestmark = pytest.mark.filterwarnings("error::RuntimeWarning")

PROJECT = """\
wall: {{thickness: 0.3, height: 3.0, unit_weight: 18.0, mechanism: one-sided}}
seismic:
  spectrum: {{type: preset, name: A2}}
  records:
    files: [{{path: r.txt, format: {fmt}, units: g{dt}}}]
"""

#: (format, record text) of the examples the long profile found, reduced by hand
FOUND = {
    "at2": "PEER NGA\nFUZZ\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 3, DT= 0.01 SEC\n"
    "0.0 1e+308 -0.5\n",
    "one-column": "0.0\n1e+308\n-0.5\n",
    "two-column": "0.0 0.0\n0.01 1e+308\n0.02 -0.5\n",
}


@pytest.mark.parametrize("fmt", sorted(FOUND))
def test_a_peak_beyond_any_units_is_one_line(tmp_path: Path, fmt: str) -> None:
    rec = tmp_path / "r.txt"
    rec.write_text(FOUND[fmt], encoding="utf-8")
    path = tmp_path / "p.yaml"
    dt = ", dt: 0.01" if fmt == "one-column" else ""
    path.write_text(PROJECT.format(fmt=fmt, dt=dt), encoding="utf-8")
    code, err = cli("validate", str(path))
    check_answer(code, err, [rec])
    assert code == 2 and err.count("\n") == 1
    assert f"{rec}: expected a peak acceleration between 1e-06 g and 10000 g" in err
