"""Seismic input: records, code spectra, response spectra, artificial accelerograms."""

from __future__ import annotations

from frp_assess.motions.record import G, Record

__all__ = ["G", "Record"]
