"""Seismic hazard of a site from its coordinates: the NTC reference grid and its formulas.

:mod:`~frp_assess.motions.site.formulas` holds the code's formulas (pure functions),
:mod:`~frp_assess.motions.site.grid` the packaged grid,
:mod:`~frp_assess.motions.site.territory` whether the site is in Italy, the three put
together in :mod:`~frp_assess.motions.site.hazard` (docs/site-hazard.md).
"""

from __future__ import annotations

from frp_assess.motions.site.formulas import LIMIT_STATES, USE_CLASSES
from frp_assess.motions.site.grid import GridDataError, OutsideGridError
from frp_assess.motions.site.hazard import LimitStateHazard, SiteHazard, site_hazard
from frp_assess.motions.site.territory import OutsideItalyError

__all__ = [
    "LIMIT_STATES",
    "USE_CLASSES",
    "GridDataError",
    "LimitStateHazard",
    "OutsideGridError",
    "OutsideItalyError",
    "SiteHazard",
    "site_hazard",
]
