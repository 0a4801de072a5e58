"""Optimum racket design: design problems, objectives over an impact zone, solvers (scipy,
pymoo NSGA-II), Sobol sensitivity (SALib), and the history that makes long runs resumable.

Modules: :mod:`.zone` (impact zone), :mod:`.swing` (a player's swing for any racket),
:mod:`.variables` (variables, constraints), :mod:`.problem` (the design problem), :mod:`.layout`
(its parameter vector and unit box), :mod:`.description` (its description and digest),
:mod:`.variable_groups` (the variables of each group), :mod:`.paper_problem` (a problem on a
segmented racket), :mod:`.build` (a problem from plain settings), :mod:`.cases` (a design's
impacts as
problems), :mod:`.impacts` (where they are solved), :mod:`.objectives`,
:mod:`.history`, :mod:`.evaluate` (batches on the executors), :mod:`.scaling` (the problem as
solvers see it), :mod:`.solvers` (scipy), :mod:`.pareto` (NSGA-II), :mod:`.result`,
:mod:`.sensitivity` (Sobol), :mod:`.report` (mass properties, modes, maps, sweet spots). Files and
figures: :mod:`fem_racket.io.design_files`, :mod:`fem_racket.io.design_plots`,
:mod:`fem_racket.io.design_study`.
"""
