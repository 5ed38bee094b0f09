from __future__ import annotations

import sys

from frp_assess.cli import main

sys.exit(main())
