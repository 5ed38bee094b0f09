"""The seismic hazard of a site from its coordinates (NTC 2018 §3.2, Allegati A and B), for the
`site` command and the TUI's Site tab: re-exported from :mod:`frp_assess.motions.site` so that
the interfaces import only this package."""

from __future__ import annotations

from frp_assess.motions.site import LIMIT_STATES, USE_CLASSES, SiteHazard, site_hazard
from frp_assess.motions.site.formulas import P_VR

__all__ = ["LIMIT_STATES", "P_VR", "USE_CLASSES", "SiteHazard", "site_hazard"]
