"""The option groups the commands share, one concept each: the frame (:mod:`.frame`), the impact
(:mod:`.impact`: ball, swing, hand, solver), the contact law (:mod:`.laws`), the design problem
(:mod:`.design`, :mod:`.variables`, :mod:`.zones`, :mod:`.objectives`), where the work runs
(:mod:`.execution`), figures and progress (:mod:`.drawing`), list values (:mod:`.lists`), outputs
(:mod:`.output`: ``--out``, ``--overwrite``, JSON) and run files (:mod:`.runfile`: ``--config``).

:mod:`fem_racket.cli.common` re-exports what most commands need.
"""
