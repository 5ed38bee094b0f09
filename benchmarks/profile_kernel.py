"""Which compiled functions the IDAs of the paper's grid spend their time in (not part of the
tests): Linux ``perf`` sampling the compiled search, with numba's functions named.

    python3 benchmarks/profile_kernel.py [--stride N] [--repeat R] [--study FILE]

Runs the IDAs of every N-th case of the study (FILE, default projects/paper-study.yaml;
N default 40: 364 IDAs of the paper's grid) through the compiled search
(:func:`frp_assess.dynamics.ida`, one thread), R times (default 2), after one warm-up IDA so
that no compilation is sampled.  numba compiles afresh, into a cache of the run's own: code
loaded from a cache keeps no list of its functions.  ``perf record -e cpu-clock`` samples
this process only while the IDAs run.  Machine code made by numba has no symbols, so the
script writes ``/tmp/perf-<pid>.map`` (the address, size and name of every compiled function
of this process, the format perf reads for code generated at run time) and prints each
function's share of the samples: the kernel's own functions one by one, everything else
(the interpreter, numpy) lumped.  A function numba inlined into its caller counts as the
caller (docs/model.md §4.2: the Dormand–Prince step and the right-hand side of Eq. 10 are
inside ``simulate``).

Needs ``perf`` (Debian's linux-perf) and permission to sample one's own process
(``/proc/sys/kernel/perf_event_paranoid`` ≤ 2); says so and exits 0 where either is missing.
The numbers of docs/paper-study.md ("Where the time goes", 2026-11-27) come from here.
"""

from __future__ import annotations

import argparse
import gc
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
# Code numba loads from its cache keeps no list of its functions: compile afresh, into a
# cache of this run's own (removed at the end), so that every function can be named.
_CACHE = tempfile.mkdtemp(prefix="frp-profile-numba-")
os.environ["NUMBA_CACHE_DIR"] = _CACHE

from frp_assess.dynamics import ida  # noqa: E402
from frp_assess.study import StudyPlan, load_study, study_records  # noqa: E402

#: The modules whose compiled functions are listed one by one (the last part of the name).
_KERNEL_MODULES = frozenset(
    (
        "simulate",
        "steppers",
        "events",
        "step_scan",
        "step_control",
        "jumps",
        "fate",
        "trig",
        "ida_search",
    )  # fmt: skip
)


def _demangle(name: str) -> str:
    """``module.function`` of a numba symbol (``_ZN10frp_assess8dynamics…``), else the name."""
    m = re.match(r"_ZN((?:\d+\w+?)+)(?:B\d|E)", name)
    if not m:
        return name
    parts: list[str] = []
    s = m.group(1)
    i = 0
    while i < len(s) and s[i].isdigit():
        j = i
        while s[j].isdigit():
            j += 1
        n = int(s[i:j])
        parts.append(s[j : j + n])
        i = j + n
    return ".".join(parts[-2:]) if parts else name


def write_perf_map(path: Path) -> int:
    """Write every compiled function of this process to ``path`` in perf's map format
    (hex start, hex size, name); returns how many.  A function's size is taken as the gap to
    the next one (numba does not keep sizes): enough to attribute samples."""
    from numba.core.registry import CPUDispatcher

    entries: list[tuple[int, str]] = []
    seen: set[int] = set()
    for obj in gc.get_objects():
        if not isinstance(obj, CPUDispatcher):
            continue
        for cres in obj.overloads.values():
            lib = cres.library  # type: ignore[attr-defined]  # numba's stubs omit it
            if id(lib) in seen:
                continue
            seen.add(id(lib))
            for f in lib._final_module.functions:  # noqa: SLF001 (numba keeps no public list)
                if f.is_declaration:
                    continue
                addr = lib._codegen._engine.get_function_address(f.name)  # noqa: SLF001
                if addr:
                    entries.append((addr, _demangle(f.name)))
    entries.sort()
    if not entries:
        return 0
    with path.open("w") as fh:
        ends = [addr for addr, _ in entries[1:]] + [entries[-1][0] + 4096]
        for (addr, name), end in zip(entries, ends, strict=True):
            fh.write(f"{addr:x} {max(1, end - addr):x} {name}\n")
    return len(entries)


def main() -> int:
    try:
        return _profile()
    finally:
        shutil.rmtree(_CACHE, ignore_errors=True)


def _profile() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", default=str(ROOT / "projects" / "paper-study.yaml"))
    ap.add_argument("--stride", type=int, default=40, help="every N-th case (default 40)")
    ap.add_argument("--repeat", type=int, default=2, help="times over the IDAs (default 2)")
    args = ap.parse_args()
    if shutil.which("perf") is None:
        print("perf is not installed (Debian: linux-perf): nothing measured")
        return 0

    plan = StudyPlan(load_study(Path(args.study)))
    records = study_records(plan)
    cases = list(plan.cases(0, len(plan)))[:: args.stride]
    work = [(plan.model(c), records[c.spectrum]) for c in cases]
    model0, recs0 = work[0]
    ida(model0, recs0[0].acc, recs0[0].dt, plan.ida_settings)  # compile before sampling

    with tempfile.TemporaryDirectory() as tmp:
        data = Path(tmp) / "perf.data"
        rec = subprocess.Popen(
            ["perf", "record", "-q", "-e", "cpu-clock", "-p", str(os.getpid()), "-o", str(data)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        time.sleep(0.5)  # perf attaches (a start-up delay, not a measurement)
        if rec.poll() is not None:
            err = rec.stderr.read().decode().strip() if rec.stderr else ""
            print(f"perf cannot sample this process: {err.splitlines()[-1] if err else '?'}")
            return 0
        t0 = time.process_time()
        n = 0
        for _ in range(args.repeat):
            for model, recs in work:
                for r in recs:
                    ida(model, r.acc, r.dt, plan.ida_settings)
                    n += 1
        cpu = time.process_time() - t0
        rec.send_signal(signal.SIGINT)
        rec.wait()
        perf_map = Path(f"/tmp/perf-{os.getpid()}.map")
        n_funcs = write_perf_map(perf_map)
        report = subprocess.run(
            ["perf", "report", "-i", str(data), "--stdio", "--sort", "sym", "--percent-limit", "0"],
            capture_output=True,
            text=True,
            check=False,
        ).stdout
        perf_map.unlink(missing_ok=True)

    shares: dict[str, float] = {}
    for line in report.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+\[\.\]\s+(\S+)", line)
        if not m:
            continue
        name = m.group(2)
        ours = name.split(".")[0] in _KERNEL_MODULES
        key = name if ours else "(the interpreter, numpy and the rest)"
        shares[key] = shares.get(key, 0.0) + float(m.group(1))
    total = sum(shares.values()) or 1.0
    print(
        f"{Path(args.study).name}, every {args.stride}th case, {args.repeat}×: {n} IDAs, "
        f"{1e3 * cpu / n:.2f} ms CPU per IDA (one thread; {n_funcs} compiled functions mapped)"
    )
    print("share of the samples  function (callees numba inlined count as their caller)")
    for key, pct in sorted(shares.items(), key=lambda kv: -kv[1]):
        if 100.0 * pct / total >= 0.1:
            print(f"  {100.0 * pct / total:5.1f} %  {key}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
