"""The exact solution of the linear impact: the eigen-solution in modal coordinates, and the
batched engine (roots, residues, separation) for many cases at once."""
