"""The loads a wall carries, as the assessment's inputs (docs/model.md §12), in practitioners'
units (kN/m, m, mm², MPa, GPa, kN per tie): the project's ``wall.loads`` block maps onto
these, results.json records them, and :meth:`LoadsInput.loads` turns them into the SI
:class:`~frp_assess.dynamics.loads.Loads` of the model (``dynamics/units.py``).
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.dynamics.loads import NO_LOADS, Loads, Tie
from frp_assess.dynamics.units import (
    thrust_from_practice,
    tie_from_practice,
    top_load_from_practice,
)


@dataclass(frozen=True)
class TopLoadInput:
    """A vertical load on the top of the wall (a floor, the roof)."""

    name: str
    load: float  #: P [kN/m]
    distance: float  #: d [m] of its line of action from the outer face
    carried: bool = True  #: its mass moves with the top of the wall (False: restrained)

    @property
    def inertia(self) -> str:
        """``carried`` or ``restrained``, the project's word."""
        return "carried" if self.carried else "restrained"


@dataclass(frozen=True)
class ThrustInput:
    """An outward horizontal force on the inner face (a roof, a vault)."""

    name: str
    force: float  #: F [kN/m]
    height: float  #: h [m] above the rocking base


@dataclass(frozen=True)
class TieInput:
    """Steel tie-rods at one height, every ``spacing`` metres along the wall."""

    name: str
    height: float  #: h_t [m] above the rocking base
    area: float  #: A_s [mm²] of one tie
    spacing: float  #: i_t [m]
    length: float  #: L_t [m], free length
    yield_strength: float = 235.0  #: f_y [MPa]
    elastic_modulus: float = 210.0  #: E_s [GPa]
    anchorage: float | None = None  #: F_a [kN per tie]; None: not governing
    diameter: float | None = None  #: the bar's diameter [mm] when given so

    def tie(self) -> Tie:
        """The ties per metre of wall, SI (k_t, F_y, F_a/i_t)."""
        return tie_from_practice(
            self.height,
            self.area,
            self.spacing,
            self.length,
            self.yield_strength,
            self.elastic_modulus,
            self.anchorage,
        )


@dataclass(frozen=True)
class LoadsInput:
    """Everything that bears on and pushes the wall; empty: the free-standing wall."""

    top: tuple[TopLoadInput, ...] = ()
    thrusts: tuple[ThrustInput, ...] = ()
    ties: tuple[TieInput, ...] = ()

    def __bool__(self) -> bool:
        return bool(self.top or self.thrusts or self.ties)

    def loads(self) -> Loads:
        """The SI loads of the model (:data:`~frp_assess.dynamics.loads.NO_LOADS` when empty,
        the very object the model's default is)."""
        if not self:
            return NO_LOADS
        return Loads(
            top=tuple(top_load_from_practice(p.load, p.distance, p.carried) for p in self.top),
            thrusts=tuple(thrust_from_practice(f.force, f.height) for f in self.thrusts),
            ties=tuple(t.tie() for t in self.ties),
        )


NO_LOAD_INPUTS = LoadsInput()


def default_name(kind: str, index: int, name: str) -> str:
    """A load's name in the outputs: the project's, else its kind and place (``tie 1``)."""
    return name or f"{kind} {index + 1}"
