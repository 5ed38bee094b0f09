"""The ``seismic.spectrum`` block: the elastic spectrum (NTC 2018 by parameters or by the
site's coordinates, EC8, a preset of the paper, a user table).
"""

from __future__ import annotations

import functools
from typing import Annotated, Any, Literal

from pydantic import (
    Field,
    model_validator,
)

from frp_assess.config.schema.spec_base import (
    MAX_TABLE_POINTS,
    MIN_SPECTRUM_G,
    TABLE_BAND,
    GroundType,
    Number,
    _Model,
    located_error,
)
from frp_assess.errors import InputError
from frp_assess.motions.site import SiteHazard, site_hazard
from frp_assess.motions.table_limits import MAX_TABLE_PERIOD, MAX_TABLE_SE

#: the hazard of a site, computed once per (latitude, longitude, V_N, use class)
site_hazard_cached = functools.lru_cache(maxsize=64)(site_hazard)


# -------------------------------------------------------------------------------- spectra
class SiteCoordinates(_Model):
    """Where the site is: decimal degrees, as in the NTC reference grid (docs/site-hazard.md)."""

    latitude: Number = Field(ge=-90, le=90, description="Latitude [°], decimal, e.g. 42.35.")
    longitude: Number = Field(
        ge=-180, le=180, description="Longitude [°], decimal, east positive, e.g. 13.40."
    )


UseClass = Literal["I", "II", "III", "IV"]
LimitState = Literal["SLO", "SLD", "SLV", "SLC"]
#: the keys of the spectrum given by its parameters, and of the one given by coordinates
NTC_PARAMETER_KEYS = ("ag", "F0", "Tc_star")
NTC_SITE_KEYS = ("site", "nominal_life", "use_class", "limit_state")


class Ntc2018Spectrum(_Model):
    """NTC 2018 §3.2.3.2.1 elastic spectrum, from the site's parameters a_g, F0, T_C* or from
    the site's coordinates (``site``: the parameters of ``limit_state`` interpolated on the
    NTC reference grid, NTC 2018 §3.2 and NTC 2008 Allegati A/B; docs/site-hazard.md)."""

    type: Literal["ntc2018"] = Field(description="Spectrum kind.")
    ag: Annotated[Number, Field(ge=MIN_SPECTRUM_G, le=1.5)] | None = Field(
        None, description=f"a_g [g] on rock, {MIN_SPECTRUM_G:g} <= a_g <= 1.5."
    )
    # F0 is an amplification of the ground motion: at least 1 (NTC's grid: 2.2-3)
    F0: Annotated[Number, Field(ge=1.0, le=5.0)] | None = Field(
        None, description="F0 [-], maximum amplification on rock, 1-5."
    )
    # T_C* of the NTC grid is 0.15-0.6 s; below 0.05 s the plateau vanishes
    Tc_star: Annotated[Number, Field(ge=0.05, le=3.0)] | None = Field(
        None, description="T_C* [s], start of the velocity branch, 0.05-3."
    )
    site: SiteCoordinates | None = Field(
        None,
        description="Coordinates {latitude, longitude} [°]: a_g, F0, T_C* from the NTC "
        "reference grid instead of ag, F0, Tc_star.",
    )
    nominal_life: Annotated[Number, Field(gt=0, le=1000)] | None = Field(
        None, description="Nominal life V_N [years], 0-1000 (50), with site (Tab. 2.4.I)."
    )
    use_class: UseClass | None = Field(
        None, description="Use class I-IV (II), with site: C_U = 0.7, 1, 1.5, 2 (Tab. 2.4.II)."
    )
    limit_state: LimitState | None = Field(
        None, description="Limit state SLO, SLD, SLV or SLC (SLV), with site (Tab. 3.2.I)."
    )
    soil: GroundType = Field(description="Subsoil category A-E (S_S, C_C of Tab. 3.2.IV).")
    topography: Literal["T1", "T2", "T3", "T4"] = Field(
        "T1", description="Topographic category T1-T4 (S_T of Tab. 3.2.V)."
    )
    damping: Number = Field(0.05, gt=0, lt=1, description="Viscous damping ratio [-] (0.05).")

    @model_validator(mode="after")
    def _one_form(self) -> Ntc2018Spectrum:
        given = [k for k in NTC_PARAMETER_KEYS if getattr(self, k) is not None]
        if self.site is not None:
            if given:
                raise located_error(
                    f"give either site (coordinates) or ag, F0, Tc_star, not both; found "
                    f"{', '.join(given)} with site",
                    given[0],
                )
            self._site_hazard()
            return self
        for key in NTC_SITE_KEYS[1:]:
            if getattr(self, key) is not None:
                raise located_error(f"{key} needs site: {{latitude, longitude}}", key)
        missing = [k for k in NTC_PARAMETER_KEYS if getattr(self, k) is None]
        if missing:
            fields = type(self).model_fields
            described = "; ".join(
                f"{k}: {(fields[k].description or '').rstrip('.')}" for k in missing
            )
            raise located_error(
                f"missing required key{'s' if len(missing) > 1 else ''} "
                f"{', '.join(repr(k) for k in missing)} ({described}), or give the site's "
                "coordinates instead: site: {latitude, longitude}"
            )
        return self

    @property
    def by_coordinates(self) -> bool:
        """The spectrum is given by the site's coordinates (not by a_g, F0, T_C*)."""
        return self.site is not None

    @property
    def V_N(self) -> float:  # noqa: N802
        """Nominal life V_N [years] (50 when not given)."""
        return 50.0 if self.nominal_life is None else float(self.nominal_life)

    @property
    def chosen_limit_state(self) -> str:
        """The limit state whose parameters make the spectrum (SLV when not given)."""
        return self.limit_state or "SLV"

    def _site_hazard(self) -> Any:
        assert self.site is not None
        try:
            return site_hazard_cached(
                float(self.site.latitude),
                float(self.site.longitude),
                self.V_N,
                self.use_class or "II",
            )
        except InputError as exc:
            raise located_error(exc.message, "site") from None

    def site_hazard(self) -> SiteHazard | None:
        """The hazard at the site (all four limit states), or None without ``site``."""
        return None if self.site is None else self._site_hazard()

    def parameters(self) -> tuple[float, float, float]:
        """(a_g [g], F0 [-], T_C* [s]) of the spectrum: as given, or interpolated at the site
        for the chosen limit state."""
        hazard = self.site_hazard()
        if hazard is None:
            assert self.ag is not None and self.F0 is not None and self.Tc_star is not None
            return float(self.ag), float(self.F0), float(self.Tc_star)
        state = hazard[self.chosen_limit_state]
        return state.ag, state.F0, state.Tc_star


class Ec8Spectrum(_Model):
    """EN 1998-1 §3.2.2.2 elastic spectrum."""

    type: Literal["ec8"] = Field(description="Spectrum kind.")
    ag: Number = Field(
        ge=MIN_SPECTRUM_G,
        le=1.5,
        description=f"a_g [g] on type A ground, {MIN_SPECTRUM_G:g} <= a_g <= 1.5.",
    )
    ground: GroundType = Field(description="Ground type A-E (Table 3.2/3.3).")
    spectrum_type: Literal[1, 2] = Field(1, description="1 (M_s > 5.5) or 2.")
    damping: Number = Field(0.05, gt=0, lt=1, description="Viscous damping ratio [-] (0.05).")


class PresetSpectrum(_Model):
    """One of the paper's spectra (a_g·S = 0.106 g, EC8 shape)."""

    type: Literal["preset"] = Field(description="Spectrum kind.")
    name: Literal["A1", "A2", "A3"] = Field(description="Preset A1, A2 or A3 (docs/model.md §6).")


class TableSpectrum(_Model):
    """A user table of (T, Se) points, linear between them."""

    type: Literal["table"] = Field(description="Spectrum kind.")
    periods: list[Annotated[Number, Field(ge=0, le=MAX_TABLE_PERIOD)]] = Field(
        min_length=2,
        max_length=MAX_TABLE_POINTS,
        description=f"Periods T [s], increasing, 0-100, 2 to {MAX_TABLE_POINTS} points.",
    )
    accelerations: list[Annotated[Number, Field(ge=0, le=MAX_TABLE_SE)]] = Field(
        min_length=2,
        max_length=MAX_TABLE_POINTS,
        description="Spectral accelerations Se(T) [g], 0-20, one per period.",
    )

    @model_validator(mode="after")
    def _check_table(self) -> TableSpectrum:
        if len(self.accelerations) != len(self.periods):
            raise located_error(
                f"expected {len(self.periods)} accelerations (one per period), "
                f"found {len(self.accelerations)}",
                "accelerations",
            )
        for i, (t, se) in enumerate(zip(self.periods, self.accelerations, strict=True)):
            # Se(T0) is the a_g*S the records are scaled to; up to 2 s it shapes the records
            if (i == 0 or t <= TABLE_BAND) and se < MIN_SPECTRUM_G:
                raise located_error(
                    f"expected Se >= {MIN_SPECTRUM_G:g} g at the first period and at every "
                    f"period up to {TABLE_BAND:g} s (the band the records are made for), "
                    f"found {se:g} at T = {t:g} s",
                    "accelerations",
                    i,
                )
        for i in range(1, len(self.periods)):
            if self.periods[i] <= self.periods[i - 1]:
                raise located_error(
                    f"expected increasing periods, found {self.periods[i]:g} s after "
                    f"{self.periods[i - 1]:g} s",
                    "periods",
                    i,
                )
        return self


Spectrum = Annotated[
    Ntc2018Spectrum | Ec8Spectrum | PresetSpectrum | TableSpectrum,
    Field(discriminator="type"),
]
