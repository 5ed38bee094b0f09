"""Write the example records of projects/records/ (run once; the files are committed).

They are *synthetic*: band-limited Gaussian noise under a trapezoidal envelope, seeded,
25 s at dt = 0.005 s, PGA 0.25 g — a stand-in until spectrum-compatible generation
(`frp-assess records generate`) lands.  They are not earthquake records.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from frp_assess.motions.record import G, Record
from frp_assess.motions.writers import write_at2

OUT = Path(__file__).resolve().parent.parent / "projects" / "records"


def synthetic(seed: int, duration: float = 25.0, dt: float = 0.005, pga_g: float = 0.25) -> Record:
    rng = np.random.default_rng(seed)
    n = int(round(duration / dt)) + 1
    t = np.arange(n) * dt
    env = np.clip(t / 3.0, 0, 1) * np.clip((duration - t) / 8.0, 0, 1)
    # 2nd-order low-pass (≈ 5 Hz) of white noise, then a high-pass by removing a moving mean
    x = rng.standard_normal(n)
    k = np.exp(-np.arange(60) * dt * 2 * np.pi * 5.0) * np.cos(np.arange(60) * dt * 2 * np.pi * 2.5)
    y = np.convolve(x, k, mode="same")
    y -= np.convolve(y, np.ones(400) / 400, mode="same")
    acc = y * env
    acc *= pga_g * G / np.max(np.abs(acc))
    return Record(f"synthetic-{seed:02d}", dt, acc, source=f"synthetic noise, seed {seed}")


if __name__ == "__main__":
    for seed in (1, 2, 3):
        rec = synthetic(seed)
        write_at2(
            rec,
            OUT / f"{rec.name}.AT2",
            f"SYNTHETIC example record (band-limited noise, seed {seed}), not an earthquake",
        )
        print("wrote", OUT / f"{rec.name}.AT2")
