"""Shared fixtures: seeded synthetic ground motions (no files, no network)."""

from __future__ import annotations

import numpy as np
import pytest

G = 9.80665


def synthetic_record(
    seed: int, duration: float = 8.0, dt: float = 0.01, pga_g: float = 0.2, corner: int = 6
) -> np.ndarray:
    """Band-limited noise under a trapezoidal envelope, scaled to ``pga_g`` [returns m/s²].

    A stand-in for an earthquake record: broadband, non-stationary, reproducible from its seed.
    """
    rng = np.random.default_rng(seed)
    n = int(round(duration / dt)) + 1
    t = np.arange(n) * dt
    env = np.clip(t / 1.5, 0, 1) * np.clip((duration - t) / 2.0, 0, 1)
    noise = np.convolve(rng.standard_normal(n), np.ones(corner) / corner, mode="same")
    acc = noise * env
    return acc / np.max(np.abs(acc)) * pga_g * G


@pytest.fixture
def record_factory():
    return synthetic_record
