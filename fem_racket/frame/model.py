"""A frame ready for impacts: mesh, assembled matrices and (lazily) its free-free modes.

Build it once and pass it to :func:`~fem_racket.impact.simulate` many times; sweeps over frame
rigidity reuse it through :meth:`FrameModel.scaled`, which scales K and the modal frequencies
without re-assembling or re-solving the eigenproblem.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from fem_racket.display import number, short_repr, span
from fem_racket.frame.constants import DEFAULT_MODES
from fem_racket.frame.fe import FrameFE
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import FrameMesh, frame_mesh
from fem_racket.frame.modal import FreeModes, MassProperties, free_modes, mass_properties
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.validation import InputError, check_positive, show

if TYPE_CHECKING:
    from fem_racket.frame.torsion import TorsionModel

__all__ = ["DEFAULT_MODES", "FrameModel"]


@dataclass(eq=False)
class FrameModel:
    """Assembled frame with cached free-free modes.

    Attributes
    ----------
    fe : FrameFE
        Mesh, basis, K and M.
    """

    fe: FrameFE
    _modes: dict[int, FreeModes] = field(default_factory=dict, repr=False)
    _torsion: TorsionModel | None = field(default=None, repr=False)

    @classmethod
    def build(cls, frame: Frame | FrameMesh | None = None, elements: int = 20) -> FrameModel:
        """Mesh (if given a :class:`Frame`) and assemble (closed-form element matrices, exact
        to round-off on any mesh: :mod:`fem_racket.frame.hermite`).

        Parameters
        ----------
        frame : Frame or FrameMesh, optional
            The paper's standard racket when None.
        elements : int
            Number of cells when meshing a :class:`Frame`; ignored for a :class:`FrameMesh`.
        """
        if frame is None:
            frame = standard_frame()
        if isinstance(frame, Frame):
            mesh = frame_mesh(frame, elements)
        elif isinstance(frame, FrameMesh):
            mesh = frame
        else:
            raise InputError(
                f"frame = {show(frame)} is not allowed: must be a Frame or a FrameMesh"
            )
        return cls(assemble_closed_form(mesh))

    def __repr__(self) -> str:
        props = self.props
        cached = sorted(m.omega.size for m in self._modes.values())
        return short_repr(
            "FrameModel",
            [
                ("cells", str(self.mesh.n_elements)),
                ("length", f"{number(self.mesh.length)} m"),
                ("mass", f"{number(props.mass)} kg"),
                ("cg", f"{number(props.cg_over_length, 4)} L"),
                ("EI", span(self.mesh.EI, "N m^2")),
                ("modes_computed", str(cached)),
            ],
        )

    @property
    def mesh(self) -> FrameMesh:
        """The frame mesh."""
        return self.fe.mesh

    @property
    def props(self) -> MassProperties:
        """Mass, centre of gravity and inertia."""
        return mass_properties(self.fe)

    def modes(self, n_modes: int | None = DEFAULT_MODES) -> FreeModes:
        """The lowest ``n_modes`` flexible free-free modes (all when None), cached."""
        n_flex = self.fe.ndof - 2
        n = n_flex if n_modes is None else min(int(n_modes), n_flex)
        for have, m in self._modes.items():
            if have >= n:
                return m.truncated(n)
        m = free_modes(self.fe, n)
        self._modes[n] = m
        return m

    @property
    def torsion(self) -> TorsionModel:
        """The frame in torsion (:mod:`fem_racket.frame.torsion`), built once; refuses a mesh
        without cell data GJ and rhoIp."""
        if self._torsion is None:
            from fem_racket.frame.torsion import TorsionModel

            self._torsion = TorsionModel(self.mesh)
        return self._torsion

    def scaled(self, ei_factor: float) -> FrameModel:
        """The same frame with every EI multiplied by ``ei_factor`` (modes reused; torsion
        unchanged)."""
        f = check_positive("ei_factor", ei_factor)
        fe = FrameFE(self.fe.mesh.scaled(f), self.fe.K_bands * f, self.fe.M_bands)
        return FrameModel(fe, {n: m.scaled(f) for n, m in self._modes.items()}, self._torsion)
