"""The compiled rocking kernel (numba): constants, steppers, events, fate and the driver.

Modules, in the order a step uses them: :mod:`.params` (the typed record of constants and
the named codes and tolerances), :mod:`.steppers` (Eq. 10 and one Dormand–Prince or RK4
step), :mod:`.events` (dense output and event location on the integrator), :mod:`.jumps`
(the state's jumps at uplift, impact and rupture), :mod:`.fate`
(when a freely moving wall can no longer fall), :mod:`.simulate` (the driver).
"""

from __future__ import annotations

from frp_assess.dynamics.kernel.params import KernelParams
from frp_assess.dynamics.kernel.simulate import Outcome, history_length, simulate

__all__ = ["KernelParams", "Outcome", "history_length", "simulate"]
