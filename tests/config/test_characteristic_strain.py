"""A material's characteristic rupture strain ε_fk is a 5 % fractile: it cannot exceed the mean
ε_u (docs/model.md §2.1); a file giving more is refused on the line of the key, not credited."""

from __future__ import annotations

import pytest

from frp_assess.config import load_project_text
from frp_assess.errors import InputError

HEAD = """\
wall: {thickness: 0.3, height: 3, masonry: rubble-stone, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A1}
materials:
"""


def load(*lines: str) -> None:
    load_project_text(HEAD + "".join(f"  {line}\n" for line in lines), "p.yaml")


def test_a_characteristic_strain_above_the_mean_is_refused_on_its_line() -> None:
    with pytest.raises(InputError) as info:
        load(
            "XFRP:",
            "  elastic_modulus: 50",
            "  ultimate_strain: 0.015",
            "  density: 2000",
            "  price: 8",
            "  characteristic_strain: 0.016",
        )
    err = info.value
    assert (err.line, err.key) == (10, "materials.XFRP.characteristic_strain")
    assert "0.016" in err.message and "0.015" in err.message
    assert "\n" not in str(err)


def test_a_fractile_above_a_library_mean_is_refused_too() -> None:
    with pytest.raises(InputError) as info:
        load("GFRP: {characteristic_strain: 0.016}")  # the library's eps_u is 0.015
    assert (info.value.line, info.value.key) == (5, "materials.GFRP.characteristic_strain")


def test_a_fractile_at_or_below_the_mean_loads() -> None:
    load(
        "XFRP:",
        "  elastic_modulus: 50",
        "  ultimate_strain: 0.015",
        "  density: 2000",
        "  price: 8",
        "  characteristic_strain: 0.015",
    )
