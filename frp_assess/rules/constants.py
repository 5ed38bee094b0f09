"""Physical constants every layer shares (SI units)."""

from __future__ import annotations

#: Standard gravity g [m/s²] (ISO 80000-3; the conventional value of the CGPM, 1901): every
#: g <-> m/s² conversion of the package.
G = 9.80665
