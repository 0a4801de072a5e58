"""The ball and the ball/string law: how the contact force follows the spring's deflection.

The paper's linear spring-dashpot with its K_CB(V) and zeta(e) rules (:mod:`.linear`), and the
contact-law interface (:mod:`.law`) with its laws: the paper's as a law (:mod:`.spring_dashpot`),
Hunt-Crossley (:mod:`.hunt_crossley`), hysteretic (:mod:`.hysteretic`), a ball in series with a
string bed (:mod:`.series`); named laws and calibrated presets (:mod:`.presets`).

Layer: lowest with :mod:`fem_racket.frame`. May import only :mod:`fem_racket.validation`,
:mod:`fem_racket.outputs`, :mod:`fem_racket.version` and itself; never :mod:`fem_racket.frame`.
"""
