"""The ball and the ball/string law: how the contact force follows the spring's deflection.

The contact-law interface (:mod:`.law`), each law declaring its parameters once with their
physical bounds (:mod:`.parameters`), and the laws: the paper's linear spring-dashpot with its
K_CB(V) and zeta(e) rules (:mod:`.linear`), Hunt-Crossley (:mod:`.hunt_crossley`), hysteretic
(:mod:`.hysteretic`), a ball in series with a string bed (:mod:`.series`); one registry of law
families and presets by name (:mod:`.registry`) and the laws by name with their parameters
(:mod:`.presets`).

Layer: lowest with :mod:`fem_racket.frame`. May import only :mod:`fem_racket.validation`,
:mod:`fem_racket.outputs`, :mod:`fem_racket.version` and itself; never :mod:`fem_racket.frame`.
"""
