"""The numerical model of one case, built in one place (docs/model.md §1–2, §1.1).

``run`` and ``design`` (:meth:`AssessmentInputs.model_for`), ``study``
(:meth:`StudyPlan.model`), ``ida`` and ``simulate`` (``cli/wall_args.py``) and the TUI's
preview (``tui/core/editor_state.py``) all build their :class:`~frp_assess.dynamics.RockingModel`
with :func:`rocking_model`: the wall with its design strength f_d (so that ``pivot:
crushing`` moves the pivot wherever the case has a masonry strength), the bars, the options.

Inputs are in practitioners' units (m, kN/m³, MPa, GPa, ‰); ``dynamics/units.py`` turns them
into SI.  The one refusal of the masonry at the base (``rules/masonry.py``): a base that
cannot carry the wall's own weight, x_W = W/(0.85·f_d) ≥ B, is an :class:`InputError`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from frp_assess.assess.masonry_strength import masonry_strength
from frp_assess.dynamics import Mechanism, ModelOptions, Position, Rebars, RockingModel, Wall
from frp_assess.dynamics.loads import NO_LOADS, Loads
from frp_assess.dynamics.rebars import DEFAULT_STRAIN_FACTOR
from frp_assess.dynamics.units import rebars_from_practice, wall_from_practice
from frp_assess.errors import InputError
from frp_assess.rules.geometry import slenderness_problem as slenderness_problem  # for cli, study
from frp_assess.rules.masonry import (
    base_carries_weight,
    compressed_zone_depth,
    weight_not_carried,
)


@dataclass(frozen=True)
class WallInput:
    """The wall of a case, per metre of length.

    Attributes:
        thickness: B [m].  height: H [m].  unit_weight: w [kN/m³].
        design_strength: f_d = f_m/FC of the masonry [MPa] (:func:`case_design_strength`);
            ``inf``: none (the pivot stays at the edge).
    """

    thickness: float
    height: float
    unit_weight: float
    design_strength: float = math.inf

    def wall(self) -> Wall:
        """The dynamics wall (SI)."""
        return wall_from_practice(
            self.thickness, self.height, self.unit_weight, self.design_strength
        )


@dataclass(frozen=True)
class BarsInput:
    """The acting bars of a case.

    Attributes:
        elastic_modulus: E [GPa].
        strain: the strain at rupture the cyclic factor multiplies [-]: the mean ε_u, or the
            design ε_fd = η_a·ε_fk/γ_f (:meth:`AssessmentInputs.strain_at_rupture`).
        position: ``centred`` or ``external``.  ratio: ρ [‰].
        strain_factor: c [-], ε_max = c·strain.
    """

    elastic_modulus: float
    strain: float
    position: Position
    ratio: float
    strain_factor: float = DEFAULT_STRAIN_FACTOR

    def rebars(self) -> Rebars:
        """The dynamics bars (SI)."""
        return rebars_from_practice(
            self.elastic_modulus, self.strain, self.position, self.ratio, self.strain_factor
        )


def case_design_strength(
    masonry: str | None, knowledge_level: str, compressive_strength: float | None = None
) -> float:
    """f_d [MPa] of a case: the project's f_m, else the masonry type's by the knowledge level,
    else the lowest of Tab. C8.5.I, divided by FC (:func:`~frp_assess.assess.masonry_strength.
    masonry_strength`, the value results.json records)."""
    return masonry_strength(masonry, knowledge_level, compressive_strength).f_d


def weight_depth(wall: Wall) -> float:
    """x_W = W/(0.85·f_d) [m]: the compressed zone under the wall's own weight, at rest (0
    when f_d is infinite)."""
    return compressed_zone_depth(wall.weight, wall.compressive_strength)


def base_problem(wall: WallInput) -> str | None:
    """Why the base cannot carry the wall's weight (one line), ``None`` when it can."""
    w = wall.wall()
    if base_carries_weight(w.weight, w.thickness, w.compressive_strength):
        return None
    return weight_not_carried(w.weight, w.thickness, w.compressive_strength)


def rocking_model(
    wall: WallInput,
    mechanism: Mechanism,
    bars: BarsInput | None,
    options: ModelOptions,
    *,
    key: str = "wall.thickness",
    loads: Loads = NO_LOADS,
) -> RockingModel:
    """The model of one case (unreinforced when ``bars`` is None) carrying ``loads`` (SI,
    docs/model.md §12; :meth:`~frp_assess.assess.load_inputs.LoadsInput.loads`).

    Raises:
        InputError: on ``key``, a wall that is not taller than thick, or a base that cannot
            carry the wall's weight (module docstring); on the loads' keys, a base that cannot
            carry the loads too, or thrusts that tip the wall at rest about the crushing pivot.
    """
    problem = slenderness_problem(wall.thickness, wall.height) or base_problem(wall)
    if problem is not None:
        raise InputError(problem, key=key)
    rebars = None if bars is None else bars.rebars()
    try:
        model = RockingModel(wall.wall(), mechanism, rebars, options, loads)
    except ValueError as exc:  # with loads: the base cannot carry N₀ = W + Σ P
        raise InputError(str(exc), key="wall.loads.top") from None
    if loads and not model.a_rm > 0.0:
        # the schema refuses thrusts that tip the wall about its edge; the stress block of the
        # crushing pivot moves the pivot inside the wall and may do it too (docs/model.md §12)
        raise InputError(
            "expected loads the wall stands against at rest, found a_RM = "
            f"{model.a_rm_g:.4g} g <= 0 with the stress block at its base (N0*x0/2 taken from "
            "the moments that hold it): the thrusts tip the wall without an earthquake",
            key="wall.loads.thrust",
        )
    return model
