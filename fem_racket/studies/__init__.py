"""Many impacts: parameter grids, per-case kernels, executors (serial, process pool, Dask),
checkpoints, :func:`~fem_racket.studies.sweep.sweep` and mesh-refinement studies.

Layer: above :mod:`fem_racket.impact`; may import it, :mod:`fem_racket.frame`,
:mod:`fem_racket.contact` and the base modules. Studies compute and write their own checkpoints
and datasets through :mod:`fem_racket.outputs`; they never plot.
"""
