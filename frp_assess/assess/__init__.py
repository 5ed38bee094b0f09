"""The assessment: cases, parallel cached IDA, ranking, demand and code checks, results."""

from __future__ import annotations
