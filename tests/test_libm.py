"""frp_assess.libm: the C library's functions element by element, and nothing else in the
computation (records, spectra, site, statistics) takes numpy's processor-dependent loops.

Reference: the ``math`` module (the C library), value by value; numpy's ``geomspace``
definition (10 to the powers of an even linspace of log10, end points exact).
"""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest

import frp_assess
from frp_assess import libm

RNG = np.random.default_rng(20261126)
WIDE = np.concatenate([RNG.uniform(-30.0, 30.0, 2000), [0.0, -0.0, 1e-300, 700.0, -745.0]])
POSITIVE = np.concatenate([RNG.uniform(1e-6, 1e3, 2000), [1e-300, 1.0, math.e, 1e300]])
UNIT = np.concatenate([RNG.uniform(-1.0, 1.0, 2000), [-1.0, 0.0, 1.0]])

CASES = [
    (libm.exp, math.exp, WIDE),
    (libm.log, math.log, POSITIVE),
    (libm.sin, math.sin, WIDE),
    (libm.cos, math.cos, WIDE),
    (libm.arctan, math.atan, WIDE),
    (libm.arcsin, math.asin, UNIT),
]


@pytest.mark.parametrize(("fn", "reference", "x"), CASES, ids=lambda c: getattr(c, "__name__", ""))
def test_every_element_is_the_c_library_value(fn, reference, x) -> None:
    got = fn(x.reshape(-1, 1))  # any shape, kept
    assert got.shape == (x.size, 1)
    assert got.dtype == np.float64
    expected = np.array([reference(float(v)) for v in x])
    assert np.array_equal(got.ravel(), expected)  # bit for bit, signed zeros included
    assert np.array_equal(np.signbit(got.ravel()), np.signbit(expected))


def test_power_is_pow_of_each_element() -> None:
    x = POSITIVE[:500]
    assert np.array_equal(libm.power(x, 1.2), np.array([float(v) ** 1.2 for v in x]))
    assert libm.power(np.array(2.0), 0.5).shape == ()


def test_geomspace_as_numpy_defines_it() -> None:
    """End points exact, the inner points 10**linspace(log10 a, log10 b) with pow of the
    C library; every ratio of neighbours the same to round-off."""
    out = libm.geomspace(0.03, 4.0, 48)
    assert out.shape == (48,) and out[0] == 0.03 and out[-1] == 4.0
    exponents = np.linspace(math.log10(0.03), math.log10(4.0), 48)
    assert np.array_equal(out[1:-1], np.array([10.0 ** float(e) for e in exponents[1:-1]]))
    ratios = out[1:] / out[:-1]
    assert np.ptp(ratios) < 1e-12 * ratios[0]
    assert np.allclose(out, np.geomspace(0.03, 4.0, 48), rtol=1e-15, atol=0.0)
    with pytest.raises(ValueError, match="positive"):
        libm.geomspace(0.0, 1.0, 3)


#: packages whose arrays end up in results.json (the report and the TUI only draw)
COMPUTATION = ("rules", "dynamics", "motions", "assess", "study", "config", "app")
#: numpy functions whose float64 loops numpy picks by the processor (AVX-512: its own
#: vectorised versions, which round otherwise than the C library)
DISPATCHED = {
    "exp", "log", "log2", "log10", "expm1", "log1p", "sin", "cos", "tan", "arcsin", "arccos",
    "arctan", "arctan2", "sinh", "cosh", "tanh", "power", "cbrt", "geomspace", "logspace",
    "exp2",
}  # fmt: skip


def _numpy_calls(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = []
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id == "np"
            and node.attr in DISPATCHED
        ):
            found.append(f"{path.name}:{node.lineno}: np.{node.attr}")
    return found


def test_no_processor_dependent_numpy_function_in_the_computation() -> None:
    """A guard: np.exp & co. in the computation would make the bytes of results.json depend
    on the processor again (use frp_assess.libm)."""
    package = Path(frp_assess.__file__).parent
    calls = [
        call
        for sub in COMPUTATION
        for path in sorted((package / sub).rglob("*.py"))
        for call in _numpy_calls(path)
    ]
    assert calls == []
