"""Unbonded vertical FRP bars (SI units: m, N, Pa; per metre of wall length).

docs/model.md §2: the acting bar (one line centred in the wall's mid-plane, or one on each
face external) has a lever arm b_r about the base corner it turns on (Eqs. 8–9), an area
A = ρ·B·1 m per line, and the tension T = E·A·e/H of an elongation e over the free length H.
Its rupture strain is ε_max = c·ε_u (the paper's mean value with the cyclic reduction c), or
with design values (CNR-DT 200 R1/2013 §3.5) ε_max = c·ε_fd, ε_fd = η_a·ε_fk/γ_f.
"""

from __future__ import annotations

from typing import Literal

Position = Literal["centred", "external"]
#: Where the acting bars are: one line in the mid-plane, or one on each face (Eqs. 8–9).
POSITIONS: tuple[Position, ...] = ("centred", "external")

#: Cyclic reduction c of the rupture strain, ε_max = c·ε_u (paper, after its ref. [53]) [-].
DEFAULT_STRAIN_FACTOR = 0.5
#: The largest ratio ρ of the active bars the model takes [‰] (the project file, the
#: bars as built and the rocking model refuse more).
MAX_RATIO = 20.0
#: γ_f for the rupture of FRP at the ultimate limit state (CNR-DT 200 R1/2013 Table 3.1) [-].
FRP_RUPTURE_PARTIAL_FACTOR = 1.10
#: k of the 5 % fractile of a normal distribution (a large number of tests) [-].
FRACTILE_5_PERCENT = 1.645
#: CoV of the rupture strain assumed when the producer gives no characteristic value (an
#: assumption of this tool, on the safe side of the scatter of tension tests on FRP bars) [-].
DEFAULT_STRAIN_COV = 0.10
#: The exposures of CNR-DT 200 R1/2013 Table 3.2, in the table's order.
EXPOSURES: tuple[str, ...] = ("internal", "external", "aggressive")
#: η_a by fibre and exposure (CNR-DT 200 R1/2013 Table 3.2) [-].
ENVIRONMENTAL_FACTORS: dict[str, dict[str, float]] = {
    "glass": {"internal": 0.75, "external": 0.65, "aggressive": 0.50},
    "carbon": {"internal": 0.95, "external": 0.85, "aggressive": 0.85},
    "aramid": {"internal": 0.85, "external": 0.75, "aggressive": 0.70},
}


def _check_position(position: str) -> None:
    if position not in POSITIONS:
        raise ValueError(f"position must be 'centred' or 'external', got {position!r}")


def lever_arm(position: str, thickness: float) -> float:
    """b_r [m] of the acting bar about the base corner: R·sin α = B/2 centred (Eq. 8),
    2R·sin α = B external (Eq. 9); B [m]."""
    _check_position(position)
    return (0.5 if position == "centred" else 1.0) * thickness


def faces(position: str) -> int:
    """Lines of bars [-]: 1 centred (mid-plane), 2 external (one per face); docs/model.md §2,
    paper Eqs. 8–9."""
    _check_position(position)
    return 1 if position == "centred" else 2


def bar_area(ratio_permille: float, thickness: float) -> float:
    """Area A [m² per metre of wall] of one line of bars: ρ·B·1 m, ρ [‰], B [m]
    (docs/model.md §2)."""
    return ratio_permille * 1e-3 * thickness


def bar_force(elastic_modulus: float, area: float, strain: float) -> float:
    """Tension T = E·A·ε [N/m] of the acting bar at strain ε = e/H [-] (E [Pa], A [m²/m];
    docs/model.md §2, paper Eq. 7)."""
    return elastic_modulus * area * strain


def elongation_strain(elongation: float, free_length: float) -> float:
    """Strain ε = e/H [-] of an unbonded bar stretched by e [m] over its free length H [m]
    (docs/model.md §2)."""
    return elongation / free_length


def rupture_strain(strain: float, cyclic_factor: float) -> float:
    """ε_max = c·ε [-]: the cyclic reduction c of the bar's strain at rupture ε, the producer's
    mean ε_u (the paper) or the design ε_fd of :func:`fd_strain` (docs/model.md §2.1)."""
    return cyclic_factor * strain


def eta_a(fibre: str, exposure: str) -> float:
    """η_a [-], the environmental conversion factor of an FRP of ``fibre`` (glass, carbon,
    aramid) under ``exposure`` (internal, external, aggressive), CNR-DT 200 R1/2013 Table 3.2.

    Raises:
        KeyError: a fibre or exposure not in the table (the caller names the key of its input).
    """
    return ENVIRONMENTAL_FACTORS[fibre][exposure]


def fd_strain(
    characteristic: float, eta_a: float, partial_factor: float = FRP_RUPTURE_PARTIAL_FACTOR
) -> float:
    """ε_fd = η_a·ε_fk/γ_f [-] (CNR-DT 200 R1/2013 §3.5): characteristic strain ε_fk,
    environmental factor η_a (Table 3.2), partial factor γ_f (Table 3.1)."""
    return eta_a * characteristic / partial_factor


def design_rupture_strain(
    characteristic: float,
    eta_a: float,
    cyclic_factor: float,
    partial_factor: float = FRP_RUPTURE_PARTIAL_FACTOR,
) -> float:
    """ε_max = c·η_a·ε_fk/γ_f [-]: the design value ε_fd of CNR-DT 200 R1/2013 §3.5 with the
    cyclic reduction c (docs/model.md §2.1), c·ε_fd."""
    return rupture_strain(fd_strain(characteristic, eta_a, partial_factor), cyclic_factor)


def characteristic_strain(mean: float, cov: float, k: float = FRACTILE_5_PERCENT) -> float:
    """5 % fractile of a normal distribution, ε_fk = ε_mean·(1 − k·CoV) [-], the
    characteristic value of CNR-DT 200 R1/2013 §3.5 (docs/model.md §2.1); ε_mean [-], CoV [-],
    k [-].

    For producers who give the mean and the coefficient of variation instead of the
    characteristic value (k = 1.645 for a large number of tests).
    """
    if not (mean > 0 and 0 <= cov < 1 / k):
        raise ValueError(f"need mean > 0 and 0 <= cov < 1/k, got {mean}, {cov}")
    return mean * (1.0 - k * cov)
