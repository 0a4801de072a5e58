"""The annotated example run file printed by ``fem-racket config --example``.

It runs as is and states the paper's standard case (Kawazoe & Kanda 1997: standard racket, ball
at 20 m/s striking 0.75 L), every key at its built-in default; ``tests/io/test_config.py`` checks
that running it gives exactly the default run.
"""

from __future__ import annotations

from fem_racket.frame.segments import EI_RATIO

__all__ = ["example_config"]

_EXAMPLE = f"""\
# fem_racket run configuration (TOML). Run it with
#     fem-racket simulate --config run.toml
# Every key is optional (a missing key keeps the default shown); options given on the command
# line override the file. Units are part of the key names. This file is the paper's standard
# case: Kawazoe & Kanda (1997), standard racket, ball at 20 m/s striking 0.75 L.

[frame]
# Describe the frame by ONE of: a preset (optionally with ei1_n_m2 / ei2_n_m2), a list of
# segments, or a mesh file.
preset = "standard"          # "standard" (EI1 = 146 N m^2) or "rigid" (EI1 = 9999 N m^2)
ei1_n_m2 = 146.0             # grip-side bending rigidity EI1 [N m^2] (overrides the preset)
# ei2_n_m2 = 128.48          # top-side rigidity EI2 [N m^2]; default {EI_RATIO} * EI1
elements = 20                # cubic Hermite beam elements (20 in the paper)
# Instead of the preset: uniform segments from the grip end (this is the standard racket),
# segments = [
#     {{ length_m = 0.204, ei_n_m2 = 146.0, rhoa_kg_m = 0.696 }},
#     {{ length_m = 0.476, ei_n_m2 = 128.48, rhoa_kg_m = 0.458 }},
# ]
# or a mesh file with cell data EI [N m^2] and rhoA [kg/m], relative to this file (this one is
# in the repository's meshes/ folder, for a run file at its root):
# mesh = "meshes/standard_racket.vtu"
# Lead tape (as --add-mass PLACE:GRAMS): a place 12, 2/10, 3/9, 4/8, throat, handle, butt
# (3/9, 2/10, 4/8: half on each side) or a distance from the butt in m, and its mass in g:
# lead = [
#     {{ place = "3/9", mass_g = 10.0 }},
#     {{ place = "0.32", mass_g = 5.0 }},
# ]

[ball]
mass_kg = 0.057              # m_B [kg]; the paper does not state it (rules: 0.056-0.0594)

[contact]
# Compound ball/string spring-dashpot (section 2.1).
# kcb_n_m = 27400.0          # K_CB [N/m]; default: from the speed through the paper's
#                            # 2.74e4 / 5.0e4 / 8.33e4 N/m at 20 / 30 / 40 m/s
clamped_cor = 0.83           # clamped-frame COR, fixes zeta by eqs 1-4 (0.0592) ...
# zeta = 0.0592              # ... or give the damping ratio in [0, 1) directly

[impact]
position_x_over_l = 0.75     # impact point x/L from the grip end, in [0, 1]
speed_m_s = 20.0             # incident ball speed V_B0 [m/s], > 0
racket_speed_m_s = 0.0       # swing: racket speed towards the ball [m/s] at ...
reference_x_over_l = 0.75    # ... this point x/L (the string centre)
# pivot_m = 0.08             # the racket turns about this point [m from the butt]
#                            # (default: it translates); simulate, sweep and map

# [hand]
# Any key here holds the racket in a hand on its grip (simulate; fem_racket.frame.hand): a
# rigid hand joined to the handle by a spring-dashpot layer. The values are assumptions.
# grip = "loose"             # "loose" or "firm": illustrative presets the keys below change
# mass_kg = 0.45             # hand mass m_h [kg] (anthropometric 0.4-0.5 kg)
# grip_start_m = 0.02        # the grip from the butt [m] ...
# grip_end_m = 0.12          # ... to here, within the frame
# stiffness_n_m2 = 1e5       # grip layer stiffness k' [N/m per m of handle] (firm: 3e5)
# damping_n_s_m2 = 100.0     # grip layer damping c' [N s/m per m of handle] (firm: 1000)
# inertia_kg_m2 = 0.000375   # hand inertia about its centre (default: a rod over the grip)
# shock_window_s = 0.05      # window of the grip force's peak and vibration RMS [s]

[solver]
name = "auto"                # "auto" (exact for the paper's law, else general), "exact" (closed
#                            # form), "general" (any law or swing), "cvode" or "bdf"
separation = "displacement"  # end of contact: "displacement" (the paper's) or "force"
basis = "modal"              # frame coordinates for cvode/bdf: "modal" or "physical"
modes = 80                   # flexible frame modes kept in the modal basis
rtol = 1e-10                 # relative tolerance of cvode/bdf
atol = 1e-12                 # absolute tolerance of cvode/bdf
# tolerance = 1e-6           # COR error the exact solver's batched engine may make without
#                            # histories (0: every mode)
# t_max_s = 0.1              # give up if the ball has not left by then [s]
#                            # (default 20 x the eq 11 contact time)

[output]
# out = "output/impact.json" # simulate's JSON output with provenance (the other commands
#                            # take `out` from their own table below: a different kind of file)
overwrite = false            # replace an existing output file
"""


def example_config() -> str:
    """An annotated run file that runs as is (the paper's standard case)."""
    return _EXAMPLE
