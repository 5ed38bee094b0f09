"""Progress of a run per case, read from the IDA cache, without Textual.

:func:`frp_assess.api.run_assessment` reports the overall number of finished (case, record)
IDAs; the batch runs them on a thread pool, so the order in which they finish is not known.
Every finished IDA is written at once to ``out_dir/.cache/<key>.json`` (before the progress
callback is called), with the key :func:`frp_assess.assess.cache.task_key` computes from the
model, the record and the IDA settings.  :class:`CaseProgress` computes the same keys for
every (case, record) pair and counts the files present: an exact per-case progress that
uses the API unchanged (cache hits of an earlier run count as done, as they are).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from frp_assess.api import CACHE_DIR
from frp_assess.assess.cache import record_digest, task_key
from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.motions import Record


@dataclass(frozen=True)
class CaseCount:
    """Finished IDAs of one case."""

    name: str
    done: int
    total: int


class CaseProgress:
    """Per-case counts of finished IDAs of a run into ``out_dir``.

    The cases are those of :func:`~frp_assess.api.run_assessment`, in its order: the
    unreinforced wall, then every option of ``inputs.options``.
    """

    def __init__(self, inputs: AssessmentInputs, records: Sequence[Record], out_dir: Path):
        self.names = ["Unreinforced", *(o.name for o in inputs.options)]
        models = [inputs.model_for(None), *(inputs.model_for(o) for o in inputs.options)]
        hashes = [record_digest(r.acc, r.dt) for r in records]
        self.cache_dir = Path(out_dir) / CACHE_DIR
        self._pending: list[set[str]] = [
            {task_key(m, h, inputs.ida) for h in hashes} for m in models
        ]
        self._done = [0] * len(models)
        self.per_case = len(hashes)

    @property
    def total(self) -> int:
        """(case, record) pairs of the run."""
        return self.per_case * len(self.names)

    def poll(self) -> list[CaseCount]:
        """Count the cache files that appeared since the last call (each key is checked until
        found, so the cost stays proportional to the pairs not yet finished)."""
        for i, pending in enumerate(self._pending):
            found = {k for k in pending if (self.cache_dir / f"{k}.json").is_file()}
            if found:
                pending -= found
                self._done[i] += len(found)
        return self.counts()

    def counts(self) -> list[CaseCount]:
        """The counts as of the last :meth:`poll`."""
        return [CaseCount(n, d, self.per_case) for n, d in zip(self.names, self._done, strict=True)]
