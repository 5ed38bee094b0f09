"""The project file: schema (pydantic v2), libraries and loader with one-line errors.

A pure schema/loader layer: it never imports the dynamics, the ground-motion module or any UI.
"""

from __future__ import annotations

from frp_assess.config.library import FRP_MATERIALS, MASONRY, FrpMaterial, Masonry
from frp_assess.config.loader import (
    LoadedProject,
    dump_project,
    load_project,
    load_project_text,
    project_data,
    validate_data,
)
from frp_assess.config.schema import Intervention, Project

__all__ = [
    "FRP_MATERIALS",
    "MASONRY",
    "FrpMaterial",
    "Intervention",
    "LoadedProject",
    "Masonry",
    "Project",
    "dump_project",
    "project_data",
    "load_project",
    "load_project_text",
    "validate_data",
]
