"""Where the scatter of the effective collapse intensity comes from, and sampling designs that
put the time histories where the collapse windows are (docs/model.md §11.2; issue 38).

    PYTHONPATH=. python3 benchmarks/effective_sampling_designs.py [--jobs N] [--no-records]

The seven cases of benchmarks/effective_sampling.py.  Every design is driven from Python here,
one compiled time history per call (:class:`Runner`: the product's compiled sampling given a
one-point ladder, so each outcome is the product's, bit for bit); the first design is the
product's default before 2026-11-28 (the plain ladder, ``ida(..., coarse=1)``), the "(e) …
from 1.35 below" one its default since; the script checks that both return the product's
capacities to 1e-12 before it measures anything (``--check-only``: on every case, and stop).

1. Per record of the two slender two-sided walls (projects/boundary-wall-records.yaml, where
   §11 (i) fails): a scan at 0.1 % (ladder 1.001, nothing refined, to a collapsed band of 2):
   the lowest collapse, the highest C at which the wall still stands, the collapse windows at
   that resolution, the capacity; and the default's capacity at each of the eight shifts (its
   standard deviation, and the record's share of the case mean's variance).
2. Designs, each at eight shifts (offset 0, 1/8, …, 7/8) and twice as fine (every ratio → its
   square root, tolerance / 2): the scatter (standard deviation of the case mean over its mean,
   §11 (i) ≤ 1.5 %), the drift (< 1 %) and the time histories per record (iii).

Output on stdout; the run of 2026-11-28 is kept beside this file
(effective_sampling_designs.txt).
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from effective_sampling import (  # noqa: E402
    OFFSETS,
    Case,
    corpus_cases,
    print_summary,
    project_cases,
    shift_statistics,
)

from frp_assess.dynamics import IdaSettings, RockingModel, ida  # noqa: E402
from frp_assess.dynamics.effective import EARLY_STOP_BAND, effective_capacity  # noqa: E402
from frp_assess.dynamics.ida import _COLLAPSE_FATE  # noqa: E402
from frp_assess.dynamics.ida_search import sample  # noqa: E402
from frp_assess.dynamics.kernel.params import STATUS_OK, kernel_record  # noqa: E402

GOLDEN = 0.6180339887498949  #: the per-record shift of design (c): frac(offset + i·φ⁻¹)
C_MAX = 100.0  #: C_max/C₀, the product's default


class Runner:
    """Whether the wall falls under the record scaled to C₀·e^x: one time history, run by the
    product's compiled sampling (:func:`~frp_assess.dynamics.ida_search.sample`) on a one-point
    ladder starting at that point (nothing to bisect); counts the time histories."""

    def __init__(self, model: RockingModel, acc: np.ndarray, dt: float) -> None:
        self.acc = kernel_record(acc)
        self.dt, self.model = float(dt), model
        self.c0 = model.a_rm / float(np.max(np.abs(self.acc)))
        self.runs = 0
        self._out = (np.empty(2), np.empty(2, np.int64), np.empty(2), np.empty(2, np.int64))

    def __call__(self, x: float) -> bool:
        c = self.c0 * math.exp(x)
        m, f, p, r = self._out
        n, status = sample(
            self.acc, self.dt, self.model.tail_samples(self.dt), self.model.params,
            np.array([c]), c, 0.1, math.inf, 1, 1, 0, -1, False, m, f, p, r, _COLLAPSE_FATE,
        )  # fmt: skip
        if n != 1 or status != STATUS_OK:
            raise RuntimeError(f"time history at C = {c} gave status {status}")
        self.runs += 1
        return bool(_COLLAPSE_FATE[f[0]])


Samples = list[tuple[float, bool]]  #: (x = ln C/C₀, collapsed)


def bisect(run: Runner, out: Samples, xa: float, fa: bool, xb: float, tol: float) -> None:
    """The product's bisection of a change of outcome (in C) until (C_hi − C_lo) ≤ tol·C_hi."""
    lo, hi = xa, xb
    while math.exp(hi) - math.exp(lo) > tol * math.exp(hi):
        m = math.log(0.5 * (math.exp(lo) + math.exp(hi)))
        f = run(m)
        out.append((m, f))
        lo, hi = (m, hi) if f == fa else (lo, m)


@dataclass(frozen=True)
class Design:
    """A sampling: ``kind`` ``ladder`` (the product's: C₀·r^(k+offset) in order, every change
    of outcome bisected to ``tol`` unless tol ≥ 0.1, early stop at ``band``) or ``adapt``
    (below); ``decorrelate``: record i shifted by frac(offset + i·φ⁻¹) (design (c))."""

    name: str
    ratio: float  #: the ladder's r, or adapt's fine ratio
    tol: float = 0.005
    band: float = EARLY_STOP_BAND
    kind: str = "ladder"
    coarse: int = 1  #: adapt: the coarse step in fine steps (a power of 2)
    settle: int = 3  #: adapt: agreeing samples in a row before the step doubles (0: never)
    decorrelate: bool = False
    coarse_standing: bool = True  #: adapt: False: only collapsed stretches are walked coarse
    margin: float = 0.0  #: adapt: the first collapse's fine walk starts this ratio below it

    def finer(self) -> Design:
        return replace(self, ratio=math.sqrt(self.ratio), tol=min(self.tol / 2, 0.1))


def ladder_design(run: Runner, d: Design, off: float) -> Samples:
    """The product's plain ladder (dynamics/ida_search.next_sample, subdivide 1; ``coarse=1``)."""
    h, out = math.log(d.ratio), []
    prev_x, prev_f, band_start, k = 0.0, False, math.nan, 0
    while (x := (k + off) * h) <= math.log(C_MAX) + 1e-12:
        f = run(x)
        out.append((x, f))
        if f != prev_f and d.tol < 0.1:
            bisect(run, out, prev_x, prev_f, x, d.tol)
        prev_x, prev_f = x, f
        band_start = math.nan if not f else (x if math.isnan(band_start) else band_start)
        if not math.isnan(band_start) and x - band_start >= math.log(d.band) - 1e-12:
            break
        k += 1
    return out


def adapt_design(run: Runner, d: Design, off: float) -> Samples:
    """Designs (a), (b), (d), (e): the fine ladder x_j = (j + offset)·ln r, walked with a step
    of ``coarse`` fine steps where the outcome does not change.  A change of outcome across a
    coarse step walks that step's interior at the fine density (the first collapse: from
    ``margin`` below it, if > 1), the step drops to one fine step and doubles after ``settle``
    agreeing samples in a row (settle 0: never, design (a): a coarse ladder to the first
    collapse, the fine ladder from there on); with ``coarse_standing`` False only a run of
    collapses is walked coarse (design (d): the fine ladder from C₀; design (e), with a margin:
    the coarse ladder to the first collapse, the fine ladder from ``margin`` below it).  A change
    that follows ``settle`` (0: 3) agreeing samples is bisected to ``tol`` (the response's
    isolated edges: a monotone record's threshold); the others take the midpoint rule.  Early
    stop as the product's."""
    h = math.log(d.ratio)
    seen: dict[int, bool] = {}

    def at(j: int) -> bool:
        if j not in seen:
            seen[j] = run((j + off) * h)
        return seen[j]

    j, agree, prev_f = 0, 0, False
    step = d.coarse if d.coarse_standing or d.margin > 1.0 else 1
    while (j + off) * h <= math.log(C_MAX) + 1e-12:
        f = at(j)
        if f != prev_f and step > 1:
            first = not any(seen.values()) or (f and sum(seen.values()) == 1)
            below = math.ceil(math.log(d.margin) / h) if first and d.margin > 1.0 else step - 1
            for i in range(max(0, j - below), j):
                at(i)
            step, agree = 1, 0
        elif f == prev_f:
            agree += 1
            if d.settle and agree >= d.settle and step < d.coarse and (f or d.coarse_standing):
                step, agree = step * 2, 0
        else:
            agree = 0
        prev_f = f
        # the early stop: collapsed at every sample since band_start
        done = sorted(seen)
        i = len(done) - 1
        while i > 0 and seen[done[i - 1]]:
            i -= 1
        if f and (j - done[i]) * h >= math.log(d.band) - 1e-12:
            break
        j += step
    out = [((i + off) * h, seen[i]) for i in sorted(seen)]
    if d.tol < 0.1:
        run_len, walk = 0, [(0.0, False), *out] if off > 0 else list(out)
        for (xa, fa), (xb, fb) in zip(walk, walk[1:], strict=False):
            if fa != fb and run_len >= (d.settle or 3) and xb - xa <= h * 1.0001:
                bisect(run, out, xa, fa, xb, d.tol)
            run_len = run_len + 1 if fa == fb else 0
    return out


def capacity_of(samples: Samples) -> float:
    """a_c/C₀ of the samples (the product's midpoint rule)."""
    return effective_capacity([(math.exp(x), f) for x, f in samples], 1.0, C_MAX).multiplier


DRIVERS: dict[str, Callable[[Runner, Design, float], Samples]] = {
    "ladder": ladder_design,
    "adapt": adapt_design,
}

DESIGNS = (
    Design("default: ladder 1.05, bisect 0.5 %, band 1.5", 1.05),
    Design("(c) default, per-record offsets frac(o + i·0.618)", 1.05, decorrelate=True),
    Design("ladder 1.025, bisect 0.5 %, band 1.5", 1.025),
    Design("ladder 1.025, midpoint only, band 1.5", 1.025, tol=0.1),
    Design("ladder 1.018, midpoint only, band 1.5", 1.018, tol=0.1),
    Design("ladder 1.0125, midpoint only, band 1.5", 1.0125, tol=0.1),
    Design("(a) coarse 1.104 to the first collapse, then 1.0125", 1.0125, kind="adapt",
           coarse=8, settle=0),
    Design("(b) adapt 1.0125 / 1.051 (settle 3)", 1.0125, kind="adapt", coarse=4),
    Design("(b) adapt 1.0125 / 1.051 (settle 6)", 1.0125, kind="adapt", coarse=4, settle=6),
    Design("(b) adapt 1.0125 / 1.104 (settle 3)", 1.0125, kind="adapt", coarse=8),
    Design("(b) adapt 1.015 / 1.126 (settle 3)", 1.015, kind="adapt", coarse=8),
    Design("(d) 1.0125 from C0, collapsed runs walked up to 1.104", 1.0125,
           kind="adapt", coarse=8, coarse_standing=False),
    Design("(e) coarse 1.104, 1.0125 from 1.5 below", 1.0125,
           kind="adapt", coarse=8, coarse_standing=False, margin=1.5),
    Design("(e) coarse 1.104, 1.0125 from 1.5 below, band 1.25", 1.0125, band=1.25,
           kind="adapt", coarse=8, coarse_standing=False, margin=1.5),
    Design("(e) coarse 1.104, 1.0125 from 1.35 below", 1.0125,
           kind="adapt", coarse=8, coarse_standing=False, margin=1.35),
    Design("(e) coarse 1.104, 1.0125 from 1.35 below, no early stop (ii)", 1.0125,
           band=math.inf, kind="adapt", coarse=8, coarse_standing=False, margin=1.35),
    Design("(e) coarse 1.104, 1.0125 from 1.25 below", 1.0125,
           kind="adapt", coarse=8, coarse_standing=False, margin=1.25),
    Design("(e) coarse 1.22, 1.0125 from 1.5 below, band 1.25", 1.0125, band=1.25,
           kind="adapt", coarse=16, coarse_standing=False, margin=1.5),
)  # fmt: skip


def one(
    model: RockingModel, acc: np.ndarray, dt: float, d: Design, off: float
) -> tuple[float, int]:
    run = Runner(model, acc, dt)
    return capacity_of(DRIVERS[d.kind](run, d, off)), run.runs


def measure(case: Case, d: Design, pool: ThreadPoolExecutor) -> tuple[list[list[float]], float]:
    """a_c/C₀ of every record (rows) at every shift (columns), and time histories per record."""
    jobs = [
        [
            pool.submit(
                one, case.model, acc, dt, d, (off + i * GOLDEN) % 1.0 if d.decorrelate else off
            )
            for off in OFFSETS
        ]
        for i, (_, acc, dt) in enumerate(case.records)
    ]
    got = [[j.result() for j in row] for row in jobs]
    runs = statistics.fmean(r for row in got for _, r in row)
    return [[a for a, _ in row] for row in got], runs


def case_means(case: Case, caps: list[list[float]]) -> list[float]:
    """The case mean a_dyn [m/s²] at each shift (a_c = a_c/C₀ · C₀ · PGA = a_c/C₀ · a_RM)."""
    return [statistics.fmean(row[k] for row in caps) * case.model.a_rm for k in range(len(OFFSETS))]


#: The product's default sampling since 2026-11-28 (frp_assess/dynamics/ida_refine.py).
DESIGN_E = next(d for d in DESIGNS if d.name == "(e) coarse 1.104, 1.0125 from 1.35 below")


def check_replica(case: Case, records: int = 3, offsets: tuple[float, ...] = (0.0, 0.375)) -> None:
    """The designs re-implemented here return the product's capacities to 1e-12: the plain
    ladder 1.05 (the product's ``coarse=1``, its default before 2026-11-28) and (e) (today's
    default, ``capacity: effective`` with nothing else set)."""
    plain = IdaSettings(capacity="effective", ladder_ratio=DESIGNS[0].ratio)
    for i, (_, acc, dt) in enumerate(case.records[:records]):
        for off in offsets:
            for d, st, coarse in (
                (DESIGNS[0], replace(plain, offset=off), 1),
                (DESIGN_E, IdaSettings(capacity="effective", offset=off), 8),
            ):
                mine, _ = one(case.model, acc, dt, d, off)
                res = ida(case.model, acc, dt, st, coarse=coarse)
                theirs = res.capacity_multiplier / res.c0
                if abs(mine / theirs - 1.0) > 1e-12:
                    raise SystemExit(
                        f"{case.name} record {i} offset {off}: {d.name} gives {mine!r}, the "
                        f"product {theirs!r}"
                    )
                print(f"  replica {case.name[:30]} record {i} offset {off:5.3f} {d.name[:20]}: "
                      f"{mine:.15f} = {theirs:.15f}")  # fmt: skip


def per_record(case: Case, pool: ThreadPoolExecutor) -> None:
    fine = IdaSettings(ladder_ratio=1.001, tolerance=0.1, capacity="effective")
    scans = [
        pool.submit(ida, case.model, acc, dt, fine, band=2.0, coarse=1)
        for _, acc, dt in case.records
    ]
    caps, _ = measure(case, DESIGNS[0], pool)
    var_case = statistics.pvariance([statistics.fmean(c) for c in zip(*caps, strict=True)])
    print(f"\n{case.name}: per record (0.1 % scan; the default at 8 shifts)")
    for (name, _, _), job, row in zip(case.records, scans, caps, strict=True):
        r = job.result()
        fell = [p.multiplier / r.c0 for p in r.curve if p.collapsed]
        stood = [p.multiplier / r.c0 for p in r.curve if not p.collapsed]
        windows, prev = 0, False
        for p in r.curve:
            windows += p.collapsed and not prev
            prev = p.collapsed
        share = statistics.pvariance(row) / len(caps) ** 2 / var_case
        print(
            f"  {name[:10]:<10} C0 {r.c0:5.3f}  a_c/C0 {r.capacity_multiplier / r.c0:5.3f}  "
            f"lowest collapse {min(fell):5.3f}  highest standing {max(stood):5.3f}  windows "
            f"{windows:3d} ({r.windows_below:3d} below a_c)  default: mean "
            f"{statistics.fmean(row):5.3f}"
            f" std {100 * statistics.pstdev(row) / statistics.fmean(row):5.2f} %  "
            f"min {min(row):5.3f} max {max(row):5.3f}  share of the case variance {share:4.2f}"
        )
    means = [statistics.fmean(c) for c in zip(*caps, strict=True)]
    print(
        "  case mean a_c/C0 at the 8 shifts: "
        + " ".join(f"{m:5.3f}" for m in means)
        + f"; scatter {100 * statistics.pstdev(means) / statistics.fmean(means):4.2f} %"
        "; the records' variances sum to "
        f"{sum(statistics.pvariance(r) for r in caps) / len(caps) ** 2 / var_case:4.2f}"
        " of the case mean's (1: uncorrelated records)"
    )


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-records", action="store_true", help="skip the per-record part")
    ap.add_argument(
        "--check-only", action="store_true", help="only check the replicas against the product"
    )
    ap.add_argument(
        "--only", default="", help="the designs whose name contains one of these texts (a|b)"
    )
    args = ap.parse_args()
    cases = project_cases("facade-laquila.yaml", (0, 1, 12))
    cases += project_cases("boundary-wall-records.yaml", (0, 1)) + corpus_cases()
    check_replica(cases[3])
    if args.check_only:
        for case in cases[:3] + cases[4:]:
            check_replica(case, 2, (0.125, 0.625))
        return 0
    designs = [d for d in DESIGNS if any(o in d.name for o in args.only.split("|"))]
    rows: dict[str, list[tuple[float, float, float]]] = {d.name: [] for d in designs}
    with ThreadPoolExecutor(args.jobs) as pool:
        if not args.no_records:
            for case in cases[3:5]:
                per_record(case, pool)
        for case in cases:
            print(f"\n{case.name} ({len(case.records)} records)")
            for d in designs:
                caps, runs = measure(case, d, pool)
                fine_caps, fine_runs = measure(case, d.finer(), pool)
                avg, scatter, drift, fine_scatter = shift_statistics(
                    case_means(case, caps), case_means(case, fine_caps)
                )
                rows[d.name].append((scatter, drift, runs))
                print(
                    f"  {d.name:<52} mean {avg:7.4f}  scatter {100 * scatter:5.2f} %  drift "
                    f"{100 * drift:+6.2f} %  (×2 fine: scatter {100 * fine_scatter:5.2f} %)  "
                    f"{runs:6.1f} runs/record (×2 fine {fine_runs:6.1f})"
                )
    print_summary("over the seven cases", rows, 52)
    return 0


if __name__ == "__main__":
    sys.exit(main())
