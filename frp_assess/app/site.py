"""The seismic parameters of a site from its coordinates (`frp-assess site`).

A thin door onto :mod:`frp_assess.motions.site` (docs/site-hazard.md): the interfaces ask
here, never the numerics directly.
"""

from __future__ import annotations

from frp_assess.motions.site import LIMIT_STATES, USE_CLASSES, SiteHazard, site_hazard
from frp_assess.motions.site.formulas import P_VR

__all__ = ["LIMIT_STATES", "P_VR", "USE_CLASSES", "SiteHazard", "site_hazard"]
