"""Code compliance of a set of accelerograms with a target elastic spectrum, clause by clause.

EN 1998-1:2004 §3.2.3.1.2 (artificial accelerograms; §3.2.3.1.3 applies the same rules to
recorded ones):
  (3) the stationary part lasts at least 10 s (artificial records that state it);
  (4)a at least 3 accelerograms;
  (4)b the mean zero-period spectral acceleration (mean PGA) is not below a_g·S;
  (4)c in 0.2·T1-2·T1 no value of the mean 5 %-damped spectrum is below 90 % of the target.

NTC 2018 §3.2.3.6 (checked on the mean 5 % spectrum in the larger of 0.15-2.0 s and
0.15 s-2·T1):
  artificial records: no point more than 10 % below the target; total duration ≥ 25 s and a
  pseudo-stationary part ≥ 10 s (the latter when the records state it);
  recorded records: no point more than 10 % below nor 30 % above the target.

T1 is the fundamental period of the structure.  A rocking wall has no fixed period -- its
apparent period grows with the rocking amplitude (Housner 1963) -- so the default
:data:`DEFAULT_T1` = 1.0 s is a choice: it makes the EC8 range 0.2-2.0 s and the NTC range
0.15-2.0 s, which covers the corner periods of every code spectrum and the periods at which
the paper's walls (H = 3-8 m) rock at the amplitudes that matter.  Give the wall's own T1
when known.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from frp_assess import libm
from frp_assess.motions.record import G, Record
from frp_assess.motions.response import response_spectrum
from frp_assess.motions.spectra import ElasticSpectrum

#: Default fundamental period T1 [s] for the check ranges (see the module docstring).
DEFAULT_T1 = 1.0
#: EC8 §3.2.3.1.2(4)a and NTC: minimum number of accelerograms in a set
MIN_RECORDS = 3
#: Lower and upper bounds of the mean spectrum / target (EC8, NTC artificial: lower only)
LOWER_BOUND = 0.90
UPPER_BOUND_RECORDED = 1.30
#: NTC 2018 §3.2.3.6 durations of artificial records [s]
NTC_MIN_TOTAL = 25.0
MIN_STATIONARY = 10.0


@dataclass(frozen=True)
class ClauseCheck:
    """One requirement of one clause.

    Attributes:
        code: ``"EN 1998-1"`` or ``"NTC 2018"``.
        clause: the clause, e.g. ``"§3.2.3.1.2(4)c"``.
        requirement: what the clause asks, in words with numbers.
        found: what the set has, in words with numbers.
        passed: whether the requirement holds.
        margin: how far from the limit, positive when passed: a ratio difference for the
            spectral and PGA checks (mean/target − limit), records for the count, s for
            durations.
        unit: the unit of ``margin`` (``""`` for a ratio, ``"records"``, ``"s"``).
    """

    code: str
    clause: str
    requirement: str
    found: str
    passed: bool
    margin: float
    unit: str = ""


@dataclass(frozen=True)
class ComplianceReport:
    """The result of :func:`check_compliance`.

    Attributes:
        checks: every requirement checked, in code and clause order.
        periods: periods of the spectra [s] (a log grid plus range ends and corners).
        target: target spectrum at ``periods`` [g].
        mean: mean 5 % (``damping``) spectrum of the set at ``periods`` [g].
        spectra: spectrum of each record at ``periods`` [g], shape (records, periods).
        record_names: names of the records, in the order of ``spectra``.
        mean_pga_g: mean PGA of the set [g].
        t1: fundamental period used for the ranges [s].
        recorded: True if checked as recorded records (NTC 90-130 % band).
        target_name: the target spectrum's name.
    """

    checks: list[ClauseCheck]
    periods: NDArray[np.float64]
    target: NDArray[np.float64]
    mean: NDArray[np.float64]
    spectra: NDArray[np.float64]
    record_names: list[str]
    mean_pga_g: float
    t1: float
    recorded: bool
    target_name: str
    damping: float = 0.05
    ranges: dict[str, tuple[float, float]] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """True if every check passed."""
        return all(c.passed for c in self.checks)

    @property
    def ratio(self) -> NDArray[np.float64]:
        """mean / target at ``periods`` [-]."""
        return self.mean / self.target


def ec8_range(t1: float) -> tuple[float, float]:
    """EN 1998-1 §3.2.3.1.2(4)c period range 0.2·T1-2·T1 [s]."""
    return 0.2 * t1, 2.0 * t1


def ntc_range(t1: float) -> tuple[float, float]:
    """NTC 2018 §3.2.3.6 period range: the larger of 0.15-2.0 s and 0.15 s-2·T1 [s]."""
    return 0.15, max(2.0, 2.0 * t1)


def check_periods(
    spectrum: ElasticSpectrum, t1: float = DEFAULT_T1, count: int = 60
) -> NDArray[np.float64]:
    """Periods [s] at which the spectra are compared: a log grid over 0.02 s to
    max(4 s, 2.5·T1) (for plots), a denser log grid over the union of the check ranges, the
    range ends and the spectrum's corner periods."""
    lo = min(ec8_range(t1)[0], ntc_range(t1)[0])
    hi = max(ec8_range(t1)[1], ntc_range(t1)[1])
    parts = [
        libm.geomspace(0.02, max(4.0, 2.5 * t1), count // 2),
        libm.geomspace(lo, hi, count),
        np.array([*ec8_range(t1), *ntc_range(t1)]),
        np.array([t for t in (spectrum.T_B, spectrum.T_C, spectrum.T_D) if t is not None]),
    ]
    return np.unique(np.round(np.concatenate(parts), 12))


def record_spectra(
    records: Sequence[Record], periods: NDArray[np.float64], damping: float = 0.05
) -> NDArray[np.float64]:
    """Pseudo-acceleration spectra [g] of the records, shape (records, periods)."""
    return np.array([response_spectrum(r.acc, r.dt, periods, damping) / G for r in records])


def _band_check(
    code: str,
    clause: str,
    periods: NDArray,
    ratio: NDArray,
    rng: tuple[float, float],
    upper: float | None,
) -> list[ClauseCheck]:
    inside = (periods >= rng[0] * (1 - 1e-9)) & (periods <= rng[1] * (1 + 1e-9))
    where = f"{rng[0]:.3g}-{rng[1]:.3g} s"
    r, p = ratio[inside], periods[inside]
    k = int(np.argmin(r))
    out = [
        ClauseCheck(
            code,
            clause,
            f"mean spectrum ≥ {LOWER_BOUND:.0%} of target in {where}",
            f"min {r[k]:.1%} at T = {p[k]:.3g} s",
            bool(r[k] >= LOWER_BOUND),
            float(r[k] - LOWER_BOUND),
        )
    ]
    if upper is not None:
        j = int(np.argmax(r))
        out.append(
            ClauseCheck(
                code,
                clause,
                f"mean spectrum ≤ {upper:.0%} of target in {where}",
                f"max {r[j]:.1%} at T = {p[j]:.3g} s",
                bool(r[j] <= upper),
                float(upper - r[j]),
            )
        )
    return out


def _stationary_parts(records: Sequence[Record]) -> list[float] | None:
    try:
        return [float(r.meta["stationary_s"]) for r in records]
    except (KeyError, ValueError):
        return None


def check_compliance(
    records: Sequence[Record],
    spectrum: ElasticSpectrum,
    *,
    t1: float = DEFAULT_T1,
    recorded: bool = False,
    damping: float = 0.05,
    periods: NDArray[np.float64] | None = None,
) -> ComplianceReport:
    """Check a set of records against ``spectrum`` by EN 1998-1 §3.2.3.1.2 and NTC 2018
    §3.2.3.6 (see the module docstring for the requirements).

    Args:
        records: the set (accelerations in m/s²); at least one record.
        spectrum: target elastic spectrum (5 % damping unless ``damping`` says otherwise).
        t1: fundamental period T1 of the structure [s] (ranges of the spectral checks).
        recorded: check as recorded records (NTC: also ≤ 130 % of the target; no duration
            checks).
        damping: damping ratio of the record spectra [-] (the codes say 5 %).
        periods: override of :func:`check_periods` [s].
    """
    if not records:
        raise ValueError("no records to check")
    if not (math.isfinite(t1) and t1 > 0):
        raise ValueError(f"T1 must be > 0 s, got {t1!r}")
    per = check_periods(spectrum, t1) if periods is None else np.asarray(periods, dtype=float)
    spectra = record_spectra(records, per, damping)
    mean = spectra.mean(axis=0)
    target = spectrum.sa(per)
    ratio = mean / target
    n = len(records)
    mean_pga = float(np.mean([r.pga_g for r in records]))
    ec8, ntc = "EN 1998-1", "NTC 2018"
    checks: list[ClauseCheck] = []

    stationary = _stationary_parts(records)
    if not recorded and stationary is not None:
        shortest = min(stationary)
        checks.append(
            ClauseCheck(
                ec8,
                "§3.2.3.1.2(3)",
                f"stationary part ≥ {MIN_STATIONARY:g} s",
                f"shortest {shortest:g} s",
                shortest >= MIN_STATIONARY,
                shortest - MIN_STATIONARY,
                "s",
            )
        )
    checks.append(
        ClauseCheck(
            ec8,
            "§3.2.3.1.2(4)a",
            f"at least {MIN_RECORDS} records",
            f"{n} records",
            n >= MIN_RECORDS,
            float(n - MIN_RECORDS),
            "records",
        )
    )
    checks.append(
        ClauseCheck(
            ec8,
            "§3.2.3.1.2(4)b",
            f"mean PGA ≥ a_g·S = {spectrum.pga_g:.4g} g",
            f"mean PGA {mean_pga:.4g} g ({mean_pga / spectrum.pga_g:.1%})",
            mean_pga >= spectrum.pga_g * (1 - 1e-9),
            mean_pga / spectrum.pga_g - 1.0,
        )
    )
    checks += _band_check(ec8, "§3.2.3.1.2(4)c", per, ratio, ec8_range(t1), None)

    ntc_upper = UPPER_BOUND_RECORDED if recorded else None
    checks += _band_check(ntc, "§3.2.3.6", per, ratio, ntc_range(t1), ntc_upper)
    if not recorded:
        shortest_total = min(r.duration for r in records)
        checks.append(
            ClauseCheck(
                ntc,
                "§3.2.3.6",
                f"total duration ≥ {NTC_MIN_TOTAL:g} s",
                f"shortest {shortest_total:.4g} s",
                shortest_total >= NTC_MIN_TOTAL - 1e-9,
                shortest_total - NTC_MIN_TOTAL,
                "s",
            )
        )
        if stationary is not None:
            checks.append(
                ClauseCheck(
                    ntc,
                    "§3.2.3.6",
                    f"pseudo-stationary part ≥ {MIN_STATIONARY:g} s",
                    f"shortest {min(stationary):g} s",
                    min(stationary) >= MIN_STATIONARY,
                    min(stationary) - MIN_STATIONARY,
                    "s",
                )
            )
    return ComplianceReport(
        checks=checks,
        periods=per,
        target=target,
        mean=mean,
        spectra=spectra,
        record_names=[r.name for r in records],
        mean_pga_g=mean_pga,
        t1=t1,
        recorded=recorded,
        target_name=spectrum.name,
        damping=damping,
        ranges={"EN 1998-1": ec8_range(t1), "NTC 2018": ntc_range(t1)},
    )


# --- scaling -----------------------------------------------------------------------------------


def scale_records(records: Sequence[Record], factor: float) -> list[Record]:
    """The records multiplied by one common ``factor`` [-] (noted in source and meta)."""
    if not (math.isfinite(factor) and factor > 0):
        raise ValueError(f"scale factor must be > 0, got {factor!r}")
    out = []
    for r in records:
        previous = float(r.meta.get("scale_factor", "1"))
        meta = {**r.meta, "scale_factor": f"{previous * factor:.6g}"}
        source = f"{r.source} (scaled x{factor:.4g})" if factor != 1.0 else r.source
        out.append(Record(name=r.name, dt=r.dt, acc=r.acc * factor, source=source, meta=meta))
    return out


def scale_to_pga(records: Sequence[Record], target_pga_g: float) -> list[Record]:
    """Scale the set by one common factor so that its mean PGA equals ``target_pga_g`` [g]
    (the site's a_g·S; EN 1998-1 §3.2.3.1.2(4)b)."""
    mean_pga = float(np.mean([r.pga_g for r in records]))
    if mean_pga <= 0:
        raise ValueError("the records have zero PGA")
    return scale_records(records, target_pga_g / mean_pga)


def ntc_band_factor(
    records: Sequence[Record],
    spectrum: ElasticSpectrum,
    *,
    t1: float = DEFAULT_T1,
    damping: float = 0.05,
) -> tuple[float, bool]:
    """Common factor [-] putting the mean spectrum of a recorded set inside the NTC 2018
    §3.2.3.6 band 90-130 % of the target over the NTC range, centred in log terms
    (f = √(0.9·1.3 / (min ratio · max ratio))), and whether the band is reachable at all
    (max/min ratio ≤ 1.3/0.9)."""
    lo, hi = ntc_range(t1)
    per = libm.geomspace(lo, hi, 60)
    ratio = record_spectra(records, per, damping).mean(axis=0) / spectrum.sa(per)
    rmin, rmax = float(ratio.min()), float(ratio.max())
    factor = math.sqrt(LOWER_BOUND * UPPER_BOUND_RECORDED / (rmin * rmax))
    return factor, rmax / rmin <= UPPER_BOUND_RECORDED / LOWER_BOUND


def scale_to_ntc_band(
    records: Sequence[Record],
    spectrum: ElasticSpectrum,
    *,
    t1: float = DEFAULT_T1,
    damping: float = 0.05,
) -> list[Record]:
    """The recorded set scaled by :func:`ntc_band_factor` (check the result: if the spectral
    shape of the set spreads more than 1.3/0.9 the band cannot be met by scaling)."""
    factor, _ = ntc_band_factor(records, spectrum, t1=t1, damping=damping)
    return scale_records(records, factor)
