"""The NTC 2018 spectrum given by the site's coordinates in the project file.

References: the site's a_g, F0, T_C* are frp_assess.motions.site's (checked against hand
calculations in tests/motions/test_site_hazard.py: L'Aquila a_g(SLV) = 0.2606566 g for
V_N = 50, class II); the old form (ag, F0, Tc_star) must give exactly what it gave before.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.assess.from_project import inputs_from_project, spectrum_of
from frp_assess.config.loader import load_project_text
from frp_assess.config.schema import Ntc2018Spectrum
from frp_assess.errors import InputError
from frp_assess.motions import ntc2018_spectrum
from frp_assess.motions.site import site_hazard

PROJECTS = Path(__file__).resolve().parents[2] / "projects"

TEMPLATE = """\
wall: {{thickness: 0.25, height: 4.5, masonry: solid-brick-lime-mortar, mechanism: one-sided}}
seismic:
  spectrum:
    type: ntc2018
{spectrum}
    soil: C
interventions:
  - {{material: GFRP, position: centred, ratio: 1.0}}
"""


def load(spectrum: str) -> Ntc2018Spectrum:
    text = TEMPLATE.format(spectrum=spectrum)
    spec = load_project_text(text, "p.yaml").project.seismic.spectrum
    assert isinstance(spec, Ntc2018Spectrum)
    return spec


def refused(spectrum: str) -> str:
    with pytest.raises(InputError) as exc:
        load(spectrum)
    message = str(exc.value)
    assert "\n" not in message
    return message


def test_by_coordinates_defaults_to_v50_class_ii_slv() -> None:
    spec = load("    site: {latitude: 42.35, longitude: 13.40}")
    assert spec.by_coordinates and spec.chosen_limit_state == "SLV"
    ag, f0, tc = spec.parameters()
    assert ag == pytest.approx(0.2606566, rel=2e-6)
    slv = site_hazard(42.35, 13.40, 50.0, "II")["SLV"]
    assert (ag, f0, tc) == (slv.ag, slv.F0, slv.Tc_star)
    assert spectrum_of(spec).pga_g == ntc2018_spectrum(ag, f0, tc, "C", "T1").pga_g


def test_limit_state_nominal_life_and_use_class_are_used() -> None:
    spec = load(
        "    site: {latitude: 42.35, longitude: 13.40}\n"
        "    nominal_life: 100\n    use_class: III\n    limit_state: SLC"
    )
    hazard = spec.site_hazard()
    assert hazard is not None and hazard.V_R == 150.0  # 100·1.5
    assert spec.parameters()[0] == hazard["SLC"].ag
    assert hazard["SLC"].ag > hazard["SLV"].ag


def test_old_form_unchanged() -> None:
    spec = load("    ag: 0.261\n    F0: 2.36\n    Tc_star: 0.347")
    assert not spec.by_coordinates and spec.site_hazard() is None
    assert spec.parameters() == (0.261, 2.36, 0.347)


def test_both_forms_refused_at_the_key() -> None:
    msg = refused("    site: {latitude: 42.35, longitude: 13.40}\n    ag: 0.25")
    assert msg.startswith("p.yaml:6: seismic.spectrum.ag: give either site")


def test_site_outside_the_grid_refused_at_site() -> None:
    msg = refused("    site: {latitude: 39.22, longitude: 9.11}")
    assert msg.startswith("p.yaml:5: seismic.spectrum.site: ")
    assert "outside the NTC reference grid" in msg and "Tab. 1" in msg


def test_site_keys_without_site_refused() -> None:
    msg = refused("    ag: 0.261\n    F0: 2.36\n    Tc_star: 0.347\n    limit_state: SLD")
    assert "seismic.spectrum.limit_state: limit_state needs site" in msg


def test_missing_parameters_without_site_name_both_ways() -> None:
    msg = refused("    ag: 0.261\n    F0: 2.36")
    assert "p.yaml:3: seismic.spectrum: missing required key 'Tc_star' (Tc_star: T_C* [s]" in msg
    assert "or give the site's coordinates instead: site: (latitude, longitude)" in msg
    msg = refused("    nominal_life: 50")
    assert "nominal_life needs site" in msg
    msg = refused("")
    assert "missing required keys 'ag', 'F0', 'Tc_star'" in msg


def test_validate_summary_names_the_site(capsys: pytest.CaptureFixture[str]) -> None:
    from frp_assess.cli import main

    assert main(["validate", str(PROJECTS / "facade-norcia-coordinates.yaml")]) == 0
    out = capsys.readouterr().out
    assert "a_g = 0.2548 g" in out
    assert "(site 42.7927°N 13.0936°E, V_R = 50 years, SLV T_R = 475 years)" in out


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("    site: {latitude: 95, longitude: 13.4}", "site.latitude: expected a number in"),
        ("    site: {latitude: 42.3}", "missing required key 'longitude'"),
        ("    site: {latitude: 42.3, longitude: 13.4}\n    use_class: V", "expected one of I,"),
        ("    site: {latitude: 42.3, longitude: 13.4}\n    limit_state: ULS", "SLO, SLD"),
    ],
)
def test_bad_site_values(line: str, expected: str) -> None:
    assert expected in refused(line)


def test_bundled_example_by_coordinates() -> None:
    from frp_assess.config import load_project

    path = PROJECTS / "facade-norcia-coordinates.yaml"
    inputs = inputs_from_project(load_project(path).project, path.parent)
    assert inputs.site is not None and inputs.site_limit_state == "SLV"
    assert inputs.spectrum.parameters["ag"] == inputs.site["SLV"].ag
