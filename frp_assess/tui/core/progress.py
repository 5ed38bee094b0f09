"""Progress of a run per case, without Textual.

:func:`frp_assess.app.assessment.run_assessment` names every (case, record) IDA as it
finishes through its ``case_progress`` callback (cache hits of an earlier run first, as they
count as done); :class:`CaseProgress` turns those calls into per-case counts.  The callback
comes from the worker threads, so the counts are guarded by a lock.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import Protocol


class HasCases(Protocol):
    """What names the cases of a run (the assessment inputs, or a prepared run's)."""

    def case_names(self) -> list[str]: ...


@dataclass(frozen=True)
class CaseCount:
    """Finished IDAs of one case."""

    name: str
    done: int
    total: int


class CaseProgress:
    """Per-case counts of finished IDAs of a run.

    The cases are those of :func:`~frp_assess.app.assessment.run_assessment`, in its order:
    the unreinforced wall, then every option of ``inputs.options``.
    """

    def __init__(self, inputs: HasCases, n_records: int):
        self.names = inputs.case_names()
        self.per_case = n_records
        self._done = [0] * len(self.names)
        self._lock = threading.Lock()

    @property
    def total(self) -> int:
        """(case, record) pairs of the run."""
        return self.per_case * len(self.names)

    def mark(self, case_index: int, record_index: int) -> None:
        """One IDA of case ``case_index`` finished (the API's ``case_progress`` callback)."""
        del record_index  # every record of a case counts the same
        with self._lock:
            self._done[case_index] += 1

    def counts(self) -> list[CaseCount]:
        """The counts so far."""
        with self._lock:
            done = list(self._done)
        return [CaseCount(n, d, self.per_case) for n, d in zip(self.names, done, strict=True)]
