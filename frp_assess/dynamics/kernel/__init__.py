"""The compiled rocking kernel (numba): constants, state, integrator, events, verdict, driver.

Modules, in the order a step uses them: :mod:`.params` (the typed record of constants and
the named codes and tolerances), :mod:`.state` (the input, the regime between events and the
output buffers), :mod:`.steppers` (Eq. 10 and one Dormand–Prince or RK4 step),
:mod:`.step_control` (one accepted step: the error control), :mod:`.step_scan` (the events
and the peak on a step's dense output), :mod:`.events` (their location on the integrator),
:mod:`.jumps` (the state's jumps at uplift, impact and rupture), :mod:`.collapse_rule` (the
collapse rule) with :mod:`.fate` (when a freely moving wall can no longer fall), and
:mod:`.simulate` (the driver that strings them together).
"""

from __future__ import annotations

from frp_assess.dynamics.kernel.params import KernelParams
from frp_assess.dynamics.kernel.simulate import Outcome, history_length, simulate
from frp_assess.dynamics.kernel.state import Buffers, Ground

__all__ = ["Buffers", "Ground", "KernelParams", "Outcome", "history_length", "simulate"]
