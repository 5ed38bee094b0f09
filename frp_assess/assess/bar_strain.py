"""Bars as they are built: the design rupture strain of a bar material.

Units: diameters [mm], bar areas [mm²], lengths and spacings [m], ratios [‰], forces [kN],
stresses [MPa], E [GPa], density [kg/m³], price [currency/kg].

**Design strain** (CNR-DT 200 R1/2013 §3, design values of the FRP): ε_d = c·η_a·ε_fk/γ_f, with
the characteristic rupture strain ε_fk (5 % fractile), the environmental conversion factor η_a
of Table 3.2 (:func:`frp_assess.rules.bars.eta_a`), the partial factor γ_f = 1.10 for the rupture of
FRP (Table 3.1) and the cyclic reduction c = 0.5 of ``docs/model.md`` §2.  The values of η_a
are those of CNR-DT 200 R1/2013 Table 3.2 (they coincide with the environmental reduction
factors C_E of ACI 440.2R).  Basalt is not in the table: BFRP takes the glass values, the fibre
whose alkali and moisture sensitivity is closest (a conservative choice).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from frp_assess.errors import InputError
from frp_assess.rules import bars as rule
from frp_assess.rules.bars import (
    DEFAULT_STRAIN_FACTOR,
    ENVIRONMENTAL_FACTORS,
    EXPOSURES,
    FRP_RUPTURE_PARTIAL_FACTOR,
    eta_a,
)

Exposure = Literal["internal", "external", "aggressive"]


#: Cyclic reduction of the rupture strain, c (``docs/model.md`` §2; the rules' default).
CYCLIC_FACTOR = DEFAULT_STRAIN_FACTOR

#: Fibre of each bar material; basalt is not in Table 3.2 and takes the glass values.
FIBRE_OF_MATERIAL: dict[str, str] = {
    "GFRP": "glass",
    "CFRP": "carbon",
    "AFRP": "aramid",
    "BFRP": "glass",
}


# ---------------------------------------------------------------------------------------------
# Design strain


def fibre_of(material: str, fibre: str | None = None) -> str:
    """The fibre whose η_a a bar material takes: ``fibre`` when given (basalt: the glass
    values, module docstring), else by the library key, else glass (the smallest η_a of the
    table: the conservative choice for a fibre not stated)."""
    if fibre is not None:
        return "glass" if fibre == "basalt" else fibre
    return FIBRE_OF_MATERIAL.get(material, "glass")


def environmental_factor(material: str, exposure: str, *, fibre: str | None = None) -> float:
    """η_a of CNR-DT 200 R1/2013 Table 3.2 for a bar material (GFRP, BFRP, CFRP, AFRP), or
    for the ``fibre`` given (glass, carbon, aramid, basalt)."""
    if fibre is not None:
        fibre = fibre_of(material, fibre)
    else:
        fibre = FIBRE_OF_MATERIAL.get(material)
    if fibre is None or fibre not in ENVIRONMENTAL_FACTORS:
        raise InputError(
            f"no environmental factor for {material!r}; known: {', '.join(FIBRE_OF_MATERIAL)}",
            key="materials",
        )
    if exposure not in EXPOSURES:
        raise InputError(
            f"unknown exposure {exposure!r}; choose one of: {', '.join(EXPOSURES)}",
            key="exposure",
        )
    return eta_a(fibre, exposure)


@dataclass(frozen=True)
class DesignStrain:
    """ε_d = c·η_a·ε_fk/γ_f and its factors.

    Attributes:
        characteristic: ε_fk [-].  eta_a: η_a [-].  partial_factor: γ_f [-].
        cyclic_factor: c [-].  exposure: internal, external or aggressive.
        design: ε_d [-].
    """

    characteristic: float
    eta_a: float
    partial_factor: float
    cyclic_factor: float
    exposure: str
    design: float

    @property
    def fd(self) -> float:
        """ε_fd = η_a·ε_fk/γ_f [-], the design strain before the cyclic reduction c."""
        return rule.fd_strain(self.characteristic, self.eta_a, self.partial_factor)


def bar_design_strain(
    characteristic: float,
    material: str,
    exposure: str,
    *,
    cyclic_factor: float = CYCLIC_FACTOR,
    partial_factor: float = FRP_RUPTURE_PARTIAL_FACTOR,
    fibre: str | None = None,
) -> DesignStrain:
    """The rupture strain the analysis uses: ε_d = c·η_a·ε_fk/γ_f (module docstring);
    ``fibre`` as :func:`environmental_factor`."""
    if not characteristic > 0:
        raise ValueError(f"characteristic strain must be > 0, got {characteristic}")
    if not (0 < cyclic_factor <= 1 and partial_factor >= 1):
        raise ValueError(f"need 0 < c <= 1 and gamma_f >= 1, got {cyclic_factor}, {partial_factor}")
    eta = environmental_factor(material, exposure, fibre=fibre)
    return DesignStrain(
        characteristic=characteristic,
        eta_a=eta,
        partial_factor=partial_factor,
        cyclic_factor=cyclic_factor,
        exposure=exposure,
        design=rule.design_rupture_strain(characteristic, eta, cyclic_factor, partial_factor),
    )
