"""The 1997 reproduction: the data of each of the paper's figures (:mod:`.figures`), their plots
(:mod:`.plots`), the paper's statements checked one by one (:mod:`.claims`) and the report that
puts them together (:mod:`.reproduce`).

Layer: above :mod:`fem_racket.io`; may import every layer below it, never :mod:`fem_racket.cli`.
"""
