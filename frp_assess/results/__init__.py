"""The typed results of an assessment (docs/results-json.md)."""
