"""A façade with a floor, a restrained roof, a thrust and a tie, assessed end to end
(tests/fixtures/facade-loads.yaml; docs/model.md §12).

The IDA's activation multiplier (a_RM/g of the kernel, from its per-side bracket) equals α₀
without ties of the code checks (the Circolare's eq. C8.7.1.1 summed term by term in
assess/loaded_capacity.py from rules/wall_loads.py) and the §10.2 hand check; the record's
capacity is a multiple of that a_RM; the tie, which the time histories do not model, is
stated in the run's warnings.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frp_assess.cli import main

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "facade-loads.yaml"


@pytest.mark.slow
def test_a_loaded_facade_runs_with_the_loads_in_the_time_histories(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert main(["run", str(FIXTURE), "--out", str(out), "--no-pdf", "--jobs", "1"]) == 0
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    alpha0 = data["loads"]["overturning"]["alpha0_without_ties"]
    # hand: (43.2·0.2 − N₀·x₀/2 + 10·0.3 + 4·0.2 − 1·5.5)/(43.2·3 + 10·6) with the stress block
    assert 0.0 < alpha0 < 0.4 / 6.0
    checks = {c["name"]: c for c in data["independent_checks"]}
    activation = checks["activation multiplier"]
    assert activation["passed"]
    assert activation["value"] == pytest.approx(alpha0, rel=1e-9)
    assert activation["reference"] == pytest.approx(alpha0, rel=1e-9)
    # Housner's closed forms are for the bare block: not claimed for a loaded wall
    assert "free rocking period" not in checks and "energy at impact" not in checks
    (record,) = data["cases"][0]["records"]
    assert record["q"] == pytest.approx(record["a_dyn"] / alpha0, rel=1e-9)  # both in g
    assert any(w.startswith("wall.loads.ties: the time histories") for w in data["input_warnings"])
