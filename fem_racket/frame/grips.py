"""The hand on the grip, its parameters: :class:`Hand` and the two illustrative grips
(:data:`LOOSE_GRIP`, :data:`FIRM_GRIP`; every value an assumption, see
:mod:`fem_racket.frame.hand`, which builds the held structure from them). Plain dataclasses,
no numerics imported, so the command line's ``--grip`` help reads them before any work.
"""

from __future__ import annotations

from dataclasses import dataclass

from fem_racket.validation import InputError, check_finite, check_positive, show

__all__ = ["FIRM_GRIP", "GRIPS", "LOOSE_GRIP", "Hand"]


@dataclass(frozen=True)
class Hand:
    """A rigid hand on the grip (module docstring; every default is an assumption).

    Parameters
    ----------
    mass : float
        m_h [kg].
    grip_start, grip_end : float
        The handle length the hand covers, from the butt [m].
    stiffness : float
        k' of the grip layer [N/m per m of handle], >= 0.
    damping : float
        c' of the grip layer [N s/m per m of handle], >= 0.
    inertia : float, optional
        I_h about the hand's centre [kg m^2]; a uniform rod over the grip when None.
    """

    mass: float = 0.45
    grip_start: float = 0.02
    grip_end: float = 0.12
    stiffness: float = 1e5
    damping: float = 100.0
    inertia: float | None = None

    def __post_init__(self) -> None:
        check_positive("hand mass", self.mass, "kg")
        a = check_finite("grip_start", self.grip_start, "m")
        b = check_finite("grip_end", self.grip_end, "m")
        if not 0.0 <= a < b:
            raise InputError(
                f"grip = ({a:g}, {b:g}) m is not allowed: must satisfy 0 <= grip_start < grip_end"
            )
        for name, v, unit in (
            ("grip stiffness", self.stiffness, "N/m^2"),
            ("grip damping", self.damping, "N s/m^2"),
        ):
            if not check_finite(name, v, unit) >= 0.0:
                raise InputError(
                    f"{name} = {show(v)} {unit} is not allowed: must be >= 0",
                    parameter=name,
                    value=v,
                )
        if self.inertia is not None:
            check_positive("hand inertia", self.inertia, "kg m^2")

    @property
    def centre(self) -> float:
        """x_h [m]."""
        return 0.5 * (self.grip_start + self.grip_end)

    @property
    def rotary_inertia(self) -> float:
        """I_h [kg m^2]."""
        length = self.grip_end - self.grip_start
        return self.mass * length**2 / 12.0 if self.inertia is None else self.inertia


#: Illustrative loose and firm grips (assumptions: :mod:`fem_racket.frame.hand`'s docstring).
LOOSE_GRIP = Hand(stiffness=1e5, damping=100.0)
FIRM_GRIP = Hand(stiffness=3e5, damping=1000.0)
#: The presets by name.
GRIPS = {"loose": LOOSE_GRIP, "firm": FIRM_GRIP}
