"""How to sample the effective collapse intensity (docs/model.md §11; issue 38 item 1).

    PYTHONPATH=. python3 benchmarks/effective_sampling.py [--quick] [--jobs N]

Cases: the unreinforced wall and two FRP options of the bundled example
(projects/facade-laquila.yaml, its seven records) and of projects/boundary-wall-records.yaml,
and two walls of the convergence corpus (tests/validation/corpus.py: the two-sided
unreinforced 0.39 × 3 m wall and the same wall with CFRP bars, external 1 ‰) under eight of its
records (four SIMQKE, four bundled).  For each sampling design (ladder ratio r, bisection
tolerance of the transitions, early-stop band; :func:`frp_assess.dynamics.ida`) and each of
eight ladder offsets (0, 1/8, …, 7/8 of a step) it computes every record's effective collapse
intensity and the case mean, and prints per case and design:

* the scatter: the standard deviation of the eight case means over their mean (§11 (i): ≤ 1.5 %);
* the drift: the average of the eight case means with the sampling twice as fine (r → √r,
  tolerance / 2) against the average of the design itself (§11 (i): < 1 %);
* the time histories per record (§11 (iii): the first collapse of §5 at s = 1.10 beside it,
  with its own scatter over the same eight shifts of its hunt's ladder, C₀·s^(k+offset)).

Then a fine scan (uniform ladder r = 1.0125, nothing refined, to the band of 2) of each case
and record: where the collapse windows are (how many, the lowest collapse against the
effective intensity) and the CPU time of one time history.  Output: the tables, on stdout;
the run of 2026-11-28 is kept beside this file (effective_sampling.txt).  Where the scatter
of the slender walls comes from (a scan at 0.1 % per record) and the designs that put the time
histories where the windows are (adaptive, two-level, decorrelated offsets):
benchmarks/effective_sampling_designs.py.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from frp_assess.app.assessment import prepare_records  # noqa: E402
from frp_assess.assess.from_project import load_inputs  # noqa: E402
from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel, ida  # noqa: E402
from tests.validation.corpus import records as corpus_records  # noqa: E402
from tests.validation.corpus import walls as corpus_walls  # noqa: E402

OFFSETS = tuple(k / 8 for k in range(8))
INF = float("inf")


@dataclass(frozen=True)
class Design:
    name: str
    ratio: float
    tolerance: float  #: 0.1 with r ≤ 1.1: no refinement at all
    band: float
    rule: str = "effective"
    subdivide: int = 1  #: a cell whose ends disagree is walked at this many times the density

    def finer(self) -> Design:
        return Design(
            self.name + " ×2 fine", self.ratio**0.5, min(self.tolerance / 2, 0.05), self.band,
            self.rule, self.subdivide,
        )  # fmt: skip


DESIGNS = (
    Design("(§5) first collapse s=1.10", 1.10, 0.005, INF, "first-collapse"),
    Design("(a) ladder 1.10", 1.10, 0.1, 2.0),
    Design("(a) ladder 1.05", 1.05, 0.1, 2.0),
    Design("(a) ladder 1.025", 1.025, 0.1, 2.0),
    Design("(b) 1.10 + bisect 0.5 %", 1.10, 0.005, INF),
    Design("(c) 1.10 + bisect 0.5 %, band 1.5", 1.10, 0.005, 1.5),
    Design("(c) 1.10 + bisect 0.5 %, band 1.25", 1.10, 0.005, 1.25),
    Design("(c) 1.10 + bisect 1.25 %, band 1.5", 1.10, 0.0125, 1.5),
    Design("(c) 1.07 + bisect 0.5 %, band 1.5", 1.07, 0.005, 1.5),
    Design("(c) 1.05 + bisect 0.5 %, band 1.5 [default]", 1.05, 0.005, 1.5),
    Design("(b) 1.10 ÷4 + bisect 0.5 %, band 1.5", 1.10, 0.005, 1.5, subdivide=4),
    Design("(b) 1.10 ÷8 + bisect 0.5 %, band 1.5", 1.10, 0.005, 1.5, subdivide=8),
    Design("(b) 1.05 ÷4 + bisect 0.5 %, band 1.5", 1.05, 0.005, 1.5, subdivide=4),
    Design("(b) 1.21 ÷8 + bisect 0.5 %, band 1.5", 1.21, 0.005, 1.5, subdivide=8),
)
QUICK = (DESIGNS[0], DESIGNS[5])


@dataclass(frozen=True)
class Case:
    name: str
    model: RockingModel
    records: tuple[tuple[str, np.ndarray, float], ...]  #: (name, acc [m/s²], dt [s])


def project_cases(file: str, picks: Sequence[int]) -> list[Case]:
    inputs = load_inputs(ROOT / "projects" / file)
    seismic = prepare_records(inputs)
    recs = tuple((r.name, r.acc, r.dt) for r in seismic.records)
    models = inputs.case_models()
    names = ["unreinforced"] + [o.name for o in inputs.options]
    return [Case(f"{file}: {names[i]}", models[i], recs) for i in picks if i < len(models)]


def corpus_cases() -> list[Case]:
    every = corpus_records()
    by_name = {r.name: r for r in every}
    chosen = [r for r in every if "SIMQKE" in r.name or "seed" in r.name][::7][:4]
    chosen += [by_name[f"bundled {n}"] for n in ("art-01.AT2", "art-02.AT2", "synthetic-01.AT2")]
    chosen += [by_name["bundled synthetic-02.AT2"]]
    recs = tuple((r.name, r.acc, r.dt) for r in chosen)
    models = dict(corpus_walls())
    return [
        Case(f"corpus: {n}", models[n], recs)
        for n in ("URM two-sided a=7.5 H=3", "CFRP external 1‰ two-sided")
    ]


def capacity(res: IdaResult) -> float:
    """a_c/PGA, or its lower bound (C_max for the first collapse)."""
    return res.capacity_multiplier


def run_design(case: Case, d: Design, pool: ThreadPoolExecutor) -> tuple[list[float], float]:
    """The case mean of C·PGA at each offset, and the time histories per record."""
    jobs = []
    for off in OFFSETS:
        st = IdaSettings(
            ladder_ratio=d.ratio, tolerance=d.tolerance, capacity="effective", offset=off
        )
        for _, acc, dt in case.records:
            if d.rule == "first-collapse":
                jobs.append(pool.submit(_first_collapse, case.model, acc, dt, d, off))
            else:
                jobs.append(
                    pool.submit(
                        ida, case.model, acc, dt, st, band=d.band, subdivide=d.subdivide, coarse=1
                    )
                )
    res = [j.result() for j in jobs]
    n = len(case.records)
    means = [
        statistics.fmean(capacity(r) * r.pga for r in res[k * n : (k + 1) * n])
        for k in range(len(OFFSETS))
    ]
    return means, sum(r.runs for r in res) / len(res)


def _first_collapse(
    model: RockingModel, acc: np.ndarray, dt: float, d: Design, off: float
) -> IdaResult:
    """The §5 hunt with its ladder shifted by ``off`` of a step: the same search on a model
    whose C₀ is C₀·s^off (a_rm scaled through a stand-in)."""
    shifted = _Shifted(model, d.ratio**off)
    res = ida(
        shifted,
        acc,
        dt,
        IdaSettings(d.ratio, d.tolerance, capacity="first-collapse"),
        compiled=False,
    )
    return res


class _Shifted:
    """``model`` with a_RM (so C₀) multiplied by ``factor``: the hunt starts higher."""

    def __init__(self, model: RockingModel, factor: float) -> None:
        self.model, self.factor = model, factor
        self.a_rm = model.a_rm * factor
        self.crushing_rotation = model.crushing_rotation

    def run(self, acc: np.ndarray, dt: float, c: float):  # type: ignore[no-untyped-def]
        return self.model.run(acc, dt, c)


def fine_scan(case: Case, pool: ThreadPoolExecutor) -> list[str]:
    st = IdaSettings(ladder_ratio=1.0125, tolerance=0.1, capacity="effective")
    out = []
    for name, acc, dt in case.records:
        t0 = time.process_time()
        r = ida(case.model, acc, dt, st, band=2.0, coarse=1)
        cpu = time.process_time() - t0
        eff = capacity(r)
        first = r.first_collapse
        windows = 0
        prev = False
        for p in r.curve:
            windows += p.collapsed and not prev
            prev = p.collapsed
        out.append(
            f"    {name[:34]:<34} C0 {r.c0:6.3f}  a_c/C0 {eff / r.c0:6.3f}  first/a_c "
            f"{(first or float('nan')) / eff:6.3f}  windows {windows:3d} (below a_c "
            f"{r.windows_below:3d})  runs {r.runs:4d}  {1e3 * cpu / max(r.runs, 1):6.2f} ms/run"
        )
    return out


def shift_statistics(
    means: Sequence[float], fine: Sequence[float]
) -> tuple[float, float, float, float]:
    """Over the shifts: the average of the case means, their scatter (standard deviation over
    the average), the drift of the average twice as fine, and the scatter there."""
    avg = statistics.fmean(means)
    return (
        avg,
        statistics.pstdev(means) / avg,
        statistics.fmean(fine) / avg - 1.0,
        statistics.pstdev(fine) / statistics.fmean(fine),
    )


def print_summary(
    title: str, summary: dict[str, list[tuple[float, float, float]]], width: int
) -> None:
    """Per design over the cases: the worst scatter, the worst |drift|, the mean runs/record."""
    print(f"\n{title}: worst scatter, worst |drift|, mean runs/record")
    for name, rows in summary.items():
        print(
            f"  {name:<{width}} {100 * max(r[0] for r in rows):5.2f} %  "
            f"{100 * max(abs(r[1]) for r in rows):5.2f} %  "
            f"{statistics.fmean(r[2] for r in rows):6.1f}"
        )


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="two designs, the example only")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-scan", action="store_true", help="skip the fine scans")
    ap.add_argument("--only", default="", help="the designs whose name contains this text")
    args = ap.parse_args()
    cases = project_cases("facade-laquila.yaml", (0, 1, 12))
    if not args.quick:
        cases += project_cases("boundary-wall-records.yaml", (0, 1))
        cases += corpus_cases()
    designs = QUICK if args.quick else DESIGNS
    if args.only:
        designs = tuple(d for d in designs if args.only in d.name or d.rule != "effective")
    print(f"offsets {OFFSETS}; {len(cases)} cases")
    summary: dict[str, list[tuple[float, float, float]]] = {d.name: [] for d in designs}
    with ThreadPoolExecutor(args.jobs) as pool:
        for case in cases:
            print(f"\n{case.name} ({len(case.records)} records)")
            for d in designs:
                means, runs = run_design(case, d, pool)
                fine, fine_runs = run_design(case, d.finer(), pool)
                avg, scatter, drift, fine_scatter = shift_statistics(means, fine)
                summary[d.name].append((scatter, drift, runs))
                print(
                    f"  {d.name:<36} mean {avg:7.4f} m/s²  scatter {100 * scatter:5.2f} %  "
                    f"drift ×2 fine {100 * drift:+6.2f} % (scatter there "
                    f"{100 * fine_scatter:5.2f} %)  "
                    f"{runs:6.1f} runs/record (×2 fine {fine_runs:6.1f})"
                )
            if not args.no_scan:
                print("  fine scan r = 1.0125, band 2:")
                print("\n".join(fine_scan(case, pool)))
    print_summary("over the cases", summary, 36)
    return 0


if __name__ == "__main__":
    sys.exit(main())
