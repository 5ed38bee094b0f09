"""Pure engineering formulas, one unit system (SI: m, N, Pa, kg, s, rad), one function per rule.

Everything else (the schema, the numerical model, the code checks, the report) calls these;
a rule changed here changes everywhere (docs/architecture.md).
"""
