"""Optimum racket design: design problems, objectives over an impact zone, solvers (scipy,
pymoo NSGA-II), Sobol sensitivity (SALib), and the history that makes long runs resumable.

Modules: :mod:`.zone` (impact zone), :mod:`.swing` (player's swing, v_out), :mod:`.problem`
(variables, constraints), :mod:`.build` (a problem from plain settings), :mod:`.impacts` (the one
impact call), :mod:`.objectives`, :mod:`.history`, :mod:`.evaluate` (batches on the executors),
:mod:`.solvers`, :mod:`.sensitivity`, :mod:`.report` (mass properties, modes, sweet spots).
Files and figures: :mod:`fem_racket.io.design_files`, :mod:`fem_racket.io.design_plots`,
:mod:`fem_racket.io.design_study`.
"""
