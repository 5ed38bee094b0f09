"""Elementary functions of arrays with the same bits on every x86-64 processor.

numpy chooses its loops for exp, log, sin, cos, arctan, arcsin, pow (and so ``geomspace``)
by the processor it runs on: on a processor with AVX-512 (AVX512F, AVX512_SKX) it uses its
own vectorised implementations, which round differently from the C library in the last bit;
on the others it calls the C library element by element.  One record generated on the two
kinds of machine then differed in the last bit, and an IDA's ill-conditioned curve points
(docs/model.md §4.5) amplified that to 1.5e-7: the same project and seed gave other bytes.

Every array function of the computation (records, spectra, site interpolation, statistics)
therefore comes from here: the C library's function (the ``math`` module) applied element
by element, which is what numpy itself computes on a processor without AVX-512 — the bytes
are the ones numpy gives there (tests/test_libm.py checks both).  The arrays are short
(at most a record's samples): ~0.1 µs an element, a few milliseconds per record at most.
Scalars keep using ``math``; the report's and the TUI's plots may keep numpy (nothing of them
is stored).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from itertools import repeat

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def _elementwise(fn: Callable[..., float], x: ArrayLike, *more: object) -> FloatArray:
    """``fn`` of every element of ``x`` (with the further arguments ``more``), same shape."""
    a = np.asarray(x, dtype=np.float64)
    args = (a.ravel().tolist(), *(repeat(m) for m in more))
    return np.fromiter(map(fn, *args), dtype=np.float64, count=a.size).reshape(a.shape)


def exp(x: ArrayLike) -> FloatArray:
    """e**x of every element (C library ``exp``)."""
    return _elementwise(math.exp, x)


def log(x: ArrayLike) -> FloatArray:
    """Natural logarithm of every element (C library ``log``); x > 0."""
    return _elementwise(math.log, x)


def sin(x: ArrayLike) -> FloatArray:
    """sin x of every element [x in rad] (C library ``sin``)."""
    return _elementwise(math.sin, x)


def cos(x: ArrayLike) -> FloatArray:
    """cos x of every element [x in rad] (C library ``cos``)."""
    return _elementwise(math.cos, x)


def arctan(x: ArrayLike) -> FloatArray:
    """atan x of every element [rad] (C library ``atan``)."""
    return _elementwise(math.atan, x)


def arcsin(x: ArrayLike) -> FloatArray:
    """asin x of every element [rad], |x| ≤ 1 (C library ``asin``)."""
    return _elementwise(math.asin, x)


def power(x: ArrayLike, exponent: float) -> FloatArray:
    """x**exponent of every element (C library ``pow``), as numpy's ``x ** exponent``."""
    return _elementwise(pow, x, float(exponent))  # pow(v, e) is v ** e for floats


def geomspace(start: float, stop: float, num: int) -> FloatArray:
    """``num`` numbers from ``start`` to ``stop`` (both > 0, both included) evenly spaced on a
    log scale: numpy's ``geomspace`` (10 to the powers of an even ``linspace`` of log10, the
    end points set exactly) with the C library's ``pow``."""
    if not (start > 0.0 and stop > 0.0):
        raise ValueError(f"geomspace needs positive end points, got {start!r} and {stop!r}")
    exponents = np.linspace(math.log10(start), math.log10(stop), num)
    out = np.fromiter(map(pow, repeat(10.0), exponents.tolist()), dtype=np.float64, count=num)
    if num > 0:
        out[0] = start
    if num > 1:
        out[-1] = stop
    return out
