"""Accuracy bar of the integrator on the convergence corpus (docs/model.md §4).

    python3 scripts/validate_accuracy.py [--quick] [--tolerance TOL] [--only TEXT] [--list-curve]

For every wall of tests/validation/corpus.py and every record, the first-collapse multiplier C
(IDA, bisection to 0.1 %) and the peak rotation at 0.5·C and at the IDA's survivor multiplier
are computed four ways: at the tolerance under test (D), at a 100× tighter one (T), with
fixed-step RK4 at h = 0.1 ms (R), and at the tight tolerance with the record multiplied by
(1 + 1e-6) (P).  So are the peaks at every other point of the IDA curve that the three
searches D, T and R ran at the same multiplier without collapse (the hunt's C₀·s^k: the small
rocking of a stiff wall lives there), at no extra cost: those peaks are the searches' own.

Near its collapse boundary a rocking wall can be *ill-conditioned*: it balances close to its
unstable equilibrium and a perturbation of one part in a million of the record (far below the
precision of any accelerogram) changes its fate.  No integrator can do better than the data
there, so a number is judged only where it is well-conditioned, i.e. where P agrees with T
(C within 0.2 %, peaks within 0.1 %); there D must agree with T and with R within the same
bars.  For a multiplier, "well-conditioned" is tested where D and a reference disagree: the
decisive time history (the smallest C where the two searches saw different fates) is rerun
with the record multiplied by 1 ± 1e-6; a changed fate or a rotation history that moves by
more than 1e-2·α (the perturbation amplified 1e4 times) marks the multiplier
ill-conditioned.  A curve peak is likewise tested only where D and a reference disagree by
more than 0.1 %: it is then rerun at the tight tolerance with the record multiplied by
1 ± 1e-6, 1 ± 2e-6 and 1 ± 4e-6, and a change of more than 0.1 % per 1e-6 marks it
ill-conditioned (a small-rocking tail can send the peak to another branch at a few 1e-6 of
the record while ± 1e-6 alone leaves it).  The peak at the survivor
multiplier is reported but not gated (and left out of the curve): it is by construction the
time history closest to the collapse boundary.  The curve peaks are reported and their misses
listed, not yet gated (docs/model.md §4.5: two known misses).  The ill-conditioned cases
are counted and listed, not hidden.  Exit code 1 if any gated,
well-conditioned comparison misses its bar.
"""

from __future__ import annotations

import argparse
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel, default_jobs, ida  # noqa: E402
from frp_assess.dynamics.rocking import DEFAULT_TOLERANCE  # noqa: E402
from tests.validation.corpus import CorpusRecord, records, walls  # noqa: E402

C_BAR = 2e-3  #: relative agreement of collapse multipliers
PEAK_BAR = 1e-3  #: relative agreement of peak rotations
RK4_STEP = 1e-4  #: [s] (0.25 ms is not converged on every corpus record)
PERTURBATION = 1e-6  #: relative change of the record that defines ill-conditioning
#: changes of the record that test a curve peak's conditioning: its change per 1e-6 of them
#: (a peak that a change of a few 1e-6 sends to another branch is not determined by the data
#: either, and ± 1e-6 alone can miss the branch: docs/model.md §4.5)
CURVE_PERTURBATIONS = (1e-6, -1e-6, 2e-6, -2e-6, 4e-6, -4e-6)
#: the first collapse of docs/model.md §5: its bracket is what the bars below are stated for
SETTINGS = IdaSettings(tolerance=1e-3, capacity="first-collapse")


def rel(a: float | None, b: float | None) -> float:
    if a is None or b is None:
        return 0.0 if a == b else float("inf")
    return 0.0 if a == b else abs(a - b) / max(abs(a), abs(b))


@dataclass
class Row:
    quantity: str  #: "C", "peak@0.5C", "peak@survivor", "peak@curve"
    wall: str
    record: str
    vs_tight: float
    vs_rk4: float
    conditioning: float  #: change under the 1e-6 perturbation of the record (tight tolerance)

    @property
    def bar(self) -> float:
        return C_BAR if self.quantity == "C" else PEAK_BAR

    @property
    def well_conditioned(self) -> bool:
        # a decisive time history that a 1e-6 change of the record moves by 1e-2·α (or whose
        # fate it flips) makes the multiplier ill-conditioned
        return self.conditioning <= (1e-2 if self.quantity == "C" else self.bar)

    @property
    def gated(self) -> bool:
        """The peak at the survivor multiplier is reported, not gated: by construction that
        time history is the closest to the collapse boundary the search found.  The other
        curve peaks are reported, not yet gated: two well-conditioned ones of the whole
        corpus miss the bar at the default (docs/model.md §4.5)."""
        return self.quantity not in ("peak@survivor", "peak@curve")

    @property
    def ok(self) -> bool:
        return not self.well_conditioned or max(self.vs_tight, self.vs_rk4) <= self.bar


def fate_sensitivity(
    model: RockingModel, rec: CorpusRecord, tol: float, a: IdaResult, b: IdaResult
) -> float:
    """How much the decisive time history of two disagreeing IDAs depends on the data.

    At the smallest multiplier where the two searches saw different fates, the time history
    is rerun at the tight tolerance with the record multiplied by 1 ± 1e-6.  Returns 1 when
    the fate changes, else the largest change of θ over the common samples, in units of α
    (an amplification of the 1e-6 perturbation by more than 1e4 means ill-conditioned).
    """
    fates = {p.multiplier: p.collapsed for p in a.curve}
    other = {p.multiplier: p.collapsed for p in b.curve}
    loose = model.with_options(tolerance=tol)
    tight = model.with_options(tolerance=tol / 100)
    for c in sorted(set(fates) | set(other)):
        fa = fates[c] if c in fates else loose.run(rec.acc, rec.dt, c).collapsed
        fb = other[c] if c in other else tight.run(rec.acc, rec.dt, c).collapsed
        if fa == fb:
            continue
        ref = tight.run(rec.acc, rec.dt, c, history=True)
        worst = 0.0
        for sign in (1.0, -1.0):
            pert = tight.run(rec.acc * (1.0 + sign * PERTURBATION), rec.dt, c, history=True)
            if pert.collapsed != ref.collapsed:
                return 1.0
            assert pert.history is not None and ref.history is not None
            n = min(pert.history.theta.size, ref.history.theta.size)
            diff = np.max(np.abs(pert.history.theta[:n] - ref.history.theta[:n]))
            worst = max(worst, float(diff) / model.wall.alpha)
        return worst
    return 0.0


def curve_rows(
    name: str, model: RockingModel, rec: CorpusRecord, tol: float, idas: dict[str, IdaResult]
) -> list[Row]:
    """One row per multiplier at which D, T and R all ran and none collapsed (the survivor
    multiplier excepted): the peaks of the three curves compared, and where D misses the bar
    against T or R, the peak's largest change per 1e-6 under the record multiplied by 1 + ε,
    ε in CURVE_PERTURBATIONS, at the tight tolerance (its conditioning; 0 where D agrees, as
    for C)."""
    peaks = {
        k: {p.multiplier: p.peak_ratio for p in r.curve if not p.collapsed} for k, r in idas.items()
    }
    common = set(peaks["D"]) & set(peaks["T"]) & set(peaks["R"])
    survivor = idas["D"].survivor_multiplier
    if survivor is not None:
        common.discard(survivor)
    tight = model.with_options(tolerance=tol / 100)
    rows = []
    for c in sorted(common):
        d, t, r = peaks["D"][c], peaks["T"][c], peaks["R"][c]
        vs_t, vs_r = rel(d, t), rel(d, r)
        conditioning = 0.0
        if max(vs_t, vs_r) > PEAK_BAR:
            for eps in CURVE_PERTURBATIONS:
                pert = tight.run(rec.acc * (1.0 + eps), rec.dt, c)
                moved = 1.0 if pert.collapsed else rel(pert.max_rotation_ratio, t)
                conditioning = max(conditioning, moved * PERTURBATION / abs(eps))
        rows.append(Row("peak@curve", name, f"{rec.name} C={c:.4g}", vs_t, vs_r, conditioning))
    return rows


def compare(name: str, model: RockingModel, rec: CorpusRecord, tol: float) -> list[Row]:
    variants = {
        "D": (model.with_options(tolerance=tol), rec.acc),
        "T": (model.with_options(tolerance=tol / 100), rec.acc),
        "R": (model.with_options(fixed_step=RK4_STEP), rec.acc),
        "P": (model.with_options(tolerance=tol / 100), rec.acc * (1.0 + PERTURBATION)),
    }
    idas = {k: ida(m, acc, rec.dt, SETTINGS) for k, (m, acc) in variants.items() if k != "P"}
    cs = {k: r.collapse_multiplier for k, r in idas.items()}
    conditioning = 0.0
    for ref in ("T", "R"):
        if rel(cs["D"], cs[ref]) > C_BAR:
            conditioning = max(
                conditioning, fate_sensitivity(model, rec, tol, idas["D"], idas[ref])
            )
    rows = [Row("C", name, rec.name, rel(cs["D"], cs["T"]), rel(cs["D"], cs["R"]), conditioning)]
    rows += curve_rows(name, model, rec, tol, idas)
    base = idas["D"]
    c = base.collapse_multiplier or base.survivor_multiplier
    if c is None:
        return rows
    for label, scale in (("0.5C", 0.5 * c), ("survivor", base.survivor_multiplier)):
        if scale is None:
            continue
        peak = {k: m.run(acc, rec.dt, scale).max_rotation for k, (m, acc) in variants.items()}
        rows.append(
            Row(
                f"peak@{label}",
                name,
                rec.name,
                rel(peak["D"], peak["T"]),
                rel(peak["D"], peak["R"]),
                rel(peak["T"], peak["P"]),
            )
        )
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="every 4th record only")
    parser.add_argument("--tolerance", type=float, default=DEFAULT_TOLERANCE)
    parser.add_argument("--only", default="", help="only the walls whose name contains TEXT")
    parser.add_argument(
        "--list-curve", action="store_true", help="list the ill-conditioned curve peaks too"
    )
    args = parser.parse_args()
    recs = records()[:: 4 if args.quick else 1]
    chosen = [(n, m) for n, m in walls() if args.only in n]
    jobs = [(n, m, r) for n, m in chosen for r in recs]
    t0 = time.perf_counter()
    with ThreadPoolExecutor(default_jobs()) as pool:
        rows = [
            row for part in pool.map(lambda j: compare(*j, args.tolerance), jobs) for row in part
        ]
    seconds = time.perf_counter() - t0
    failed = [r for r in rows if r.gated and not r.ok]
    print(
        f"tolerance {args.tolerance:g}: {len(chosen)} walls x {len(recs)} records, {seconds:.0f} s"
    )
    for q in sorted({r.quantity for r in rows}):
        sel = [r for r in rows if r.quantity == q]
        well = [r for r in sel if r.well_conditioned]
        bad = [r for r in well if not r.ok]
        worst_t = max((r.vs_tight for r in well), default=0.0)
        worst_r = max((r.vs_rk4 for r in well), default=0.0)
        print(
            f"{q:14s}{'' if sel[0].gated else ' (not gated)'}: {len(sel):4d} cases, "
            f"{len(sel) - len(well):3d} ill-conditioned; of the "
            f"{len(well)} others {len(bad)} miss {well[0].bar if well else 0:.1%}: worst "
            f"{worst_t:.1e} vs 100x tighter, {worst_r:.1e} vs RK4 {RK4_STEP * 1e3:g} ms"
        )
    for r in rows:
        if not r.ok:
            print(
                f"  {'MISS' if r.gated else 'off (not gated)'} {r.quantity} {r.wall} / "
                f"{r.record}: {r.vs_tight:.2e} vs tight, {r.vs_rk4:.2e} vs RK4"
            )
    for r in rows:
        if not r.well_conditioned and (args.list_curve or r.quantity != "peak@curve"):
            print(f"  ill-conditioned {r.quantity} {r.wall} / {r.record}: {r.conditioning:.2e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
