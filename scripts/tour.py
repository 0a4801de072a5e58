# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # A tour of fem_racket
#
# One impact, a sweep, a refinement study, a VTK export for ParaView and a power map with its
# sweet spots. Run it as a script,
# `python scripts/tour.py [--quick] [--out DIR]` (about 10 s here, 5 s with `--quick`; it
# rewrites its own folder, the repository's `output/tour/` by default, from wherever it runs),
# or as a notebook (each `# %%` is a cell; the plots show inline):
# `jupytext --to notebook scripts/tour.py` makes `scripts/tour.ipynb` to open in Jupyter, or
# `jupytext --to notebook --output output/tour.ipynb --execute scripts/tour.py` runs it.

# %%
import argparse
from pathlib import Path

import fem_racket as fr
from fem_racket.outputs import provenance

ap = argparse.ArgumentParser(
    description="A tour of fem_racket.", epilog="Run time here: ~10 s; --quick ~5 s."
)
ap.add_argument("--quick", action="store_true", help="smaller sweep and refinement (~5 s)")
ap.add_argument("--out", default=None, metavar="DIR", help="output folder (output/tour)")
args, _ = ap.parse_known_args()  # a notebook kernel passes its own arguments
# The repository's output/ (ignored by git) whether run from its root or, as a notebook, from
# scripts/: the first folder up holding pyproject.toml.
here = Path.cwd().resolve()
root = next((p for p in (here, *here.parents) if (p / "pyproject.toml").is_file()), here)
OUT = Path(args.out) if args.out else root / "output" / "tour"

# %% [markdown]
# ## 1. One impact
#
# The paper's standard racket (EI1 = 146 N m², 20 elements) struck at 0.75 L by a ball at
# 20 m/s. The result shows what matters at a glance; its fields hold the time histories.

# %%
r = fr.simulate(position=0.75, speed=20.0)
print(r)

# %%
print(f"K_CB = {r.contact.stiffness:.0f} N/m, zeta = {r.contact.zeta:.4f} (derived, not given)")
ds = r.to_xarray()  # the histories as a labelled dataset, units in attrs
print(list(ds.data_vars))
print("contact force at t = 0 and t_c:", ds.contact_force.values[[0, -1]].round(1), "N")

# %% [markdown]
# The contact force is not zero at t = 0 (the dashpot pushes with C_CB V_B0 at once) and is
# negative at the end: the paper's contact ends when the spring deflection returns to zero,
# while the dashpot still pulls. `separation="force"` ends it where the force is zero.

# %%
ax = fr.plot_impact(r, "force")
path = fr.save_figure(ax.figure, OUT / "force.png", provenance({"tour": "force"}), overwrite=True)
print(f"wrote {path}")

# %% [markdown]
# ## 2. A sweep
#
# COR against the frame's rigidity EI1 at seven impact points (Fig. 13 of the paper, at one
# speed). `fr.sweep` returns an `xarray.Dataset`; `fr.plot_sweep` labels the lines with
# rounded coordinates.

# %%
n_ei = 12 if args.quick else 40
ds = fr.sweep(position="0.55:0.95:7", speed=30.0, ei1=f"50:3000:{n_ei}:log", backend="serial")
cor = ds.cor.sel(ei1=3000, method="nearest")
print(cor.assign_coords(position=cor.position.round(3)).round(4).to_series().to_string())

# %%
ax = fr.plot_sweep(ds.cor, "ei1", hue="position")
path = fr.save_figure(ax.figure, OUT / "sweep.png", provenance({"tour": "sweep"}), overwrite=True)
print(f"wrote {path}")

# %% [markdown]
# ## 3. A refinement study
#
# Frequencies against the exact stepped beam (order 4 for cubic Hermite elements), COR and
# contact time as the mesh is refined.

# %%
elements = (5, 10, 20, 40) if args.quick else (5, 10, 20, 40, 80, 160)
study = fr.refinement_study(elements=elements)
print(study)
print(study.to_xarray().cor.round(6).to_pandas().to_string())

# %%
ax = fr.plot_refinement(study, "frequency")
path = fr.save_figure(ax.figure, OUT / "refine.png", provenance({"tour": "refine"}), overwrite=True)
print(f"wrote {path}")

# %% [markdown]
# ## 4. A VTK export
#
# The frame and the ball at every output time, for ParaView (open `impact.pvd`).

# %%
pvd = fr.write_vtk_series(r, OUT / "impact_vtk", frames=50, overwrite=True)
print(pvd.name, len(list(pvd.parent.glob("frame_*.vtu"))), "frames")

# %% [markdown]
# ## 5. A power map
#
# Ball speed off the strings along the frame of a racket swung at 25 m/s (at 0.75 L, about a
# hand 0.10 m from the butt) against a 20 m/s ball, and its sweet spots (`fem-racket map`).

# %%
m = fr.racket_map(speed=20.0, racket_speed=25.0, pivot=0.1)
s = m.spots
print(
    f"mode-1 node {s.node:.3f} L, centre of percussion {s.cop:.3f} L, "
    f"max e_A at {s.max_apparent_cor:.3f} L, max v_out at {s.max_ball_speed:.3f} L "
    f"({m.ball_speed_out.max():.1f} m/s), power region {s.power_region[0]:.3f}-"
    f"{s.power_region[1]:.3f} L"
)

# %% [markdown]
# The map's figure: e_A and v_out along the frame, the sweet spots marked and named in the
# legends (`fr.map_figure` takes several maps: one curve each).

# %%
fig = fr.map_figure([m], pyplot=True)
path = fr.save_figure(fig, OUT / "map.png", provenance({"tour": "map"}), overwrite=True)
print(f"wrote {path}")
