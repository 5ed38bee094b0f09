"""The site block of results.json (spectrum given by coordinates) and its report part.

References: T_R = −V_R/ln(1 − P_VR) for V_R = 35 years (class I, V_N = 50: 0.7·50 = 35):
SLO 21.1 years (clamped to 30), SLD 35.4, SLV 332.2, SLC 682.3 years; the numbers a_g, F0,
T_C* below are arbitrary test values, shown as typed with the report's rounding.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

from frp_assess.report import build_report, build_story
from frp_assess.report.site_section import limit_state_table, site_section
from frp_assess.results.json_io import from_json, to_json
from frp_assess.results.model import AssessmentResult, LimitStateSite, SiteResult
from tests.report.test_report import DATA, story_text

P_VR = {"SLO": 0.81, "SLD": 0.63, "SLV": 0.10, "SLC": 0.05}


def _state(name: str, ag: float) -> LimitStateSite:
    tr = -35.0 / math.log(1.0 - P_VR[name])
    return LimitStateSite(P_VR[name], tr, max(tr, 30.0), ag, 2.4, 0.3)


SITE = SiteResult(
    latitude=42.7927,
    longitude=13.0936,
    V_N=50.0,
    use_class="I",
    C_U=0.7,
    V_R=35.0,
    limit_states={
        s: _state(s, ag)
        for s, ag in (("SLO", 0.071), ("SLD", 0.088), ("SLV", 0.2166), ("SLC", 0.2811))
    },
    limit_state="SLD",
    nearest_node=1.4,
)


def _base() -> AssessmentResult:
    return from_json(DATA.read_text(encoding="utf-8"))


def test_no_site_no_key_and_no_part() -> None:
    base = _base()
    assert base.site is None
    assert '"site"' not in to_json(base)
    assert site_section(base) == []


def test_site_round_trips_and_is_the_last_key() -> None:
    res = replace(_base(), site=SITE)
    text = to_json(res)
    assert list(json.loads(text))[-1] == "site"
    assert from_json(text) == res


def test_table_rows_and_clamp_note() -> None:
    table = limit_state_table(SITE)
    rows = {r[0]: r for r in table.rows}
    assert rows["SLO"][2] == "21 (30 used)"  # −35/ln(0.19) = 21.1 years
    assert rows["SLV"][2] == "332"  # −35/ln(0.90) = 332.2 years
    assert rows["SLV"][3:6] == ["0.2166", "2.400", "0.300"]
    assert [r[6] for r in table.rows] == ["", "used", "", ""]


def test_report_shows_the_site(tmp_path: Path) -> None:
    res = replace(_base(), site=SITE)
    text = story_text(build_story(res))
    assert "Site hazard from coordinates" in text
    assert "42.7927°, 13.0936°" in text
    assert "those of SLD at the site" in text
    build_report(res, tmp_path / "r.pdf")
    assert (tmp_path / "r.pdf").stat().st_size > 0
