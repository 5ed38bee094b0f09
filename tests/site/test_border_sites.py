"""Sites near Italy's land border: abroad refused, near the border warned, Italy accepted.

The issue (36, item 8): Lugano lies in a complete NTC grid cell 0.9 km from a node and got
Italian values.  The coordinates below are written from public sources, not from the data
file: the infobox of each town's Wikipedia article (en.wikipedia unless said otherwise; the
degrees-minutes-seconds there, converted):

- Lugano 46°00′18″N 08°57′09″E; Bellinzona 46°12′N 9°01′E (simple.wikipedia); Locarno
  46°10′N 8°48′E; Koper 45°33′N 13°44′E; Nova Gorica 45°57′21″N 13°38′36″E; Menton
  43°46′30″N 7°30′00″E; City of San Marino 43°56′4.56″N 12°26′50.28″E; Vatican City
  41°54′10″N 12°27′9″E ("Geography of Vatican City");
- Como 45°49′N 9°05′E; Ventimiglia 43°47′25″N 7°36′30″E (it.wikipedia); Trieste
  45°39′01″N 13°46′13″E; Gorizia 45°56′N 13°37′E; Aosta 45°44′N 7°19′E; Bolzano 46°30′N
  11°21′E; L'Aquila 42°21′N 13°24′E; Norcia 42°48′N 13°05′E; Lampedusa 35°30′N 12°36′E;
  Campione d'Italia 45°58′15″N 8°58′15″E (fr.wikipedia; the outline's correction uses
  en.wikipedia's 45°58′N 8°58′E, 600 m away).

The expected outcome follows the rule of frp_assess/motions/site/territory.py: refused when
abroad more than 2 km beyond the outline's land border, warned within 2 km of it (either
side), accepted silently elsewhere in Italy; the small islands keep the grid's rule
(Lampedusa, which Allegato B Tab. 1 gives separately, is refused by the grid as before).
"""

from __future__ import annotations

import pytest

from frp_assess.cli import main
from frp_assess.config.loader import load_project_text
from frp_assess.errors import InputError
from frp_assess.motions.site import OutsideGridError, OutsideItalyError, site_hazard
from frp_assess.tui.core.editor_state import spectrum_site_warning

ABROAD = {
    "Lugano": (46.00500, 8.95250, "Switzerland"),
    "Bellinzona": (46.20000, 9.01667, None),  # 9 km from the border: not named
    "Locarno": (46.16667, 8.80000, None),
    "Koper": (45.55000, 13.73333, "Slovenia"),
    "City of San Marino": (43.93460, 12.44730, "San Marino"),
}
WARNED = {
    "Nova Gorica": (45.95583, 13.64333, "Slovenia"),
    "Menton": (43.77500, 7.50000, "France"),
    "Vatican City": (41.90278, 12.45250, "Vatican City"),
    "Gorizia": (45.93333, 13.61667, "Slovenia"),
    "Campione d'Italia": (45.97083, 8.97083, "Switzerland"),
}
ACCEPTED = {
    "Como": (45.81667, 9.08333),
    "Ventimiglia": (43.79028, 7.60833),
    "Trieste": (45.65028, 13.77028),
    "Aosta": (45.73333, 7.31667),
    "Bolzano": (46.50000, 11.35000),
    "L'Aquila": (42.35000, 13.40000),
    "Norcia": (42.80000, 13.08333),
}


@pytest.mark.parametrize("town", ABROAD)
def test_a_site_abroad_is_refused(town: str) -> None:
    lat, lon, country = ABROAD[town]
    with pytest.raises(OutsideItalyError) as exc:
        site_hazard(lat, lon)
    message = str(exc.value)
    assert isinstance(exc.value, InputError) and "\n" not in message
    assert message.startswith(f"{lat:.4f} N {lon:.4f} E lies outside Italy")
    if country is None:
        assert "?)" not in message
    else:
        assert f"outside Italy ({country}?)" in message


def test_the_issues_lugano_message() -> None:
    with pytest.raises(OutsideItalyError, match=r"^46\.0037 N 8\.9511 E lies outside Italy "
                       r"\(Switzerland\?\), 3\.\d km beyond its border"):  # fmt: skip
        site_hazard(46.0037, 8.9511)


@pytest.mark.parametrize("town", WARNED)
def test_a_site_near_the_border_is_computed_with_a_warning(town: str) -> None:
    lat, lon, country = WARNED[town]
    hazard = site_hazard(lat, lon)
    assert hazard["SLV"].ag > 0
    warning = hazard.border_warning
    assert f"from Italy's border with {country}" in warning
    assert "the NTC values assume it is in Italy" in warning and "\n" not in warning


@pytest.mark.parametrize("town", ACCEPTED)
def test_an_italian_site_away_from_the_border_has_no_warning(town: str) -> None:
    hazard = site_hazard(*ACCEPTED[town])
    assert hazard["SLV"].ag > 0
    assert hazard.border_warning == ""


def test_lampedusa_keeps_the_grids_refusal() -> None:
    with pytest.raises(OutsideGridError, match="outside the NTC reference grid"):
        site_hazard(35.5, 12.6)


PROJECT = """\
wall: {{thickness: 0.25, height: 4.5, masonry: solid-brick-lime-mortar, mechanism: one-sided}}
seismic:
  spectrum:
    type: ntc2018
    site: {{latitude: {lat}, longitude: {lon}}}
    soil: C
interventions:
  - {{material: GFRP, position: centred, ratio: 1.0}}
"""


def test_a_project_abroad_is_refused_at_the_site_key() -> None:
    with pytest.raises(InputError) as exc:
        load_project_text(PROJECT.format(lat=46.005, lon=8.9525), "p.yaml")
    message = str(exc.value)
    assert "seismic.spectrum.site" in message and "lies outside Italy (Switzerland?)" in message
    assert "p.yaml:5" in message


def test_a_project_near_the_border_carries_the_warning() -> None:
    checked = load_project_text(PROJECT.format(lat=45.93333, lon=13.61667), "p.yaml")
    expected = site_hazard(45.93333, 13.61667).border_warning
    lines = [w for w in checked.warnings if "seismic.spectrum.site" in w]
    assert len(lines) == 1 and lines[0].endswith(expected) and lines[0].startswith("p.yaml:5")


def test_the_site_command_refuses_and_warns_like_the_project(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["site", "--lat", "46.0037", "--lon", "8.9511"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "lies outside Italy (Switzerland?)" in err
    assert main(["site", "--lat", "45.93333", "--lon", "13.61667"]) == 0
    captured = capsys.readouterr()
    expected = site_hazard(45.93333, 13.61667).border_warning
    assert captured.err.strip() == f"frp-assess: warning: --lat/--lon: {expected}"
    assert "V_R = 50 years" in captured.out


def test_the_tui_shows_the_site_modules_warning() -> None:
    spec = {"type": "ntc2018", "site": {"latitude": 45.93333, "longitude": 13.61667}, "soil": "C"}
    assert spectrum_site_warning(spec) == site_hazard(45.93333, 13.61667).border_warning != ""
    spec["site"] = {"latitude": 42.35, "longitude": 13.4}
    assert spectrum_site_warning(spec) == ""
