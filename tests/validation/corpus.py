"""The convergence corpus of docs/model.md §4: broadband records and the walls they shake.

Records: SIMQKE sets (frp_assess.motions.generate_artificial) for the paper's presets A1–A3
and an EC8 type-1 ground-C spectrum, several seeds, at dt = 0.005 and 0.01 s (28 records),
plus the bundled example records under projects/records (10 records).  Walls: unreinforced
one- and two-sided walls at α = 5°, 7.5°, 10° and H = 3, 6 m, and GFRP/CFRP bars, centred
and external, on a 3 m wall at α = 7.5°, one- and two-sided; and the same 3 m wall with the
base reaction of docs/model.md §1.1 (f_d = 1 MPa: x_W = 18 mm of B = 395 mm), unreinforced and
with bars whose toe crushes before they break.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from frp_assess.dynamics import ModelOptions, Rebars, RockingModel, Wall
from frp_assess.motions import generate_artificial, parse_spectrum, read_record

ROOT = Path(__file__).resolve().parents[2]
UNIT_WEIGHT = 18e3  # N/m³

#: (spectrum, seed, dt [s], count): 4 + 4 + 4 + 4 + 4 + 4 + 4 = 28 SIMQKE records
SIMQKE_SETS: tuple[tuple[str, int, float, int], ...] = (
    ("A1", 3, 0.005, 4),
    ("A2", 1, 0.005, 4),
    ("A2", 5, 0.01, 4),
    ("A3", 7, 0.005, 4),
    ("A3", 2, 0.01, 4),
    ("ec8:type=1,ground=C,ag=0.25", 4, 0.01, 4),
    ("ec8:type=1,ground=C,ag=0.25", 9, 0.005, 4),
)


@dataclass(frozen=True)
class CorpusRecord:
    name: str
    acc: np.ndarray  #: [m/s²]
    dt: float  #: [s]


@cache
def records() -> tuple[CorpusRecord, ...]:
    """Every record of the corpus, in a fixed order."""
    out: list[CorpusRecord] = []
    for spec, seed, dt, count in SIMQKE_SETS:
        for rec in generate_artificial(parse_spectrum(spec), count=count, seed=seed, dt=dt):
            out.append(CorpusRecord(f"{spec} seed {seed} dt {dt} {rec.name}", rec.acc, rec.dt))
    for path in sorted((ROOT / "projects" / "records").rglob("*.AT2")):
        rec = read_record(path)
        out.append(CorpusRecord(f"bundled {path.name}", rec.acc, rec.dt))
    return tuple(out)


def unreinforced_walls() -> list[tuple[str, RockingModel]]:
    out = []
    for mechanism in ("one-sided", "two-sided"):
        for alpha_deg in (5.0, 7.5, 10.0):
            for height in (3.0, 6.0):
                wall = Wall.from_slenderness(height, math.radians(alpha_deg), UNIT_WEIGHT)
                out.append(
                    (f"URM {mechanism} a={alpha_deg:g} H={height:g}", RockingModel(wall, mechanism))
                )
    return out


def reinforced_walls() -> list[tuple[str, RockingModel]]:
    wall = Wall.from_slenderness(3.0, math.radians(7.5), UNIT_WEIGHT)
    materials = {"GFRP": (46e9, 0.015, 2.0), "CFRP": (150e9, 0.013, 1.0)}
    out = []
    for mechanism in ("one-sided", "two-sided"):
        for label, (e, eps, rho) in materials.items():
            for position in ("centred", "external"):
                bars = Rebars(e, eps, position, rho)  # type: ignore[arg-type]
                out.append(
                    (
                        f"{label} {position} {rho:g}‰ {mechanism}",
                        RockingModel(wall, mechanism, bars),
                    )
                )
    return out


def base_reaction_walls() -> list[tuple[str, RockingModel]]:
    """The 3 m wall at α = 7.5° with f_d = 1 MPa and ``pivot: crushing``."""
    ref = Wall.from_slenderness(3.0, math.radians(7.5), UNIT_WEIGHT)
    wall = Wall(ref.thickness, ref.height, UNIT_WEIGHT, 1.0e6)
    opts = ModelOptions(pivot="crushing")
    cases: tuple[tuple[str, str, Rebars | None], ...] = (
        ("URM two-sided f_d=1MPa", "two-sided", None),
        ("GFRP centred 2‰ one-sided f_d=1MPa", "one-sided", Rebars(46e9, 0.015, "centred", 2.0)),
        (
            "CFRP external 1‰ two-sided f_d=1MPa",
            "two-sided",
            Rebars(150e9, 0.013, "external", 1.0),
        ),
    )
    return [(n, RockingModel(wall, mech, bars, opts)) for n, mech, bars in cases]  # type: ignore[arg-type]


def walls() -> list[tuple[str, RockingModel]]:
    return unreinforced_walls() + reinforced_walls() + base_reaction_walls()
