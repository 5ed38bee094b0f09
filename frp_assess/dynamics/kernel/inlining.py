"""Where numba inlines a kernel function into its caller (``@njit(inline=into(...))``).

numba compiles every ``@njit`` function on its own and calls it with all its arguments,
the 23 fields of :class:`~.params.KernelParams` included, through memory; LLVM did not inline
the integrator's stages into the driver.  A step of Dormand–Prince evaluates Eq. 10 seven
times, so those calls were a third of the kernel's time (docs/model.md §4.2).  numba's own
inliner copies a function's code into the callers named here, before types are inferred.
Each copy costs compilation time (the whole kernel is compiled once per cache), so a
function is inlined only into the callers on the path of every step, nowhere else.
Inlining changes no arithmetic: the results are the same bit for bit.

The driver's own pieces, written as functions a reader can follow against docs/model.md §3–4,
are inlined with ``inline="always"`` (they are called from the driver and from each other
only): :func:`.step_control.try_step` and :func:`.step_scan.scan_step` on the path of every
step, :func:`.collapse_rule.collapse_verdict`, the regime's helpers of :mod:`.state`.
The jumps at an
event or an uplift (:func:`.jumps.jump`, :func:`.jumps.uplift_from_rest`) are compiled on
their own instead, with the jumps inlined into them: one call per event, as before the
split, and compiled once for both versions of the driver.  Measured on 2026-11-28 against
the driver before the split (benchmarks/bench_kernel_against.py, every 20th case of the
paper's grid): the same results bit for bit, the same speed; the first IDA's compilation
0.2–0.4 CPU-s (2–3 %) longer (docs/model.md §4.6).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

#: numba's cost model for ``inline=``: (call expression, caller's IR, callee's IR) -> inline?
CostModel = Callable[[Any, Any, Any], bool]


def into(*callers: str) -> CostModel:
    """Inline the decorated function into the functions named ``callers`` only."""
    names = frozenset(callers)

    def cost_model(expr: Any, caller: Any, callee: Any) -> bool:
        return bool(caller.func_id.func_name in names)

    return cost_model
