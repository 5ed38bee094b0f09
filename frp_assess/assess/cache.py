"""On-disk cache of finished IDAs, keyed by everything that determines the result.

One small JSON file per (case, record), written atomically as soon as its IDA finishes, so an
interrupted run loses nothing and an unchanged rerun computes nothing.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict
from pathlib import Path

import numpy as np

from frp_assess import __version__
from frp_assess.dynamics import IdaResult, IdaSettings, RockingModel
from frp_assess.io_utils import atomic_write_text

#: Bump when the numerics change in a way that changes results.
CACHE_VERSION = 2  # 2: IdaResult.survivor_multiplier


def record_digest(acc: np.ndarray, dt: float) -> str:
    h = hashlib.sha256(np.ascontiguousarray(acc, dtype=np.float64).tobytes())
    h.update(repr(float(dt)).encode())
    return h.hexdigest()


def task_key(model: RockingModel, record_hash: str, settings: IdaSettings) -> str:
    bars = model.rebars
    o = model.options
    payload = {
        "cache": CACHE_VERSION,
        "version": __version__,
        "wall": [model.wall.thickness, model.wall.height, model.wall.unit_weight],
        "mechanism": model.mechanism,
        "bars": None
        if bars is None
        else [
            bars.elastic_modulus,
            bars.ultimate_strain,
            bars.position,
            bars.ratio,
            bars.strain_factor,
        ],
        "model": [o.restitution, o.rupture, o.collapse, o.free_vibration_tail, o.max_step],
        "ida": [settings.step_ratio, settings.tolerance, settings.max_multiplier],
        "record": record_hash,
    }
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


def cache_file(directory: Path, key: str) -> Path:
    """Where the IDA result of ``key`` is stored in a cache directory."""
    return directory / f"{key}.json"


class IdaCache:
    """A directory of ``<key>.json`` files; ``None`` directory disables caching."""

    def __init__(self, directory: Path | None) -> None:
        self.directory = directory
        if directory is not None:
            directory.mkdir(parents=True, exist_ok=True)

    def get(self, key: str) -> IdaResult | None:
        if self.directory is None:
            return None
        path = cache_file(self.directory, key)
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            return IdaResult(**data)
        except (OSError, ValueError, TypeError):
            return None

    def put(self, key: str, result: IdaResult) -> None:
        if self.directory is not None:
            atomic_write_text(cache_file(self.directory, key), json.dumps(asdict(result)))
