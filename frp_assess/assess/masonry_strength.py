"""The masonry at the pivot: strength table, knowledge-level rule, crushing of the pivot.

Units: lengths [m], forces per metre of wall [kN/m], moments per metre [kN·m/m], stresses
[MPa], unit weights [kN/m³].  Everything is per metre of wall length, as in the dynamics
(``docs/model.md`` §1).

**Table.** :data:`MASONRY_TABLE` holds, per masonry type of Circolare 2019 (NTC 2018)
Tab. C8.5.I, the ranges of the mean compressive strength f_m, of the shear strength τ0 and of
the elastic modulus E, and the unit weight w.  The numbers were typed from the Circolare as
the author knows it; the published table could not be retrieved while this module was
written, so check them against your copy (the f_m range of solid brick and lime mortar,
2.6–4.3 MPa, is the one quoted in issue 16).  The table's values refer to poor mortar, no
through-stones, leaves not connected; its corrective coefficients (Tab. C8.5.II) are not
applied here: give a project value instead.

**Knowledge level** (Circolare 2019 §C8.5.4.1): with LC1 the strength is the *minimum* of the
table's range and the elastic modulus the *mean*; with LC2 and LC3 both are the means (LC3
normally replaces them by test results: pass them as project values).  The design strength
divides by the confidence factor FC of Tab. C8.5.IV (1.35 / 1.20 / 1.00); a partial factor
γ_M may be added (1 by default: the seismic assessment of existing masonry, Circolare
§C8.7.1, uses f/FC).

**Pivot.** The rocking model assumes a rigid block turning about the edge of its base.  The
base actually carries the compressive force N = W + T (weight of the wall above the pivot and
tension of the bars) on a compressed zone of finite depth x.  With the stress block of 0.85·f_d
over x (the rectangular block behind the flexural strength of masonry piers, NTC 2018
§7.8.2.2.1, M_u = (l²·t·σ0/2)·(1 − σ0/(0.85·f_d))), equilibrium gives x = N / (0.85·f_d·1 m).
The resultant of the block lies at x/2 from the edge, so the pivot moves inward by x/2 and
every lever arm measured from the edge shrinks by x/2 (Circolare 2019 §C8.7.1 allows the finite
compressive strength of masonry to be accounted for precisely by moving the hinge inward).  The
lever arm of gravity falls from B/2 to (B − x)/2, i.e. by the fraction x/B: the premise is
kept while x ≤ k·B with k = 0.1 by default (edge-pivot moments within 10 % of the crushed-pivot
ones), a stated choice that the caller can change.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from frp_assess.dynamics.units import KPA_PER_MPA
from frp_assess.errors import InputError
from frp_assess.results.pivot import MasonryResult
from frp_assess.rules import masonry as rule
from frp_assess.rules.masonry import STRESS_BLOCK_FACTOR as STRESS_BLOCK_FACTOR  # re-export
from frp_assess.rules.masonry import (
    base_force,
    compressed_zone_depth,
    design_strength,
)

KnowledgeLevel = Literal["LC1", "LC2", "LC3"]

#: Default largest x/B for which the edge-pivot premise is accepted (see the module docstring).
DEFAULT_PIVOT_LIMIT = 0.10

_TABLE = "Circolare 2019 (NTC 2018), Tab. C8.5.I"


@dataclass(frozen=True)
class MasonryType:
    """One row of Circolare 2019 Tab. C8.5.I.

    Attributes:
        key: kebab-case key (the keys of ``frp_assess.config.library.MASONRY`` plus
            ``regular-soft-stone``).
        description: the type in words, with the Italian name of the table.
        f_m: (min, max) mean compressive strength [MPa].
        tau_0: (min, max) mean shear strength for diagonal cracking [MPa].
        elastic_modulus: (min, max) mean elastic modulus E [MPa].
        unit_weight: (min, max) unit weight w [kN/m³] (equal ends when the table gives one).
        source: the table cited.
    """

    key: str
    description: str
    f_m: tuple[float, float]
    tau_0: tuple[float, float]
    elastic_modulus: tuple[float, float]
    unit_weight: tuple[float, float]
    source: str = _TABLE


#: Circolare 2019 Tab. C8.5.I by key (values as typed in the module docstring).
MASONRY_TABLE: dict[str, MasonryType] = {
    m.key: m
    for m in (
        MasonryType(
            "rubble-stone",
            "rubble stone, irregular stones and pebbles (muratura in pietrame disordinata)",
            (1.0, 2.0),
            (0.018, 0.032),
            (690.0, 1050.0),
            (19.0, 19.0),
        ),
        MasonryType(
            "roughly-cut-stone",
            "roughly cut stone, leaves of uneven thickness (muratura a conci sbozzati)",
            (2.0, 2.0),
            (0.035, 0.051),
            (1020.0, 1440.0),
            (20.0, 20.0),
        ),
        MasonryType(
            "good-split-stone",
            "split stone with good texture (muratura in pietre a spacco con buona tessitura)",
            (2.6, 3.8),
            (0.056, 0.074),
            (1500.0, 1980.0),
            (21.0, 21.0),
        ),
        MasonryType(
            "soft-stone",
            "irregular soft stone, tuff, calcarenite (muratura irregolare di pietra tenera)",
            (1.4, 2.2),
            (0.028, 0.042),
            (900.0, 1260.0),
            (13.0, 16.0),
        ),
        MasonryType(
            "regular-soft-stone",
            "regular soft stone blocks, tuff, calcarenite (muratura a conci regolari di pietra "
            "tenera)",
            (2.0, 3.2),
            (0.04, 0.08),
            (1200.0, 1620.0),
            (13.0, 16.0),
        ),
        MasonryType(
            "squared-blocks",
            "squared stone blocks (muratura a blocchi lapidei squadrati)",
            (5.8, 8.2),
            (0.09, 0.12),
            (2400.0, 3200.0),
            (22.0, 22.0),
        ),
        MasonryType(
            "solid-brick-lime-mortar",
            "solid brick and lime mortar (muratura in mattoni pieni e malta di calce)",
            (2.6, 4.3),
            (0.05, 0.13),
            (1200.0, 1800.0),
            (18.0, 18.0),
        ),
        MasonryType(
            "semi-solid-brick-cement-mortar",
            "semi-solid brick and cement mortar (muratura in mattoni semipieni con malta "
            "cementizia)",
            (5.0, 8.0),
            (0.08, 0.17),
            (3500.0, 5600.0),
            (15.0, 15.0),
        ),
    )
}


@dataclass(frozen=True)
class MasonryDesignValues:
    """The masonry values an assessment uses.

    Attributes:
        key: masonry type.
        knowledge_level: LC1, LC2 or LC3.
        f_m: compressive strength taken [MPa] (table value by the level's rule, or the
            project's).
        elastic_modulus: E taken [MPa].
        tau_0: shear strength taken [MPa] (same rule as f_m).
        confidence_factor: FC [-].
        partial_factor: γ_M [-].
        f_d: design compressive strength f_m / (FC·γ_M) [MPa].
        tau_0d: design shear strength τ0 / (FC·γ_M) [MPa].
        from_project: names of the values given by the project instead of the table.
    """

    key: str
    knowledge_level: str
    f_m: float
    elastic_modulus: float
    tau_0: float
    confidence_factor: float
    partial_factor: float
    f_d: float
    tau_0d: float
    from_project: tuple[str, ...] = ()


def _mean(r: tuple[float, float]) -> float:
    return 0.5 * (r[0] + r[1])


def masonry_type(key: str) -> MasonryType:
    """The table row ``key``; an unknown key is an :class:`InputError` naming the choices."""
    try:
        return MASONRY_TABLE[key]
    except KeyError:
        choices = ", ".join(MASONRY_TABLE)
        raise InputError(
            f"unknown masonry type {key!r}; choose one of: {choices}", key="wall.masonry"
        ) from None


def knowledge_level_fc(knowledge_level: str) -> float:
    """FC [-] of a knowledge level (Circolare 2019 Tab. C8.5.IV); an unknown level is an
    input error on ``code_check.knowledge_level``, where the project sets it."""
    try:
        return rule.confidence_factor(knowledge_level)
    except KeyError:
        raise InputError(
            f"unknown knowledge level {knowledge_level!r}; choose LC1, LC2 or LC3",
            key="code_check.knowledge_level",
        ) from None


def masonry_design_values(
    key: str,
    knowledge_level: str = "LC1",
    *,
    f_m: float | None = None,
    elastic_modulus: float | None = None,
    tau_0: float | None = None,
    partial_factor: float = 1.0,
) -> MasonryDesignValues:
    """Strength and stiffness by the knowledge-level rule of Circolare 2019 §C8.5.4.1.

    LC1: minimum of the strength ranges, mean of E.  LC2, LC3: means.  A project value
    (``f_m``, ``elastic_modulus``, ``tau_0`` [MPa]) overrides the table's.  The design values
    divide by FC (Tab. C8.5.IV) and by ``partial_factor`` γ_M.
    """
    row = masonry_type(key)
    fc = knowledge_level_fc(knowledge_level)
    for name, value in (("f_m", f_m), ("elastic_modulus", elastic_modulus), ("tau_0", tau_0)):
        if value is not None and not value > 0:
            raise InputError(f"must be > 0 MPa, got {value}", key=f"wall.{name}")
    if not partial_factor >= 1.0:
        raise InputError(f"must be >= 1, got {partial_factor}", key="wall.partial_factor")
    lowest = knowledge_level == "LC1"
    strength = row.f_m[0] if lowest else _mean(row.f_m)
    shear = row.tau_0[0] if lowest else _mean(row.tau_0)
    modulus = _mean(row.elastic_modulus)
    given = tuple(
        n
        for n, v in (("f_m", f_m), ("elastic_modulus", elastic_modulus), ("tau_0", tau_0))
        if v is not None
    )
    strength = f_m if f_m is not None else strength
    modulus = elastic_modulus if elastic_modulus is not None else modulus
    shear = tau_0 if tau_0 is not None else shear
    return MasonryDesignValues(
        key=key,
        knowledge_level=knowledge_level,
        f_m=strength,
        elastic_modulus=modulus,
        tau_0=shear,
        confidence_factor=fc,
        partial_factor=partial_factor,
        f_d=design_strength(strength, fc, partial_factor),
        tau_0d=design_strength(shear, fc, partial_factor),
        from_project=given,
    )


# ---------------------------------------------------------------------------------------------
# The compressed zone at the pivot (the rules of frp_assess.rules.masonry, in kN and kPa)


def compressed_depth(force: float, f_d: float) -> float:
    """Depth x [m] of the stress block 0.85·f_d that carries ``force`` [kN/m] (f_d [MPa]):
    :func:`~frp_assess.rules.masonry.compressed_zone_depth` with f_d in kPa."""
    if not f_d > 0:
        raise ValueError(f"f_d must be > 0 MPa, got {f_d}")
    return compressed_zone_depth(force, f_d * KPA_PER_MPA)


@dataclass(frozen=True)
class PivotCheck:
    """Compression at the pivot against the masonry's strength.

    Attributes:
        weight: W [kN/m].
        bar_force: T [kN/m].
        force: N = W + T [kN/m].
        f_d: design compressive strength [MPa].
        depth: x = N / (0.85·f_d·1 m) [m].
        depth_ratio: x/B [-].
        limit: largest accepted x/B [-].
        rigid_block_holds: x/B ≤ limit and x < B.
    """

    weight: float
    bar_force: float
    force: float
    f_d: float
    depth: float
    depth_ratio: float
    limit: float
    rigid_block_holds: bool

    @property
    def reason(self) -> str:
        """One line for a report: why the premise holds or fails."""
        verdict = "holds" if self.rigid_block_holds else "fails"
        return (
            f"pivot: N = {self.force:.0f} kN/m needs x = {self.depth * 1e3:.0f} mm of masonry "
            f"at {STRESS_BLOCK_FACTOR:g}*f_d = {STRESS_BLOCK_FACTOR * self.f_d:.2f} MPa, x/B = "
            f"{self.depth_ratio:.3f} (limit {self.limit:.2f}): rigid-block premise {verdict}"
        )


def pivot_check(
    weight: float,
    bar_force: float,
    thickness: float,
    f_d: float,
    limit: float = DEFAULT_PIVOT_LIMIT,
) -> PivotCheck:
    """The compressed zone at the pivot and whether the rigid-block premise holds.

    Args:
        weight: W [kN/m] (:func:`~frp_assess.rules.masonry.wall_weight` of w [kN/m³]).
        bar_force: T [kN/m] (:func:`~frp_assess.rules.bars.bar_force`), at rupture or at the
            peak strain reached.
        thickness: B [m].
        f_d: design compressive strength [MPa] (:func:`masonry_design_values`).
        limit: largest accepted x/B [-].
    """
    if not thickness > 0:
        raise ValueError(f"thickness must be > 0 m, got {thickness}")
    if not 0 < limit <= 1:
        raise ValueError(f"limit must be in (0, 1], got {limit}")
    force = base_force(weight, bar_force)
    x = compressed_depth(force, f_d)
    ratio = x / thickness
    return PivotCheck(
        weight=weight,
        bar_force=bar_force,
        force=force,
        f_d=f_d,
        depth=x,
        depth_ratio=ratio,
        limit=limit,
        rigid_block_holds=bool(ratio <= limit and ratio < 1.0),
    )


# ---------------------------------------------------------------------------------------------
# The strength an assessment uses


#: f_m [MPa] taken when the project gives neither ``wall.masonry`` nor
#: ``wall.compressive_strength``: the lowest value of Tab. C8.5.I (rubble stone, LC1 rule),
#: so that an unstated masonry is never credited with more strength than the table allows.
DEFAULT_COMPRESSIVE_STRENGTH = min(m.f_m[0] for m in MASONRY_TABLE.values())


def masonry_strength(
    masonry: str | None, knowledge_level: str, compressive_strength: float | None = None
) -> MasonryResult:
    """f_m and f_d = f_m/FC of a project (docs/model.md §1.1), as results.json records it.

    The project's ``compressive_strength`` [MPa] wins; else the masonry type's value by the
    knowledge-level rule (:func:`masonry_design_values`); else
    :data:`DEFAULT_COMPRESSIVE_STRENGTH`.  FC is always the knowledge level's.
    """
    fc = knowledge_level_fc(knowledge_level)
    if compressive_strength is not None:
        if not compressive_strength > 0:
            raise InputError(
                f"must be > 0 MPa, got {compressive_strength}", key="wall.compressive_strength"
            )
        f_m, source = compressive_strength, "project value (wall.compressive_strength)"
    elif masonry is not None:
        v = masonry_design_values(masonry, knowledge_level)
        rule = "minimum" if knowledge_level == "LC1" else "mean"
        f_m, source = v.f_m, f"{_TABLE}, {masonry}, {rule} of the range ({knowledge_level})"
    else:
        f_m = DEFAULT_COMPRESSIVE_STRENGTH
        source = (
            f"no wall.masonry nor wall.compressive_strength: the lowest f_m of {_TABLE} "
            f"({f_m:g} MPa)"
        )
    return MasonryResult(
        masonry=masonry,
        knowledge_level=knowledge_level,
        f_m=f_m,
        confidence_factor=fc,
        f_d=design_strength(f_m, fc),
        stress_block_factor=STRESS_BLOCK_FACTOR,
        source=source,
    )
