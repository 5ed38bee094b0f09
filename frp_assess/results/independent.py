"""The independent checks of a run (results.json ``independent_checks``): NTC 2018 §10.2's
reasoned judgement of a program's results rests on checks that could fail, each computed in
the run by a route the analysis did not take (a closed form, a hand formula, another
integrator), with its value, its reference, its tolerance and its outcome.

Filled by :mod:`frp_assess.assess.independent_checks`; plain frozen dataclasses (the field
names are the JSON keys).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["IndependentCheck"]


@dataclass(frozen=True)
class IndependentCheck:
    """One independent check: ``value`` is the run's (the model's) figure, ``reference`` the
    independent one, both in ``unit``; ``deviation`` = |value − reference| / |reference| [-]
    (or the absolute difference when ``absolute``), passing at ≤ ``tolerance``."""

    #: "activation multiplier" | "free rocking period" | "energy at impact" |
    #: "reference integrator" | "tighter tolerance"
    name: str
    value: float
    reference: float
    unit: str
    deviation: float
    tolerance: float
    absolute: bool
    passed: bool
    detail: str  #: one sentence with the numbers and what was compared (English)
