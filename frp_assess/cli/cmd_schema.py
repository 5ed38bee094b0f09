"""`frp-assess schema`: the JSON Schema of project files (for editor completion)."""

from __future__ import annotations

import argparse
import json

from frp_assess.config.schema.building_spec import ProjectFileSchema


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "schema",
        help="print the JSON Schema of project files",
        description="Print the JSON Schema of the project file, e.g. for YAML completion in "
        "an editor (yaml-language-server: '# yaml-language-server: $schema=frp-assess.json').",
    )
    p.set_defaults(handler=run)


def project_json_schema() -> dict[str, object]:
    """The JSON Schema of a project file: :class:`~frp_assess.config.schema.Project`, with
    ``walls:`` (a building) in place of ``wall:`` as the alternative (exactly one of them)."""
    schema = ProjectFileSchema.model_json_schema()
    schema["oneOf"] = [{"required": ["wall"]}, {"required": ["walls"]}]
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "frp-assess project file"
    return schema


def run(args: argparse.Namespace) -> int:
    print(json.dumps(project_json_schema(), indent=2, ensure_ascii=False))
    return 0
