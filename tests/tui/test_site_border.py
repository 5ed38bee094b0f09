"""The Site tab shows the site module's refusal of a site abroad and its warning near the
border (Pilot, 100 x 30): the same text as `frp-assess site` (one source,
frp_assess/motions/site/territory.py).

References: Gorizia 45°56′N 13°37′E and Lugano 46°00′18″N 08°57′09″E (en.wikipedia
infoboxes), 0.5 km from the outline's border with Slovenia and 3.4 km into Switzerland.
"""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Select, Static

from frp_assess.motions.site import site_hazard
from frp_assess.tui.app import FrpAssessApp
from tests.tui.conftest import run_async, settle
from tests.tui.test_app import SIZE, plain, row_error, type_into


def test_the_site_pane_warns_near_the_border_and_refuses_abroad(small_project: Path) -> None:
    warning = site_hazard(45.93333, 13.61667).border_warning

    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("f3")
            await pilot.pause()
            app.query_one("#f-seismic-spectrum-type-control", Select).value = "ntc2018"
            await settle(pilot, lambda: app.project is not None and "ntc2018" in str(
                app.project.seismic.spectrum.type))  # fmt: skip
            app.query_one(
                "#f-seismic-spectrum-given-by-ntc2018-control", Select
            ).value = "coordinates"
            info = app.query_one("#spectrum-info", Static)
            await settle(pilot, lambda: "a_g = 0.2607 g" in plain(info))
            lat = "#f-seismic-spectrum-site-latitude-coordinates-control"
            lon = "#f-seismic-spectrum-site-longitude-coordinates-control"
            await type_into(pilot, lat, "45.93333")
            await type_into(pilot, lon, "13.61667")
            await settle(pilot, lambda: "warning:" in plain(info))
            assert " ".join(warning.split()) in " ".join(plain(info).split())
            assert app.project is not None  # a warning, not an error

            await type_into(pilot, lat, "46.005")
            await type_into(pilot, lon, "8.9525")
            assert app.project is None
            assert "lies outside Italy (Switzerland?)" in (
                row_error(app, ("seismic", "spectrum", "site", "latitude"))
                or row_error(app, ("seismic", "spectrum", "site", "longitude"))
                or plain(app.query_one("#err-site", Static))
            )

    run_async(body)
