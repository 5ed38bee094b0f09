"""A tiny study and its records (short synthetic records: no generator, no files, no network)."""

from __future__ import annotations

import numpy as np
import pytest

from frp_assess.motions import Record
from frp_assess.study import StudyFile, parse_study
from tests.conftest import synthetic_record

TINY = {
    "name": "tiny",
    "height": [3.0, 4.0],
    "alpha_deg": [7.5],
    "ratio": [1.0, 2.0],
    "material": ["CFRP"],
    "position": ["external"],
    "mechanism": ["one-sided"],
    "spectrum": ["A2"],
    "records": {"count": 3, "seed": 1, "duration": 14.0},
    "chunk_size": 2,
}


def tiny_records() -> dict[str, list[Record]]:
    """Three short (6 s) seeded records at 0.1 g for spectrum A2."""
    recs = [
        Record(f"syn-{i}", 0.01, synthetic_record(seed=10 + i, duration=6.0, pga_g=0.1))
        for i in range(3)
    ]
    return {"A2": recs}


@pytest.fixture
def tiny_study() -> StudyFile:
    return parse_study(dict(TINY))


@pytest.fixture
def records() -> dict[str, list[Record]]:
    return tiny_records()


def as_float(x: str) -> float:
    return float(x) if x else float("nan")


__all__ = ["TINY", "as_float", "np", "tiny_records"]
