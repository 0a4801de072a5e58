"""Compare set-ups: rackets, each with its own strings and ball, side by side and B - A.

For each set-up (:class:`Setup`: a frame with any lead on it, the ball's mass and the
ball/string law) under the same play (:class:`Play`: ball speed, swing, the impact point of the
single-impact measures and the hand), one :class:`Report`:

- catalogue numbers (:mod:`fem_racket.frame.catalogue`): mass, balance, swing weight,
  f1, and on frames with torsion data the twistweight and the first torsion frequency;
- the maps of e_A and v_out along the frame and the sweet spots
  (:func:`fem_racket.studies.racket_map.racket_map`), the power region [x/L] and its length [m];
- at the impact point ``Play.position``: contact time (:func:`fem_racket.simulate`, any law)
  and the handle shock of the racket held by ``Play.grip`` (vibration RMS and peak of the grip
  force, :mod:`fem_racket.impact.held.shock`; the paper's linear law only, None under another
  law);
- with ``Play.offsets``, the face map of e_A and v_out over (x, y)
  (:func:`fem_racket.studies.face_map.face_map`: the frame bends and twists; the paper's linear
  law) and its power area [cm^2].

:func:`differences` gives every scalar of each later report minus the first's (B - A); the
maps' differences are taken on the shared x/L grid.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.catalogue import Catalogue, catalogue
from fem_racket.frame.hand import GRIPS
from fem_racket.frame.mesh import FrameMesh, frame_mesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.modal import held_contacts
from fem_racket.impact.held.shock import DEFAULT_WINDOW, grip_peak, vibration_rms
from fem_racket.impact.simulate import simulate
from fem_racket.studies.face_map import FaceMap, face_map
from fem_racket.studies.map_options import MapPlay, check_at_rest
from fem_racket.studies.racket_map import RacketMap, racket_map
from fem_racket.studies.swing_points import check_swing_points
from fem_racket.validation import InputError, check_choice, check_range

__all__ = ["Play", "Report", "Setup", "check_compare", "compare", "differences", "unique_names"]


@dataclass(frozen=True)
class Setup:
    """A racket with its strings and ball.

    Attributes
    ----------
    name : str
    frame : Frame or FrameMesh
        The racket (lead already added).
    ball_mass : float
        m_B [kg].
    kcb, zeta : float, optional
        The paper's linear law's K_CB [N/m] (from the closing speed when None) and damping ratio.
    law : ContactLaw, optional
        Another ball/string law (then ``kcb`` and ``zeta`` must be None).
    elements : int
        Cells when meshing a Frame.
    """

    name: str
    frame: Frame | FrameMesh
    ball_mass: float = DEFAULT_BALL_MASS
    kcb: float | None = None
    zeta: float | None = None
    law: Any = None
    elements: int = 20

    def mesh(self) -> FrameMesh:
        """The racket's mesh."""
        f = self.frame
        return f if isinstance(f, FrameMesh) else frame_mesh(f, self.elements)

    def contact(self) -> dict[str, Any]:
        """The ball's mass and the ball/string law, as keywords of :func:`fem_racket.simulate`
        and the maps: ``ball_mass`` and ``law``, or ``ball_mass``, ``kcb`` and ``zeta``."""
        if self.law is not None:
            return {"ball_mass": self.ball_mass, "law": self.law}
        return {"ball_mass": self.ball_mass, "kcb": self.kcb, "zeta": self.zeta}


@dataclass(frozen=True)
class Play(MapPlay):
    """How every set-up is played: ball speed [m/s], swing (speed [m/s] of the point
    ``reference`` x/L, pivot [m from the butt] or None), the grid of the maps (x/L) — the
    fields of :class:`~fem_racket.studies.map_options.MapPlay` — then the
    impact point [x/L] of the single-impact measures, the grip holding the racket and, to map
    the whole face, the lateral offsets [m] of its grid (None: along the axis only)."""

    position: float = 0.75
    grip: str = "firm"
    offsets: Any = None

    def __post_init__(self) -> None:
        check_at_rest(self.racket_speed, self.reference, self.pivot)  # compare shows no COP
        super().__post_init__()
        check_range("position", self.position, 0.0, 1.0, unit="x/L")
        check_choice("grip", self.grip, tuple(GRIPS))


@dataclass(frozen=True, eq=False)
class Report:
    """One set-up's numbers and maps (module docstring)."""

    setup: Setup
    specs: Catalogue
    map: RacketMap
    contact_time: float
    shock_rms: float | None
    shock_peak: float | None
    face: FaceMap | None = None

    def values(self) -> dict[str, float | None]:
        """Every scalar, JSON-ready, units in the keys."""
        s = self.map.spots
        start, end = s.power_region
        length = self.map.length
        out: dict[str, float | None] = dict(self.specs.as_dict())
        out.update(
            {
                "ball_mass_kg": self.setup.ball_mass,
                "node_x_over_l": s.node,
                "max_apparent_cor_x_over_l": s.max_apparent_cor,
                "max_apparent_cor": float(np.nanmax(self.map.apparent_cor)),
                "max_ball_speed_x_over_l": s.max_ball_speed,
                "max_ball_speed_out_m_s": float(np.nanmax(self.map.ball_speed_out)),
                "power_region_start_x_over_l": start,
                "power_region_end_x_over_l": end,
                "power_region_length_m": (end - start) * length,
                "contact_time_s": self.contact_time,
                "handle_shock_rms_n": self.shock_rms,
                "peak_grip_force_n": self.shock_peak,
                "power_area_cm2": None if self.face is None else self.face.power_area_cm2,
            }
        )
        return {k: (None if v is None or v != v else float(v)) for k, v in out.items()}


def _shock(model: FrameModel, setup: Setup, play: Play, v: float) -> tuple[float, float] | None:
    if setup.law is not None:
        return None
    basis = held_basis(model.fe, GRIPS[play.grip])
    (contact,) = held_contacts(basis, [play.position], [v], **setup.contact())
    return vibration_rms(contact, DEFAULT_WINDOW), grip_peak(contact, DEFAULT_WINDOW)


def report(setup: Setup, play: Play) -> Report:
    """The :class:`Report` of one set-up."""
    model = FrameModel.build(setup.mesh())
    contact = setup.contact()
    rmap = racket_map(model, name=setup.name, **play.keywords(), **contact)
    sw = play.swing(model.mesh.length)
    one = simulate(
        model, position=play.position, speed=play.speed, swing=sw, output_step=None, **contact
    )
    closing = closing_speed(play.speed, sw.speed_at(play.position * model.mesh.length))
    shock = _shock(model, setup, play, closing)
    face = None
    if play.offsets is not None:
        if setup.law is not None:
            raise InputError(
                f"offsets are not allowed with {setup.name}'s contact law {setup.law.name!r}: "
                "the face map runs the paper's linear law"
            )
        face = face_map(
            model,
            **{**play.keywords(), "positions": rmap.positions},
            offsets=play.offsets,
            name=setup.name,
            options=contact,
        )
    return Report(
        setup,
        catalogue(model),
        rmap,
        one.contact_time,
        None if shock is None else shock[0],
        None if shock is None else shock[1],
        face,
    )


def unique_names(names: Sequence[str]) -> list[str]:
    """``names`` with repeats numbered (``A``, ``A (2)``) so each labels one set-up."""
    out: list[str] = []
    for n in names:
        k, label = 1, n
        while label in out:
            k += 1
            label = f"{n} ({k})"
        out.append(label)
    return out


def check_compare(setups: Sequence[Setup], play: Play) -> None:
    """Refuse, before any work, what :func:`compare` cannot play: fewer than two set-ups, or a
    swing the library refuses at one of a set-up's impact points, the maps' or
    ``play.position``, as one impact refuses it
    (:func:`fem_racket.studies.swing_points.check_swing_points`)."""
    if len(setups) < 2:
        raise InputError(f"rackets = {len(setups)} is not allowed: compare needs at least 2")
    for s in setups:
        check_swing_points(s.mesh(), play, s.contact(), [play.position])


def compare(setups: Sequence[Setup], play: Play | None = None) -> list[Report]:
    """One :class:`Report` per set-up, all played alike (at least two set-ups; checked first by
    :func:`check_compare`)."""
    play = play or Play()
    check_compare(setups, play)
    return [report(s, play) for s in setups]


def differences(reports: Sequence[Report]) -> dict[str, dict[str, Any]]:
    """Label of each later set-up -> its scalars minus the first's (None where either is None),
    and its e_A and v_out curves (and face maps) minus the first's on the shared grid."""
    first = reports[0]
    base = first.values()
    out: dict[str, dict[str, Any]] = {}
    for r in reports[1:]:
        if not np.array_equal(r.map.positions, first.map.positions):
            raise InputError("maps = several position grids is not allowed: must share one grid")
        vals = r.values()
        d: dict[str, Any] = {
            k: (None if vals[k] is None or base[k] is None else vals[k] - base[k]) for k in base
        }
        d["apparent_cor_curve"] = (r.map.apparent_cor - first.map.apparent_cor).tolist()
        d["ball_speed_out_curve_m_s"] = (r.map.ball_speed_out - first.map.ball_speed_out).tolist()
        if r.face is not None and first.face is not None:
            d["apparent_cor_face"] = r.face.apparent_cor - first.face.apparent_cor
            d["ball_speed_out_face_m_s"] = r.face.ball_speed_out - first.face.ball_speed_out
        out[r.map.name] = d
    return out
