"""The Site tab gives the NTC 2018 spectrum by the site's coordinates too (Pilot, 100 x 30).

References: L'Aquila (42.35 N, 13.40 E), V_N = 50 years, class II: a_g(SLV) = 0.2607 g (the
hand calculation of tests/motions/test_site_hazard.py); the project file keeps the form the
user chose, and the coordinates form written to disk loads as coordinates.
"""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Select, Static

from frp_assess.config import load_project
from frp_assess.config.schema import Ntc2018Spectrum
from frp_assess.tui.app import FrpAssessApp
from tests.tui.conftest import run_async, settle
from tests.tui.test_app import SIZE, plain, row_error, type_into


def test_switch_to_coordinates_shows_the_derived_parameters(small_project: Path) -> None:
    async def body() -> None:
        app = FrpAssessApp(small_project)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            await pilot.press("f3")
            await pilot.pause()
            app.query_one("#f-seismic-spectrum-type-control", Select).value = "ntc2018"
            await settle(pilot, lambda: app.project is not None and "ntc2018" in str(
                app.project.seismic.spectrum.type))  # fmt: skip
            given_by = app.query_one("#f-seismic-spectrum-given-by-ntc2018-control", Select)
            assert given_by.value == "parameters"
            given_by.value = "coordinates"
            info = app.query_one("#spectrum-info", Static)
            await settle(pilot, lambda: "a_g = 0.2607 g" in plain(info))
            spec = app.project.seismic.spectrum if app.project else None
            assert isinstance(spec, Ntc2018Spectrum) and spec.by_coordinates
            assert spec.ag is None and spec.site is not None and spec.site.latitude == 42.35

            # the limit state changes the derived values live
            app.query_one(
                "#f-seismic-spectrum-limit-state-coordinates-control", Select
            ).value = "SLD"
            await settle(pilot, lambda: "a_g = 0.1042 g" in plain(info))

            # a site at sea: the grid's message under the field block, no project
            await type_into(pilot, "#f-seismic-spectrum-site-latitude-coordinates-control", "42.5")
            await type_into(pilot, "#f-seismic-spectrum-site-longitude-coordinates-control", "15")
            assert app.project is None
            assert "outside the NTC reference grid" in (
                row_error(app, ("seismic", "spectrum", "site", "latitude"))
                or row_error(app, ("seismic", "spectrum", "site", "longitude"))
                or plain(app.query_one("#err-site", Static))
            )
            # back on land, saved: the file holds the coordinates form
            await type_into(pilot, "#f-seismic-spectrum-site-longitude-coordinates-control", "13.4")
            await type_into(pilot, "#f-seismic-spectrum-site-latitude-coordinates-control", "42.35")
            assert app.project is not None
            await pilot.press("ctrl+s")
            await pilot.pause()

    run_async(body)
    saved = load_project(small_project).project.seismic.spectrum
    assert isinstance(saved, Ntc2018Spectrum) and saved.by_coordinates
    assert saved.chosen_limit_state == "SLD"
    assert saved.parameters()[0] == saved.site_hazard()["SLD"].ag  # type: ignore[index]
