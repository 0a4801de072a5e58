"""The tangential contact of an oblique impact: Stronge's compliant frictional contact marched
over a normal force history (:mod:`.march`), the histories it runs over (:mod:`.normal`),
Stronge's closed forms (:mod:`.stronge`), a fixed-step second path (:mod:`.stepping`) and the
ball's outcome (:mod:`.oblique`).
"""
