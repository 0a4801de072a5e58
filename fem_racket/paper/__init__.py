"""The 1997 reproduction: the data of each of the paper's figures (:mod:`.figures`), their plots
(:mod:`.plots`), the paper's statements checked one by one (:mod:`.claims`) and the reports that
put them together (:mod:`.reproduce`: :mod:`.report` with the paper's linear K_CB,
:mod:`.law_report` under another contact law, whose impacts :mod:`.figures.law_runs` runs).

Layer: above :mod:`fem_racket.io`; may import every layer below it, never :mod:`fem_racket.cli`.
"""
