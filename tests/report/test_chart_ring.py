"""The ring on the options chart says what the decision says (results.json's decision:
``recommended``, ``retrofit_required``, ``input_code_compliant``): a wall that passes as it is
has no recommendation to ring, only the cheapest option for extra margin (the golden small
project's results with the three decisions set)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from reportlab.graphics.shapes import Group, String

from frp_assess.report.charts import options_chart
from frp_assess.results.json_io import from_json

SMALL = Path(__file__).resolve().parents[1] / "golden" / "expected" / "small" / "results.json"


def _texts(node: object) -> list[str]:
    out: list[str] = []
    if isinstance(node, String):
        out.append(node.text)
    for child in (
        getattr(node, "contents", [])
        if isinstance(node, Group) or hasattr(node, "contents")
        else []
    ):
        out += _texts(child)
    return out


def test_the_ring_names_the_decision() -> None:
    stored = from_json(SMALL.read_text(encoding="utf-8"))
    assert stored.recommended is not None
    r = dataclasses.replace(stored, input_code_compliant=True, retrofit_required=False)
    optional = " ".join(_texts(options_chart(r, "capacity_demand")))
    assert "optional margin (ringed)" in optional
    assert "recommended (ringed)" not in optional
    needed = " ".join(
        _texts(options_chart(dataclasses.replace(r, retrofit_required=True), "capacity_demand"))
    )
    assert "recommended (ringed)" in needed
    bad = dataclasses.replace(r, input_code_compliant=False)
    assert "best ranked (ringed)" in " ".join(_texts(options_chart(bad, "capacity_demand")))
