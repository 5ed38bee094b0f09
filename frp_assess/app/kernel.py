"""Whether a run will first compile the numerical kernel, and the line that says so."""

from __future__ import annotations


def compile_notice() -> str | None:
    """The line to show before a run that will compile the kernel (numba's cache is cold
    for this processor, numba and source: :func:`~frp_assess.dynamics.kernel_cache.
    cache_is_cold`), else None.  A few milliseconds; imports the numerics."""
    from frp_assess.dynamics.kernel_cache import COLD_NOTICE, cache_is_cold

    return COLD_NOTICE if cache_is_cold() else None
