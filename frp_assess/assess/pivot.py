"""The pivot check of every case of an assessment, and the rule that drops an option.

docs/model.md §1.1.  Units: forces per metre of wall [kN/m], lengths [m], stresses [MPa].

The check is made at the largest compression the section must carry in the model,
N = W + T_u (T_u: the acting bar at the rupture strain ε_max the model uses, c·ε_u or the
design value; N = W for the unreinforced wall), on the stress block 0.85·f_d:
x = N / (0.85·f_d·1 m).

Drop rule (:func:`pivot_fails`):

* ``pivot: edge`` — the rigid block turning about its edge is accepted while
  x/B ≤ :data:`~frp_assess.assess.masonry.DEFAULT_PIVOT_LIMIT` (0.10);
* ``pivot: crushing`` — the shifted pivot is modelled, so the option fails only when the
  mechanism does not exist: the bar lies inside the compressed zone (x ≥ its distance from the
  compressed edge: B/2 centred, B external; a bar in compression cannot restrain the wall), or
  the base cannot carry N at all (x ≥ B).
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.inputs import UNREINFORCED, AssessmentInputs, Material, Option
from frp_assess.assess.masonry import (
    DEFAULT_PIVOT_LIMIT,
    STRESS_BLOCK_FACTOR,
    PivotCheck,
    max_ratio_for_pivot,
    pivot_check,
)
from frp_assess.dynamics import PivotRule, Position
from frp_assess.dynamics.units import KPA_PER_GPA
from frp_assess.results.pivot import PivotResult
from frp_assess.rules.bars import bar_area, bar_force, lever_arm
from frp_assess.rules.masonry import toe_crushes, wall_weight


def pivot_fails(
    rule: PivotRule,
    depth: float,
    thickness: float,
    bar_distance: float | None,
    limit: float = DEFAULT_PIVOT_LIMIT,
) -> str | None:
    """Why a case fails the pivot check, in one line; ``None`` when it holds.

    Args:
        rule: ``edge`` or ``crushing`` (``analysis.pivot``).
        depth: x [m].
        thickness: B [m].
        bar_distance: distance of the acting bar from the compressed edge [m] (B/2 centred,
            B external); ``None`` unreinforced.
        limit: largest x/B accepted with the edge pivot [-].
    """
    mm = 1e3
    if rule == "edge":
        if depth / thickness > limit:
            return (
                f"x/B = {depth / thickness:.3f} > {limit:.2f}: the compressed zone at the pivot "
                f"(x = {depth * mm:.0f} mm) is too deep for a rigid block turning about its edge"
            )
        return None
    if rule != "crushing":
        raise ValueError(f"pivot must be 'edge' or 'crushing', got {rule!r}")
    if not toe_crushes(depth, thickness, bar_distance):
        return None
    if toe_crushes(depth, thickness):
        return (
            f"x = {depth * mm:.0f} mm >= B = {thickness * mm:.0f} mm: the base cannot carry the "
            "weight and the bar force at rupture, there is no rocking mechanism"
        )
    assert bar_distance is not None  # x < B: the bar's distance is the smaller bound
    return (
        f"the bar, {bar_distance * mm:.0f} mm from the compressed edge, lies inside the "
        f"compressed zone x = {depth * mm:.0f} mm: it cannot be in tension, the mechanism "
        "does not exist"
    )


@dataclass(frozen=True)
class CasePivot:
    """The pivot of one case.

    Attributes:
        case: the case's name (``Unreinforced`` or the option's).
        rule: ``analysis.pivot``.
        check: W, T_u, N, f_d, x, x/B against the edge limit (:class:`PivotCheck`).
        bar_distance: the acting bar from the compressed edge [m]; ``None`` unreinforced.
        model_pivot: the pivot the case's IDA runs with (``edge`` when ``crushing`` has no
            mechanism, :attr:`RockingModel.pivot_used`).
        reason: why the case is dropped (one line), ``None`` when it stands.
    """

    case: str
    rule: PivotRule
    check: PivotCheck
    bar_distance: float | None
    model_pivot: PivotRule
    reason: str | None

    @property
    def dropped(self) -> bool:
        """The case fails the check (an option leaves the ranking)."""
        return self.reason is not None

    def line(self) -> str:
        """One line for the report: the check's numbers, then the verdict."""
        c = self.check
        head = (
            f"{self.case}: N = {c.force:.0f} kN/m (W {c.weight:.0f} + T_u {c.bar_force:.0f}) on "
            f"0.85*f_d = {STRESS_BLOCK_FACTOR * c.f_d:.2f} MPa needs x = {c.depth * 1e3:.0f} mm, "
            f"x/B = {c.depth_ratio:.3f}"
        )
        if self.reason is not None:
            return f"{head}; dropped: {self.reason}"
        if self.rule == "crushing":
            return f"{head}; pivot moved {c.depth * 500:.0f} mm inward (pivot: crushing)"
        return f"{head} <= {c.limit:.2f}: the edge pivot holds"

    def result(self) -> PivotResult:
        """The results.json record of this case."""
        c = self.check
        return PivotResult(
            rule=self.rule,
            model_pivot=self.model_pivot,
            weight=c.weight,
            bar_force=c.bar_force,
            force=c.force,
            depth=c.depth,
            depth_ratio=c.depth_ratio,
            pivot_shift=0.5 * c.depth if self.model_pivot == "crushing" else 0.0,
            bar_distance=self.bar_distance,
            limit=c.limit,
            dropped=self.dropped,
            reason=self.line(),
        )


def case_pivot(
    inputs: AssessmentInputs, option: Option | None, limit: float = DEFAULT_PIVOT_LIMIT
) -> CasePivot:
    """The pivot check of the unreinforced wall (``None``) or of one option."""
    b = inputs.thickness
    weight = wall_weight(inputs.unit_weight, b, inputs.height)  # [kN/m]
    f_d = inputs.masonry_strength.f_d
    rule = inputs.model.pivot
    if option is None:
        force, distance = 0.0, None
    else:
        strain = inputs.rupture_strain(option.material)  # ε_max the model uses [-]
        modulus = option.material.elastic_modulus * KPA_PER_GPA  # [kPa]: T in kN/m
        force = bar_force(modulus, bar_area(option.ratio, b), strain)
        distance = lever_arm(option.position, b)
    check = pivot_check(weight, force, b, f_d, limit)
    model = inputs.model_for(option)
    return CasePivot(
        case=UNREINFORCED if option is None else option.name,
        rule=rule,
        check=check,
        bar_distance=distance,
        model_pivot=model.pivot_used,
        reason=pivot_fails(rule, check.depth, b, distance, limit),
    )


def pivot_checks(
    inputs: AssessmentInputs, limit: float = DEFAULT_PIVOT_LIMIT
) -> tuple[CasePivot, ...]:
    """The pivot check of every case, in the order of :meth:`AssessmentInputs.case_names`."""
    return (
        case_pivot(inputs, None, limit),
        *(case_pivot(inputs, o, limit) for o in inputs.options),
    )


def largest_ratio(
    inputs: AssessmentInputs,
    material: Material,
    position: Position,
    limit: float = DEFAULT_PIVOT_LIMIT,
) -> float:
    """Largest bar ratio ρ [‰] that the drop rule keeps (for design mode's search range).

    The depth must stay below a bound x_b: ``edge`` x_b = limit·B (kept at equality);
    ``crushing`` the bar's distance from the compressed edge (B/2 centred, B external; the
    option is dropped at equality, so ρ must stay strictly below the value returned).  From
    x = (W + T_u)/(0.85·f_d·1 m) and T_u = E·ρ·B·ε_max:
    ρ = (0.85·f_d·x_b − W)/(E·B·ε_max), 0 when the wall alone reaches the bound.
    """
    b = inputs.thickness
    weight = wall_weight(inputs.unit_weight, b, inputs.height)  # [kN/m]
    f_d = inputs.masonry_strength.f_d
    strain = inputs.rupture_strain(material)  # ε_max the model uses [-]
    bound = limit * b if inputs.model.pivot == "edge" else lever_arm(position, b)
    return max_ratio_for_pivot(weight, b, material.elastic_modulus, strain, f_d, bound)
