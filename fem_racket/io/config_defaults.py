"""``fem-racket simulate``'s option defaults, for the run file's Python methods: an option at its
default changes nothing, as on the command line (where a run file's key at its default is not
counted as given, :func:`fem_racket.cli.options.runfile.given_options`).

``tests/io/test_config_run.py`` checks every value against the command's parser.
"""

from __future__ import annotations

from typing import Any

from fem_racket.contact.constants import DEFAULT_BALL_MASS
from fem_racket.frame.constants import DEFAULT_MODES, PAPER_EI1
from fem_racket.impact.constants import DEFAULT_TOLERANCE

__all__ = [
    "DEFAULTS",
    "DEFAULT_STEP",
    "FRAME_ELEMENTS",
    "PLAY_DEFAULTS",
    "SIMULATE_DEFAULTS",
    "given",
]

#: The beam elements of a frame of segments unless given: ``--elements``'s default (the paper's).
FRAME_ELEMENTS = 20
#: The ball's speed [m/s] and the racket's swing (racket speed [m/s], reference point x/L [-],
#: pivot [m]) unless given: the defaults of ``--speed``, ``--racket-speed``, ``--reference`` and
#: ``--pivot`` (a ball at 20 m/s on a racket at rest; the reference point not given, the
#: swing's own when there is one: :meth:`~fem_racket.impact.swing.Swing.from_speed`).
PLAY_DEFAULTS: dict[str, Any] = {
    "speed": 20.0,
    "racket_speed": 0.0,
    "reference": None,
    "pivot": None,
}

#: The options of :func:`fem_racket.simulate` a file or the command line may set, with their
#: defaults: an option at its default that was not given is left to the library.
DEFAULTS: dict[str, Any] = {
    "ball_mass": DEFAULT_BALL_MASS,
    "kcb": None,
    "zeta": None,
    "solver": "auto",
    "separation": "displacement",
    "basis": "modal",
    "modes": DEFAULT_MODES,
    "tolerance": DEFAULT_TOLERANCE,
    "t_max": None,
    "rtol": 1e-10,
    "atol": 1e-12,
    "offset": 0.0,
}
#: Every option of ``simulate`` the core tables set with a default other than None (the frame,
#: the impact point and speed, the swing, the law; the others default to None).
SIMULATE_DEFAULTS: dict[str, Any] = {
    **DEFAULTS,
    "ei1": PAPER_EI1,
    "elements": FRAME_ELEMENTS,
    "position": 0.75,
    **{k: v for k, v in PLAY_DEFAULTS.items() if v is not None},
    "law": "linear",
}
#: The histories' output step [s] without ``output_step`` (the command's ``--output-step``
#: default, :class:`fem_racket.impact.settings.Settings`'s).
DEFAULT_STEP = 1e-5


def given(values: dict[str, Any]) -> set[str]:
    """The options (argparse dests) of ``values`` (a RunConfig's ``defaults()``) that are not at
    ``simulate``'s default."""
    return {k for k, v in values.items() if k not in SIMULATE_DEFAULTS or v != SIMULATE_DEFAULTS[k]}
