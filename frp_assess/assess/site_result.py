"""The ``site`` block of results.json: the hazard of a site given by its coordinates."""

from __future__ import annotations

from frp_assess.motions.site import LIMIT_STATES, SiteHazard
from frp_assess.motions.site.formulas import P_VR
from frp_assess.results.run_inputs import LimitStateSite, SiteResult


def site_result(hazard: SiteHazard | None, limit_state: str) -> SiteResult | None:
    """The :class:`~frp_assess.results.model.SiteResult` of ``hazard`` (None: the spectrum
    was given by its parameters), ``limit_state`` the one that makes the spectrum."""
    if hazard is None:
        return None
    return SiteResult(
        latitude=hazard.latitude,
        longitude=hazard.longitude,
        V_N=hazard.V_N,
        use_class=hazard.use_class,
        C_U=hazard.C_U,
        V_R=hazard.V_R,
        limit_states={
            s: LimitStateSite(
                P_VR=P_VR[s],
                TR=hazard[s].TR,
                TR_used=hazard[s].TR_used,
                ag=hazard[s].ag,
                F0=hazard[s].F0,
                Tc_star=hazard[s].Tc_star,
            )
            for s in LIMIT_STATES
        },
        limit_state=limit_state,
        nearest_node=hazard.nodes[0].distance,
    )
