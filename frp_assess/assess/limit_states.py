"""The seismic action of each limit state the code checks name (docs/model.md §5.5).

Circolare 2019 §C8.7.1.2.1 checks a local mechanism at SLV (the linear check, eq. C8.7.1.9;
the nonlinear static check with d_SLV) and at SLC (d_SLC); each limit state has its own
probability of exceedance P_VR, hence its own return period and spectrum (NTC 2018 §3.2.1,
Tab. 3.2.I).  When the project gives the site by its coordinates, the hazard of every limit
state is known (:mod:`frp_assess.motions.site`): each check then runs at its own spectrum, the
NTC 2018 §3.2.3.2.1 shape built from that limit state's a_g, F0, T_C* with the project's
subsoil, topography and damping.  When the project gives one spectrum by its parameters, only
that one is known, and every limit state is checked at it (said in the results and report).

There is no damage-limit (SLD) check of a local mechanism: §C8.7.1.2.1 names none; its
a_g,SLD (eq. C8.7.1.8) is the ground acceleration that starts the mechanism, used only as the
lower bound of a_g,SLV, and NTC 2018 §2.1 allows an existing structure to be checked at the
ultimate limit states only (docs/model.md §5.5).

Units: accelerations in g; periods in s.
"""

from __future__ import annotations

from collections.abc import Sequence

from frp_assess.assess.inputs import ArtificialRecords, AssessmentInputs
from frp_assess.motions import ElasticSpectrum, Record, check_compliance, ntc2018_spectrum
from frp_assess.results.checks import LimitStateIntensity

#: the limit states the code checks of a local mechanism are made at (Circolare 2019
#: §C8.7.1.2.1), in order
CHECKED_STATES: tuple[str, ...] = ("SLV", "SLC")

SITE = "site"
TYPED = "typed"


def own_spectra(inputs: AssessmentInputs) -> bool:
    """Whether every limit state has its own spectrum (the site is given by coordinates and
    the project's spectrum is an NTC 2018 one)."""
    return inputs.site is not None and inputs.spectrum.kind == "ntc2018"


def limit_state_spectrum(inputs: AssessmentInputs, state: str) -> ElasticSpectrum:
    """The elastic spectrum of ``state`` ("SLO", "SLD", "SLV", "SLC"): with the site known,
    NTC 2018 §3.2.3.2.1 with that state's a_g, F0, T_C* at the site and the subsoil,
    topography and damping of the project's spectrum (the project's own spectrum when the
    state is the one it was built for); else the project's one spectrum."""
    site = inputs.site
    if site is None or not own_spectra(inputs) or state == inputs.site_limit_state:
        return inputs.spectrum
    p = inputs.spectrum.parameters
    h = site[state]
    return ntc2018_spectrum(
        h.ag,
        h.F0,
        h.Tc_star,
        str(p["soil"]),
        str(p["topography"]),
        float(p["damping"]),  # type: ignore[arg-type]
    )


def spectrum_compatible_records(inputs: AssessmentInputs, state: str) -> bool:
    """Whether ``state`` gets its own set of artificial records, generated for its own
    spectrum with the project's count, seed, duration and dt (the site is known, the records
    are artificial and the state is not the one the assessment's set was generated for)."""
    return (
        own_spectra(inputs)
        and isinstance(inputs.records, ArtificialRecords)
        and state != inputs.site_limit_state
    )


def records_basis(inputs: AssessmentInputs, state: str) -> str:
    """How the time-history check of ``state`` gets its motions (one phrase)."""
    if isinstance(inputs.records, ArtificialRecords):
        if not own_spectra(inputs) or state == inputs.site_limit_state:
            return "the assessment's artificial records, each scaled to PGA = a_g·S"
        return (
            f"artificial records generated for the {state} spectrum (seed "
            f"{inputs.records.seed}, as the assessment's; records/{state}/), each scaled to "
            "PGA = a_g·S"
        )
    return f"the recorded accelerograms, each scaled to PGA = a_g·S of {state}"


def intensity(
    inputs: AssessmentInputs, state: str, own_records: Sequence[Record] | None = None
) -> LimitStateIntensity:
    """The seismic action ``state`` is checked at, for results.json; ``own_records`` the
    state's own set (checked against its spectrum, EC8 §3.2.3.1.2 and NTC 2018 §3.2.3.6),
    None: it uses the assessment's."""
    spectrum = limit_state_spectrum(inputs, state)
    p = spectrum.parameters

    def number(key: str) -> float | None:
        value = p.get(key)
        return float(value) if isinstance(value, (int, float)) else None

    return LimitStateIntensity(
        limit_state=state,
        a_g_s=spectrum.pga_g,
        ag=number("ag"),
        S=number("S"),
        F0=number("F0"),
        Tc_star=number("Tc_star"),
        source=SITE if own_spectra(inputs) else TYPED,
        records=records_basis(inputs, state),
        records_compliant=None
        if not own_records
        else bool(check_compliance(list(own_records), spectrum, t1=inputs.t1).passed),
    )


def intensity_basis(inputs: AssessmentInputs) -> str:
    """One sentence: at which spectrum each limit state is checked."""
    if own_spectra(inputs):
        parts = [
            f"{s} a_g·S = {limit_state_spectrum(inputs, s).pga_g:.3f} g" for s in CHECKED_STATES
        ]
        return (
            "Each limit state is checked at its own spectrum from the site's coordinates "
            f"({'; '.join(parts)}); the IDA's capacity/demand is stated at each of them, and "
            f"decides at {inputs.site_limit_state}."
        )
    return (
        "One spectrum is given (by its parameters, not by the site's coordinates): the SLV "
        f"and SLC checks both run at its intensity a_g·S = {inputs.spectrum.pga_g:.3f} g, so "
        "the SLC check is implied by the SLV one."
    )
