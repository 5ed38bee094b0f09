"""The code's clauses and the material rules, one small pure function per clause or symbol.

Every other layer calls these (docs/architecture.md, "Where each rule lives": the rule ->
function table); a rule changed here changes everywhere.  Each function is named after its
symbol and its docstring cites the clause and the unit of every argument (SI: m, N, Pa, kg, s,
rad, unless it says g).  Nothing of frp_assess below, the standard library only.

- :mod:`~frp_assess.rules.constants`: g.
- :mod:`~frp_assess.rules.geometry`: the rocking block (α, R, B).
- :mod:`~frp_assess.rules.masonry`: FC (Circolare 2019 Tab. C8.5.IV), f_d, the stress block
  0.85·f_d (NTC 2018 §7.8.2.2.1), the toe.
- :mod:`~frp_assess.rules.bars`: the FRP bars (CNR-DT 200 R1/2013: η_a, γ_f, ε_fd).
- :mod:`~frp_assess.rules.impact`: Housner's restitution.
- :mod:`~frp_assess.rules.kinematic`: the kinematic checks (Circolare 2019 §C8.7.1.2.1).
- :mod:`~frp_assess.rules.record_sets`: the design value over the records (NTC 2018 §7.3.5).
- :mod:`~frp_assess.rules.spectrum`: the elastic spectrum's coefficients (NTC 2018 §3.2.3,
  EN 1998-1 §3.2.2).
"""
