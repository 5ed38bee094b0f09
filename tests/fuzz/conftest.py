"""Hypothesis profiles of the fuzz tests.

``fast`` (the default): a few hundred examples in total, derandomized (the same examples on
every machine, so CI is reproducible), no deadline, no example database.  ``long``: many more
random examples, for a developer to run by name::

    HYPOTHESIS_PROFILE=long python3 -m pytest -q tests/fuzz -p no:cacheprovider

The long profile's failures are kept as regression tests (tests/fuzz/test_regressions.py).
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

_SLOW = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]
settings.register_profile(
    "fast",
    max_examples=60,
    deadline=None,
    derandomize=True,
    database=None,
    print_blob=True,
    suppress_health_check=_SLOW,
)
settings.register_profile(
    "long",
    max_examples=1500,
    deadline=None,
    derandomize=False,
    database=None,
    print_blob=True,
    suppress_health_check=_SLOW,
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "fast"))
