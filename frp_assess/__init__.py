"""frp-assess: incremental dynamic analysis of rocking masonry walls with vertical FRP rebars."""

from __future__ import annotations

__version__ = "0.1.0"
