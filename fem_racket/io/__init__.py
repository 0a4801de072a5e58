"""Files: mesh files, TOML run files, VTK time series, offscreen animations, refinement tables
and plots.

Layer: above :mod:`fem_racket.studies`; may import every layer below it. Every file goes through
:mod:`fem_racket.outputs` (checked before the work, written atomically, with provenance).
"""
