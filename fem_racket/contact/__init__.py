"""The ball and the ball/string law: how the contact force follows the spring's deflection.

Today the paper's linear spring-dashpot with its K_CB(V) and zeta(e) rules (:mod:`.linear`).

Layer: lowest with :mod:`fem_racket.frame`. May import only :mod:`fem_racket.validation`,
:mod:`fem_racket.outputs`, :mod:`fem_racket.version` and itself; never :mod:`fem_racket.frame`.
"""
