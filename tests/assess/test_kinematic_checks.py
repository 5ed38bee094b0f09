"""The code's kinematic checks assembled for a wall and its options (assess.kinematic_checks).

Worked examples computed here by hand from Circolare 2019 §C8.7.1.2.1 and the geometry of
docs/model.md, not read back from the module: the paper's wall (H = 3 m, α = 7.5°,
w = 18 kN/m³) on an EC8-shaped spectrum a_g·S = 0.25 g, T_B = 0.15 s, T_C = 0.5 s,
T_D = 1.5 s, plateau 2.5, so that the displacement spectrum is
S_De(T, ξ) = Se(T, ξ)·g·T²/4π² with Se = a_g·S·η(ξ)·2.5·T_C/T in [T_C, T_D] and
a_g·S·η(ξ)·2.5·T_C·T_D/T² beyond (η = √(10/(5 + ξ[%])), EN 1998-1 eq. 3.6).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from frp_assess.assess.from_project import load_inputs
from frp_assess.assess.inputs import (
    ArtificialRecords,
    AssessmentInputs,
    CodeCheckSettings,
    Material,
    RetrofitOption,
)
from frp_assess.assess.kinematic_checks import (
    FloorPosition,
    IdaSummary,
    base_motions,
    case_checks,
    displacement_spectrum,
    ida_capacity_demand,
    ida_check,
    ida_confidence_factor,
    kinematic_checks,
    linear_check,
    model_capacity_curve,
    peak_displacements,
)
from frp_assess.dynamics import ModelOptions, Rebars, RockingModel, Wall
from frp_assess.dynamics.loads import NO_LOADS, Loads
from frp_assess.motions import ElasticSpectrum, Record
from frp_assess.results.checks import KinematicChecks
from frp_assess.results.json_io import from_data, to_json

G = 9.80665
ALPHA = math.radians(7.5)
B = 3.0 * math.tan(ALPHA)  # 0.394958 m
R = 0.5 * math.hypot(B, 3.0)  # 1.512943 m
FC = 1.35
AGS = 0.25  # a_g·S [g]
T_C, T_D = 0.5, 1.5
SPECTRUM = ElasticSpectrum("test", "ec8", AGS, 0.15, T_C, T_D)
CFRP = Material("CFRP", 150.0, 0.013, 1550.0, 0.0)
CFRP_EXTERNAL = RetrofitOption("CFRP external 1‰", CFRP, "external", 1.0)


def _inputs(**changes: object) -> AssessmentInputs:
    base: dict[str, object] = {
        "thickness": B,
        "height": 3.0,
        "unit_weight": 18.0,
        "mechanism": "one-sided",
        "spectrum": SPECTRUM,
        "records": ArtificialRecords(),
        "options": (CFRP_EXTERNAL,),
        # the paper's block about its edge: the hand calculations below are for α = 7.5°
        "model": ModelOptions(pivot="edge"),
    }
    base.update(changes)
    return AssessmentInputs(**base)  # type: ignore[arg-type]


def _theta_at(d: float) -> float:
    """Rotation at which the centroid has moved d: R·[sin α − sin(α − θ)] = d."""
    return ALPHA - math.asin(math.sin(ALPHA) - d / R)


def _eta(xi: float) -> float:
    return math.sqrt(10.0 / (5.0 + 100.0 * xi))


def test_worked_example_of_the_unreinforced_wall_at_ground_level():
    """e* = 1, M* = m = 18e3·B·3/g = 2174.82 kg/m;  d0 = B/2 = 0.197479 m.

    SLV: d_SLV = 0.4·d0 = 0.078991 m, a(d_SLV) = tan(α − θ)·g/FC = 0.570653 m/s²,
      T_SLV = 1.68·π·√(0.078991/0.570653) = 1.963647 s > T_D, so the demand is the
      plateau of S_De: 0.25·η(8 %)·2.5·0.5·1.5·g/4π² = 0.25·0.877058·1.875·9.80665/39.478418
      = 0.102125 m;  a_g,SLV = 0.25·0.078991/0.102125 = 0.193370 g (> a_g,SLD = tan α/FC
      = 0.097520 g);  ζ_E = 0.773481: fails.
    SLC: d_SLC = 0.118487 m, a = 0.379785 m/s², T_SLC = 1.56·π·√(d/a) = 2.737421 s > T_D,
      demand 0.25·η(10 %)·1.875·g/4π² = 0.095073 m, a_g,SLC = 0.311570 g, ζ_E = 1.246278.
    Linear: a0* = tan α/FC = 0.097520 g against a_g·S/q = 0.125 g: ζ_E = 0.780163, fails.
    """
    checks = kinematic_checks(_inputs())
    urm = checks.cases[0]
    assert urm.case == "Unreinforced" and checks.floor is None
    assert checks.fc == FC and checks.a_g == AGS
    cap = urm.capacity
    assert cap.e_star == pytest.approx(1.0)
    assert cap.m_star == pytest.approx(2174.82, abs=0.01)
    assert cap.d0 == pytest.approx(0.197479, abs=1e-6)
    assert cap.rupture_displacement is None and cap.rupture_limit is None

    slv = urm.slv
    assert slv.d_limit == pytest.approx(0.078991, abs=1e-6)
    assert slv.a_limit == pytest.approx(0.570653, abs=2e-6)
    assert slv.period == pytest.approx(1.963647, abs=5e-6)
    assert slv.damping == 0.08
    demand = AGS * _eta(0.08) * 2.5 * T_C * T_D * G / (4 * math.pi**2)
    assert demand == pytest.approx(0.102125, abs=1e-6)
    assert slv.demand == pytest.approx(demand, rel=1e-9)
    assert slv.a_g_sld == pytest.approx(0.097520, abs=1e-6)
    assert slv.a_g_capacity == pytest.approx(0.193370, abs=2e-6)
    assert slv.zeta_e == pytest.approx(0.773481, abs=1e-5)
    assert not slv.passed

    slc = urm.slc
    assert slc.d_limit == pytest.approx(0.118487, abs=1e-6)
    assert slc.period == pytest.approx(2.737421, abs=5e-6)
    assert slc.demand == pytest.approx(0.095073, abs=1e-6)
    assert slc.a_g_capacity == pytest.approx(0.311570, abs=2e-6)
    assert slc.zeta_e == pytest.approx(1.246278, abs=1e-5) and slc.passed

    lin = urm.linear
    assert lin.a0_star == pytest.approx(0.097520, abs=1e-6)
    assert lin.demand == pytest.approx(0.125)
    assert lin.zeta_e == pytest.approx(0.780163, abs=1e-5) and not lin.passed
    assert not urm.passed


def test_worked_example_of_external_cfrp_bars_whose_rupture_limits_d_slv():
    """CFRP external, ρ = 1 ‰ (E = 150 GPa, ε_u = 0.013, c = 0.5):
    K = sin α·tan α·(4/2)·E·ρ/(w·H) = 0.130526·0.131652·2·150e9·1e-3/54e3 = 95.467;
    θ_max = 2·asin(0.0065·3/(2·B)) = 0.049377 rad, d_rupture = R·[sin α − sin(α − θ_max)]
    = 0.074277 m < 0.4·d0: d_SLV = 0.074277 m (the capacity falls from α = 4.809 to 0.0817,
    far more than 50 %); d0 stays the bare wall's B/2.
    a(d_SLV) = [sin(α − θ) + K·sin θ]/cos(α − θ)·g/FC = 4.809·g/FC = 34.93 m/s²;
    T_SLV = 1.68·π·√(0.074277/34.93) = 0.2434 s lies on the plateau [T_B, T_C], where
    S_De(T) = 0.25·η(8 %)·2.5·g·T²/4π² grows with T: the demand is its value at T_SLV, and
    a_g,SLV = 0.25·d_SLV/demand.  The linear check is the bare wall's."""
    checks = kinematic_checks(_inputs())
    bars = checks.cases[1]
    assert bars.case == CFRP_EXTERNAL.name
    k = math.sin(ALPHA) * math.tan(ALPHA) * 2 * 150e9 * 1e-3 / (18e3 * 3.0)
    assert bars.capacity.stiffness == pytest.approx(k, rel=1e-9)
    assert k == pytest.approx(95.467, abs=1e-3)
    theta_max = 2 * math.asin(0.5 * 0.013 * 3.0 / (2 * B))
    d_rupture = R * (math.sin(ALPHA) - math.sin(ALPHA - theta_max))
    assert d_rupture == pytest.approx(0.074277, abs=2e-6)
    assert bars.capacity.d0 == pytest.approx(B / 2)
    assert bars.capacity.rupture_limit == pytest.approx(d_rupture, rel=1e-9)
    assert bars.slv.d_limit == pytest.approx(d_rupture, rel=1e-9)
    a_lim = (
        (math.sin(ALPHA - theta_max) + k * math.sin(theta_max))
        / math.cos(ALPHA - theta_max)
        * G
        / FC
    )
    assert bars.slv.a_limit == pytest.approx(a_lim, rel=1e-9)
    period = 1.68 * math.pi * math.sqrt(d_rupture / a_lim)
    assert period == pytest.approx(0.2434, abs=1e-4)
    assert 0.15 < period < T_C
    assert bars.slv.period == pytest.approx(period, rel=1e-9)
    demand = AGS * _eta(0.08) * 2.5 * period**2 * G / (4 * math.pi**2)
    assert bars.slv.demand == pytest.approx(demand, rel=1e-6)
    assert bars.slv.a_g_capacity == pytest.approx(AGS * d_rupture / demand, rel=1e-6)
    assert bars.slv.passed and bars.slv.zeta_e > 3 * checks.cases[0].slv.zeta_e
    assert bars.linear == checks.cases[0].linear


def test_checks_round_trip_through_json():
    """results.json holds the checks as plain JSON (no infinity) and reads them back."""
    checks = kinematic_checks(_inputs(), ida={"Unreinforced": IdaSummary(0.3, 0.2, 7)})
    text = to_json(checks)  # the writer of results.json (refuses NaN and infinity)
    assert from_data(KinematicChecks, json.loads(text)) == checks
    assert checks.cases[0].ida is not None and checks.cases[1].ida is None


# --- the wall above ground -----------------------------------------------------------------


def test_wall_above_ground_uses_the_floor_spectrum():
    """Z = 6 m in a 3-storey building 9 m tall: T1 = 0.05·9^0.75 = 0.259808 s (on the
    plateau: Se(T1, 5 %) = 2.5·0.25 = 0.625 g), γ1 = 9/7, ψ1 = 2/3,
    a_Z,1 = 0.625·(9/7)·(2/3)·√(1 + 0.0004·5²) = 0.538386 g (eq. C7.2.7): the linear demand
    is a_Z/q and a_g,SLD = a0*/(a_Z/a_g·S).  For T_SLV far beyond b·T1 the floor spectrum is
    A·a_Z/[1 + (A − 1)·(T/(b·T1) − 1)^1.2], A = 1.1·0.05^-0.5·η(8 %), not below the ground
    spectrum; the displacement demand is at least its S_De at T_SLV.  Z = 0 is ground level.
    """
    floor = FloorPosition(height=9.0, storeys=3, wall_base=6.0)
    checks = kinematic_checks(_inputs(), building=floor)
    t1 = 0.05 * 9.0**0.75
    assert t1 == pytest.approx(0.259808, abs=1e-6)
    a_z = 0.625 * (9 / 7) * (2 / 3) * math.sqrt(1.01)
    assert a_z == pytest.approx(0.538386, abs=1e-6)
    assert checks.floor is not None
    assert checks.floor.period == pytest.approx(t1)
    assert checks.floor.floor_ratio == pytest.approx(a_z / AGS, rel=1e-9)
    urm = checks.cases[0]
    assert urm.linear.demand == pytest.approx(a_z / 2.0, rel=1e-9)
    assert urm.slv.a_g_sld == pytest.approx(math.tan(ALPHA) / FC * AGS / a_z, rel=1e-9)
    T = urm.slv.period
    amp = 1.1 / math.sqrt(0.05) * _eta(0.08)
    sez = amp * a_z / (1 + (amp - 1) * (T / (1.1 * t1) - 1) ** 1.2)
    ground = AGS * _eta(0.08) * 2.5 * T_C * T_D / T**2
    at_t = max(sez, ground) * G * T**2 / (4 * math.pi**2)
    assert urm.slv.demand >= at_t * (1 - 1e-9)
    # at ground level (Z = 0) the checks are the ground's
    ground_level = kinematic_checks(_inputs(), building=FloorPosition(9.0, 3, 0.0))
    assert ground_level.floor is None
    assert ground_level.cases == kinematic_checks(_inputs()).cases


def test_ground_displacement_spectrum_is_the_code_shape():
    """S_De(2 s, 8 %) beyond T_D = 0.25·η·2.5·0.5·1.5·g/4π²; at 1 s, 0.25·η·2.5·0.5·1·g/4π²."""
    sd = displacement_spectrum(SPECTRUM, None)
    k = AGS * _eta(0.08) * 2.5 * T_C * G / (4 * math.pi**2)
    assert sd(2.0, 0.08) == pytest.approx(k * T_D, rel=1e-12)
    assert sd(1.0, 0.08) == pytest.approx(k * 1.0, rel=1e-12)


# --- the time-history check (Circolare 2019 §C8.7.1.2.1.9) ------------------------------------


@dataclass
class _Result:
    max_rotation: float
    collapsed: bool


@dataclass
class _StubModel:
    """A model whose runs give set peak rotations: the check's logic, independent of the
    integrator.  It records the scale it was run at."""

    wall: Wall
    peaks: list[float]
    rebars: None = None

    def __post_init__(self) -> None:
        self.scales: list[float] = []

    K: float = 0.0
    theta_max: float = math.inf
    loads: Loads = NO_LOADS  # free-standing (docs/model.md §12)

    @property
    def alpha(self) -> float:
        """The edge pivot: the model's slenderness is the wall's."""
        return self.wall.alpha

    @property
    def a_rm_g(self) -> float:
        return math.tan(self.wall.alpha)

    def run(self, acc: object, dt: float, scale: float = 1.0) -> _Result:
        self.scales.append(scale)
        theta = self.peaks[len(self.scales) - 1]
        return _Result(theta, math.isinf(theta))


WALL = Wall(B, 3.0, 18e3)
MOTIONS = [(np.zeros(4), 0.01)] * 3


def _d(theta: float) -> float:
    return R * (math.sin(ALPHA) - math.sin(ALPHA - theta))


def test_time_history_check_mean_peak_against_d_slv_and_fc_scale():
    """Peaks θ = 0.01, 0.05, 0.09 rad: d = R·[sin α − sin(α − θ)] = 0.015010, 0.075216,
    0.135617 m; all below d0 = 0.197479 m; mean 0.075281 m ≤ d_SLV = 0.078991 m: passes.
    With FC in the dynamics the records are run at FC = 1.35×."""
    model = _StubModel(WALL, [0.01, 0.05, 0.09])
    out = case_checks(
        "stub",
        model,  # type: ignore[arg-type]
        a_g=AGS,
        sd=displacement_spectrum(SPECTRUM, None),
        settings=CodeCheckSettings(),
        motions=MOTIONS,
    )
    th = out.time_history
    assert th is not None
    assert model.scales == [FC] * 3 and th.scale == FC
    expected = [_d(0.01), _d(0.05), _d(0.09)]
    assert expected == pytest.approx([0.015010, 0.075216, 0.135617], abs=2e-6)
    assert list(th.peaks) == pytest.approx(expected, rel=1e-12)
    assert th.mean_peak == pytest.approx(sum(expected) / 3, rel=1e-12)
    assert th.d_limit == pytest.approx(0.4 * B / 2)
    assert th.d0_respected and th.mean_respected and th.passed
    assert th.ratio == pytest.approx(0.4 * B / 2 / (sum(expected) / 3), rel=1e-12)


def test_time_history_check_fails_on_d0_or_on_the_mean():
    """θ = 0.14 rad > α = 0.130900: d = 0.211247 m > d0, fails although the mean is small;
    θ = 0.08 rad three times: mean 0.120504 m > d_SLV with d0 kept: fails on the mean;
    a fall: peak None, ratio 0.  fc_in_ida off: the records are run at 1×."""
    sd = displacement_spectrum(SPECTRUM, None)
    off = CodeCheckSettings(fc_in_ida=False)
    past = _StubModel(WALL, [0.0, 0.0, 0.14])
    th = case_checks("a", past, a_g=AGS, sd=sd, settings=off, motions=MOTIONS).time_history  # type: ignore[arg-type]
    assert th is not None and past.scales == [1.0] * 3
    assert _d(0.14) == pytest.approx(0.211247, abs=2e-6)
    assert not th.d0_respected and th.mean_respected and not th.passed
    many = _StubModel(WALL, [0.08] * 3)
    th = case_checks("b", many, a_g=AGS, sd=sd, settings=off, motions=MOTIONS).time_history  # type: ignore[arg-type]
    assert th is not None and th.mean_peak == pytest.approx(0.120504, abs=2e-6)
    assert th.d0_respected and not th.mean_respected and not th.passed
    fell = _StubModel(WALL, [0.01, math.inf, 0.01])
    th = case_checks("c", fell, a_g=AGS, sd=sd, settings=off, motions=MOTIONS).time_history  # type: ignore[arg-type]
    assert th is not None and th.peaks[1] is None and th.mean_peak is None
    assert th.ratio == 0.0 and not th.passed


def test_peak_displacements_of_the_real_model():
    """A constant base acceleration below g·tan α does not lift the wall (d = 0); 3·g·tan α
    held for 3 s overturns it (Housner 1963: a step above the static threshold topples a
    rigid block once it lasts long enough), the peak is inf."""
    model = RockingModel(WALL, "one-sided")
    quiet = np.full(200, -0.9 * G * math.tan(ALPHA))
    strong = np.full(300, -3.0 * G * math.tan(ALPHA))
    peaks = peak_displacements(model, [(quiet, 0.01), (strong, 0.01)])
    assert peaks[0] == 0.0
    assert peaks[1] == math.inf


def test_checks_use_the_models_slenderness_and_stiffness():
    """The code checks use the model the IDA runs.  With the crushing pivot the model's
    restoring moment vanishes at α' = atan((B − x)/H) (x = N/(0.85·f_d)): α0 of the linear
    check is tan α' = (B − x)/H (not B/H), d0 = d_C(α') = R·[sin α − sin(α − α')] of the block
    turning about its corner (< B/2), and the capacity curve carries the model's K'."""
    wall = Wall(WALL.thickness, WALL.height, WALL.unit_weight, compressive_strength=0.5e6)
    model = RockingModel(wall, "one-sided", None, ModelOptions(pivot="crushing"))
    x = WALL.unit_weight * WALL.thickness * WALL.height / (0.85 * 0.5e6)  # N/(0.85·f_d) [m]
    assert model.alpha == pytest.approx(math.atan((WALL.thickness - x) / WALL.height))
    assert model.alpha < wall.alpha - 1e-3  # the pivot did move: the test can tell
    curve = model_capacity_curve(model, FC)
    assert curve.d0 == pytest.approx(R * (math.sin(ALPHA) - math.sin(ALPHA - model.alpha)))
    assert curve.d0 < WALL.thickness / 2 - 1e-4
    assert curve.a0 == pytest.approx((WALL.thickness - x) / WALL.height * G / FC, rel=1e-9)
    lin = linear_check(model, AGS, "LC1", 2.0)
    assert lin.alpha0 == pytest.approx((WALL.thickness - x) / WALL.height, rel=1e-9)
    bars = RockingModel(wall, "one-sided", Rebars(46e9, 0.015, "centred", 1.0), model.options)
    curve_b = model_capacity_curve(bars, FC)
    assert curve_b.stiffness == pytest.approx(bars.K) and bars.K > 0.0
    assert curve_b.d0 == pytest.approx(
        R * (math.sin(ALPHA) - math.sin(ALPHA - bars.alpha)), rel=1e-12
    )


def test_records_are_scaled_to_the_design_pga_before_the_time_histories():
    """Each ground record is scaled to PGA = a_g·S: a 0.2 g step and a 0.4 g sine both become
    0.25 g.  With a_g·S = 0.05 g and FC = 1.35 the base never exceeds 0.0675 g < g·tan α =
    0.1317 g (the uplift threshold of Eq. 10 at rest), so no record rocks: every peak is 0 and
    the check passes (ratio None: no displacement to compare with)."""
    t = np.arange(400) * 0.01
    step = Record("step", 0.01, np.full(400, 0.2 * G))
    sine = Record("sine", 0.01, 0.4 * G * np.sin(2 * math.pi * t))
    motions = base_motions([step, sine], None, AGS)
    np.testing.assert_allclose(motions[0][0], np.full(400, AGS * G), rtol=1e-12)
    np.testing.assert_allclose(motions[1][0], AGS * G * np.sin(2 * math.pi * t), rtol=1e-12)
    low = ElasticSpectrum("low", "ec8", 0.05, 0.15, T_C, T_D)
    checks = kinematic_checks(_inputs(options=(), spectrum=low), records=[step, sine])
    th = checks.cases[0].time_history
    assert th is not None and th.scale == FC and th.peaks == (0.0, 0.0)
    assert th.passed and th.ratio is None
    with pytest.raises(ValueError, match="zero PGA"):
        base_motions([Record("zero", 0.01, np.zeros(10))], None, AGS)


# --- FC in the IDA verdict ---------------------------------------------------------------------


def test_fc_enters_the_ida_verdict():
    """capacity/demand = a_dyn/(FC·a_g·S): 0.25/(1.35·0.2) = 0.925926 fails where 0.25/0.2 =
    1.25 passed; FC = 1.35 (LC1) by default, 1.20 (LC2), 1.00 (LC3), 1 when turned off."""
    assert ida_confidence_factor(CodeCheckSettings()) == 1.35
    assert ida_confidence_factor(CodeCheckSettings("LC2")) == 1.20
    assert ida_confidence_factor(CodeCheckSettings("LC3")) == 1.00
    assert ida_confidence_factor(CodeCheckSettings(fc_in_ida=False)) == 1.0
    assert ida_capacity_demand(0.25, 0.2, 1.35) == pytest.approx(0.925926, abs=1e-6)
    assert ida_capacity_demand(0.25, 0.2, 1.0) == pytest.approx(1.25)
    with pytest.raises(ValueError):
        ida_capacity_demand(0.25, 0.0, 1.35)


def test_ida_check_design_value_is_the_mean_from_seven_records():
    """7 records: the mean decides, 0.30/(1.35·0.2) = 1.111111 passes although the least
    favourable 0.20/(1.35·0.2) = 0.740741 does not; 5 records: the least decides, fails."""
    seven = ida_check(IdaSummary(0.30, 0.20, 7), 0.2, 1.35)
    assert seven.zeta_e_mean == pytest.approx(1.111111, abs=1e-6)
    assert seven.zeta_e_least == pytest.approx(0.740741, abs=1e-6)
    assert seven.design_value == "mean" and seven.passed
    five = ida_check(IdaSummary(0.30, 0.20, 5), 0.2, 1.35)
    assert five.design_value == "least" and five.zeta_e == five.zeta_e_least
    assert not five.passed


def test_fc_in_ida_is_read_from_the_project(tmp_path: Path):
    """code_check.fc_in_ida defaults to true and can be turned off in the project file."""
    src = Path(__file__).parents[2] / "projects" / "paper-case.yaml"
    text = src.read_text(encoding="utf-8")
    assert "code_check" not in text
    default = tmp_path / "default.yaml"
    default.write_text(text, encoding="utf-8")
    assert load_inputs(default, warn=None).code_check.fc_in_ida is True
    off = tmp_path / "off.yaml"
    off.write_text(text + "\ncode_check: {knowledge_level: LC1, fc_in_ida: false}\n", "utf-8")
    inputs = load_inputs(off, warn=None)
    assert inputs.code_check.fc_in_ida is False
    assert ida_confidence_factor(inputs.code_check) == 1.0


def test_base_motion_above_ground_is_the_floor_filter():
    """A constant ground acceleration a (the record's PGA: scaled by 1) switched on at t = 0
    under an undamped oscillator (T1, ξ1 = 0) starting at rest: u = −(a/ω²)(1 − cos ωt), so
    ü_rel = −a − ω²·u = −a·cos ωt and the floor's absolute acceleration is
    a·(1 − γ1·ψ1·cos ωt) (closed form), γ1 = 3·3/7 = 9/7, ψ1 = 6/9.  Z = 0: the record."""
    dt, a = 0.005, 1.0
    record = Record("step", dt, np.full(801, a))
    floor = FloorPosition(height=9.0, storeys=3, wall_base=6.0, period=0.4, damping=0.0)
    ((acc, step),) = base_motions([record], floor, a / G)
    t = np.arange(801) * dt
    expected = a * (1.0 - (9 / 7) * (2 / 3) * np.cos(2 * math.pi / 0.4 * t))
    assert step == dt
    np.testing.assert_allclose(acc, expected, atol=1e-9)
    ((ground, _),) = base_motions([record], FloorPosition(9.0, 3, 0.0), a / G)
    np.testing.assert_array_equal(ground, record.acc)
