"""What the racket is: the frame as a free-free stepped Euler-Bernoulli beam.

Segments and the paper's presets (:mod:`.segments`), the 1-D mesh with per-cell EI and rhoA
(:mod:`.mesh`), the assembled frame on its cubic Hermite DOFs (:mod:`.fe`), scikit-fem's forms
(:mod:`.forms`) and the closed-form element matrices (:mod:`.hermite`), free-free modes and mass
properties (:mod:`.modal`), the exact continuous frequencies by transfer matrices
(:mod:`.continuous`) and the assembled :class:`~fem_racket.frame.model.FrameModel`.

Layer: lowest with :mod:`fem_racket.contact`. May import only :mod:`fem_racket.validation`,
:mod:`fem_racket.outputs`, :mod:`fem_racket.version` and itself; never :mod:`fem_racket.contact`.
"""
