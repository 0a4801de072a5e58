"""A run file's modal analysis in Python: :meth:`RunConfig.modes` = ``fem-racket modes --config``.

:func:`modes_file` computes what the command reports, from the file's frame (``[frame]`` with
its lead) and ``[modes] count``: the free-free bending modes with their vibration nodes, the mass
properties and catalogue numbers, and, on a frame with torsion data (cell data GJ and rhoIp: the
standard preset, a mesh fitted with a twistweight), the torsion modes. :meth:`RacketModes.summary`
is the command's ``--json`` object.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.display import number, short_repr
from fem_racket.io.config_defaults import FRAME_ELEMENTS
from fem_racket.io.config_tables import Option, integer, table_options
from fem_racket.validation import InputError, work_begins

__all__ = ["MODES_OPTIONS", "RacketModes", "modes_file"]

log = logging.getLogger(__name__)

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any
#: The options of ``[modes]``: dest -> (default, conversion), the command's defaults.
MODES_OPTIONS: dict[str, tuple[Any, Option]] = {"count": (4, integer)}


@dataclass(frozen=True)
class RacketModes:
    """The free-free modal analysis of a frame, everything ``fem-racket modes`` reports.

    Attributes
    ----------
    bending : FreeModes
        The flexible bending modes (:class:`fem_racket.frame.modal.FreeModes`): angular
        frequencies [rad/s], mass-normalised shapes, mass properties (mass [kg], centre of
        gravity [m], inertia about it [kg m^2], length [m]).
    torsion : TorsionModes or None
        The flexible torsion modes (:class:`fem_racket.frame.torsion.TorsionModes`: angular
        frequencies [rad/s], shapes, polar moment I_p [kg m^2]) of a frame with torsion data;
        None without.
    nodes : tuple of ndarray
        The vibration nodes of each bending mode, positions x/L [-] from the butt.
    catalogue : Catalogue
        Length [m], mass [kg], balance [m], swing weight and twistweight [kg m^2]
        (:class:`fem_racket.frame.catalogue.Catalogue`, frequencies not computed).
    elements : int
        Cells of the mesh the modes are computed on.
    """

    bending: Any
    torsion: Any
    nodes: tuple[np.ndarray, ...]
    catalogue: Any
    elements: int

    def __repr__(self) -> str:
        def shown(f: np.ndarray) -> str:
            return "[" + ", ".join(number(v) for v in f) + "] Hz"

        tf = self.torsion_frequencies
        return short_repr(
            "RacketModes",
            [
                ("bending", shown(self.frequencies)),
                ("torsion", "None" if tf is None else shown(tf)),
                ("mass", f"{number(self.props.mass)} kg"),
                ("elements", str(self.elements)),
            ],
        )

    @property
    def frequencies(self) -> np.ndarray:
        """The bending frequencies [Hz], ascending (as ``FreeModes.frequencies``)."""
        return self.bending.frequencies

    @property
    def props(self) -> Any:
        """The mass properties (as ``FreeModes.props``)."""
        return self.bending.props

    @property
    def torsion_frequencies(self) -> np.ndarray | None:
        """The torsion frequencies [Hz], ascending; None for a frame without torsion data."""
        return None if self.torsion is None else self.torsion.frequencies

    def summary(self) -> dict[str, Any]:
        """The object ``fem-racket modes --json`` prints: units in the keys (swing and twist
        weight in kg cm^2 as quoted; the torsion keys only with torsion data)."""
        props, specs = self.props, self.catalogue.as_dict()
        data = {
            "mass_kg": props.mass,
            "cg_x_over_l": props.cg_over_length,
            "cg_m": props.cg,
            "swing_weight_kg_cm2": specs["swing_weight_kg_cm2"],
            "twist_weight_kg_cm2": specs["twist_weight_kg_cm2"],
            "inertia_cg_kg_m2": props.inertia,
            "length_m": props.length,
            "elements": self.elements,
            "frequencies_hz": self.frequencies.tolist(),
            "nodes_x_over_l": [n.tolist() for n in self.nodes],
        }
        if self.torsion is not None:
            data["polar_moment_kg_m2"] = self.torsion.polar_moment
            data["twist_weight_kg_cm2"] = self.torsion.polar_moment * 1e4
            data["torsion_frequencies_hz"] = self.torsion.frequencies.tolist()
        return data


def modes_file(cfg: RunConfig) -> RacketModes:
    """The modal analysis ``fem-racket modes --config`` reports on the file's frame: ``[modes]
    count`` flexible bending modes (4 by default; fewer when the mesh has fewer, noted in the
    log as the command notes it) and as many torsion modes where the frame has torsion data."""
    from fem_racket.frame.catalogue import catalogue
    from fem_racket.frame.modal import mode_nodes
    from fem_racket.frame.model import FrameModel
    from fem_racket.io.config_run import file_frame

    count = table_options(cfg, "modes", MODES_OPTIONS)["count"]
    if count < 1:
        raise InputError(f"count = {count} is not allowed: must be an integer >= 1")
    model = FrameModel.build(file_frame(cfg), cfg.defaults().get("elements", FRAME_ELEMENTS))
    work_begins()
    fm = model.modes(count)
    n = model.mesh.n_elements
    if fm.omega.size < count:
        shown = fm.omega.size
        log.info("count = %d: the %d-element mesh has %d flexible modes; showing %d",
                 count, n, shown, shown)  # fmt: skip
    nodes = tuple(mode_nodes(model.fe, fm.shapes[:, k]) for k in range(fm.omega.size))
    torsion = model.torsion.modes(count) if model.mesh.has_torsion else None
    return RacketModes(fm, torsion, nodes, catalogue(model.mesh, f1=False), n)
