"""The study axis ``building.wall_base``: walls above the ground floor in a parametric study.

References: Z = 0 must give the ground study's numbers exactly (ψ1 = 0); for Z > 0 one
case is recomputed directly with :func:`frp_assess.dynamics.ida` on
:func:`frp_assess.motions.floor.floor_acceleration` of the record (a_dyn = C·PGA_ground, the
PGA taken here with numpy); T1 defaults to 0.05·H_b^0.75, 0.05·10^0.75 = 0.28117 s by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from frp_assess.dynamics import ida
from frp_assess.errors import InputError
from frp_assess.motions import G
from frp_assess.motions.floor import floor_acceleration
from frp_assess.study import parse_study, run_study
from frp_assess.study.plan import StudyPlan
from frp_assess.study.run import read_summary
from tests.study.conftest import TINY, tiny_records

BUILDING = {"height": 10.0, "storeys": 3, "wall_base": [0.0, 9.0]}


def study(**extra: object):  # type: ignore[no-untyped-def]
    data = {**TINY, "height": [3.0], "ratio": [1.0], **extra}
    return parse_study(data)


def test_plan_has_a_wall_group_per_wall_base() -> None:
    ground = StudyPlan(study())
    plan = StudyPlan(study(building=BUILDING))
    assert len(plan) == 2 * len(ground) == 4 and plan.n_unreinforced == 2
    assert plan.study.case_count() == 4
    cases = list(plan.cases())
    assert [c.wall_base for c in cases] == [0.0, 0.0, 9.0, 9.0]
    assert [c.unreinforced_index for c in cases] == [0, 0, 2, 2]
    assert cases[3].label.endswith("/Z9/CFRP-external-1")
    b = plan.building(cases[2])
    assert b is not None and (b.height, b.storeys, b.wall_base) == (10.0, 3, 9.0)
    assert b.period == pytest.approx(0.28117, abs=5e-6)
    assert ground.building(next(ground.cases())) is None
    assert "/Z" not in next(ground.cases()).label


@pytest.mark.parametrize(
    "bad, message",
    [
        ({"wall_base": [10.0]}, "expected 0 <= Z < height H_b = 10 m, found 10"),
        ({"wall_base": [3.0, 3.0]}, "repeated values"),
        ({"wall_base": []}, "at least 1"),
        ({"storeys": 0}, r"in \[1, 60\], found 0"),
    ],
)
def test_bad_building_of_a_study(bad: dict[str, object], message: str) -> None:
    with pytest.raises(InputError, match=message) as exc:
        study(building={**BUILDING, **bad})
    assert "building" in str(exc.value)


def test_study_at_z0_matches_the_ground_and_z9_runs_on_the_floor(tmp_path: Path) -> None:
    records = tiny_records()
    run_study(study(), tmp_path / "ground", jobs=1, records=records)
    run_study(study(building=BUILDING), tmp_path / "floor", jobs=1, records=records)
    ground = read_summary(tmp_path / "ground" / "summary.csv")
    floor = read_summary(tmp_path / "floor" / "summary.csv")
    assert len(floor) == 2 * len(ground) == 4
    for g, f in zip(ground, floor[:2], strict=True):  # Z = 0: the same numbers
        for key in ("mean_a_dyn_g", "min_a_dyn_g", "mean_q", "improvement"):
            assert f[key] == g[key]
        assert f["label"] == g["label"].replace("/a7.5", "/a7.5/Z0")
    # Z = 9 m, the unreinforced wall, first record: an independent IDA on the floor motion
    plan = StudyPlan(study(building=BUILDING))
    case = plan.case(2)
    rec = records["A2"][0]
    motion = floor_acceleration(
        rec.acc,
        rec.dt,
        height_building=10.0,
        storeys=3,
        wall_base=9.0,
        period=0.05 * 10.0**0.75,
    )
    direct = ida(plan.model(case), motion, rec.dt, plan.ida_settings)
    assert direct.collapse_multiplier is not None
    long = (tmp_path / "floor" / "long.csv").read_text().splitlines()
    header = long[0].split(",")
    row = dict(zip(header, next(r for r in long[1:] if r.startswith("2,")).split(","), strict=True))
    pga_ground = float(np.max(np.abs(rec.acc)))
    assert float(row["collapse_multiplier"]) == pytest.approx(direct.collapse_multiplier, 1e-12)
    assert float(row["a_dyn_g"]) == pytest.approx(
        direct.collapse_multiplier * pga_ground / G, rel=1e-12
    )
    assert float(row["pga_g"]) == pytest.approx(pga_ground / G, rel=1e-12)
    assert not math.isclose(float(row["a_dyn_g"]), direct.a_dyn / G, rel_tol=1e-3)
