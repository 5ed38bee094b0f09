"""The `run` summary line states which pivot its a_RM is about (docs/model.md §1.1).

With the crushing pivot results.json ``wall.a_rm`` is g·(B − x)/H, below g·tan α: the line
printed α and a_RM side by side without saying so, as if a_RM = g·tan α. Reference written
here: the small wall of tests/assess/test_run.py (B = 0.3 m, H = 3 m, tan α = 0.1) turns
about x/2 with x = W/(0.85·f_d·1 m), so a_RM = (0.3 − x)/3 g for the x the line prints.
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest

from frp_assess.cli.cmd_run import activation_text
from tests.results.test_pivot_and_as_built import small_result


def test_crushing_pivot_is_named_with_its_depth(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    m = re.fullmatch(
        r"a_RM = ([0-9.]+) g about the crushing pivot \(x = (\d+) mm\)", activation_text(r)
    )
    assert m is not None, activation_text(r)
    x = int(m.group(2)) / 1000
    assert float(m.group(1)) == pytest.approx((0.3 - x) / 3.0, abs=5e-4)


def test_edge_pivot_is_plain_a_rm(tmp_path: Path) -> None:
    r = small_result(tmp_path)
    urm = r.urm
    assert urm.pivot is not None
    edge_urm = replace(urm, pivot=replace(urm.pivot, model_pivot="edge", pivot_shift=0.0))
    r = replace(r, cases=(edge_urm, *r.cases[1:]), wall=replace(r.wall, a_rm=0.1))
    assert activation_text(r) == "a_RM = 0.100 g"
