"""What bends or twists a uniform piece of the frame, and what it may be: :class:`Rigidity`.

A piece's frequencies scale as sqrt(rigidity / mass) / L^2 (bending: EI / rhoA) or
sqrt(rigidity / mass) / L (torsion: GJ / rhoIp); each kind bounds that ratio
(:data:`fem_racket.frame.segments.BENDING`, :data:`~fem_racket.frame.segments.TORSION`) and
states the bounds in one message shape.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from fem_racket.validation import InputError, check_positive, show

__all__ = ["Rigidity"]


@dataclass(frozen=True)
class Rigidity:
    """A kind of rigidity of a uniform piece, the mass it drives and their allowed ratio.

    Attributes
    ----------
    name : str
        The rigidity's field and name in messages (``"EI"``, ``"GJ"``) [N m^2].
    density : str
        The mass field it drives (``"rhoA"``, ``"rhoIp"``).
    density_unit : str
        Unit of the mass field (``"kg/m"``, ``"kg m"``).
    ratio_unit : str
        Unit of rigidity / mass (``"m^4/s^2"``, ``"m^2/s^2"``).
    ratio_range : tuple of float
        Allowed rigidity / mass (:data:`~fem_racket.frame.segments.EI_RANGE`,
        :data:`~fem_racket.frame.segments.GJ_RANGE`).
    """

    name: str
    density: str
    density_unit: str
    ratio_unit: str
    ratio_range: tuple[float, float]

    def check(self, label: str, rigidity: float, density: float) -> float:
        """Return ``rigidity`` [N m^2] if rigidity / ``density`` lies in :attr:`ratio_range`,
        else raise naming ``label``."""
        low, high = self.ratio_range[0] * density, self.ratio_range[1] * density
        if not low <= rigidity <= high:
            raise InputError(
                f"{label} = {show(rigidity)} N m^2 is not allowed with {self.density} = "
                f"{density:g} {self.density_unit}: must lie in [{low:.3g}, {high:.3g}] N m^2 "
                f"({self.name} / {self.density} in [{self.ratio_range[0]:g}, "
                f"{self.ratio_range[1]:g}] {self.ratio_unit})",
                parameter=label,
                value=rigidity,
            )
        return rigidity

    def check_piece(self, piece: Any) -> None:
        """Check and store (as floats) the length [m], rigidity and mass of ``piece`` (a frozen
        :class:`~fem_racket.frame.segments.Segment` or ``TorsionSegment``, in its
        ``__post_init__``): each > 0, and their ratio within :attr:`ratio_range`."""
        object.__setattr__(piece, "length", check_positive("segment length", piece.length, "m"))
        rigidity = check_positive(self.name, getattr(piece, self.name), "N m^2")
        density = check_positive(self.density, getattr(piece, self.density), self.density_unit)
        object.__setattr__(piece, self.name, rigidity)
        object.__setattr__(piece, self.density, density)
        self.check(self.name, rigidity, density)
