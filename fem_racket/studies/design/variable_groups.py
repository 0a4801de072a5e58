"""The design variables of each parameter group a design may vary (``vary``).

Groups (:data:`VARY`): "ei" and "rhoa" (one variable per segment or control station, or one
linked variable keeping the starting ratios), "mass" and "position" (each added mass's value and
centre x/L), "string" (the string bed's stiffness: the factor on the paper's K_CB(v) for its
linear law, k_s of the series law) and "string_cubic" (the series law's k_3). Each variable
names its entry of the parameter vector (:mod:`.layout`); EI and string stiffness are searched on
a log scale.
"""

from __future__ import annotations

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.series import SeriesBallString
from fem_racket.studies.design.variables import Variable
from fem_racket.validation import InputError

__all__ = ["VARY", "design_variables"]

#: Parameter groups a design may vary.
VARY = ("ei", "rhoa", "mass", "position", "string", "string_cubic")


def design_variables(
    vary: tuple[str, ...],
    *,
    n_ei: int,
    n_rhoa: int,
    n_masses: int,
    link_ei: bool,
    link_rhoa: bool,
    ei_bounds: tuple[float, float],
    rhoa_bounds: tuple[float, float],
    mass_bounds: tuple[float, float],
    position_bounds: tuple[float, float],
    mass_width: float,
    law: ContactLaw | None,
    law_start: list[float],
    string_bounds: tuple[float, float] | None,
    cubic_bounds: tuple[float, float] | None,
) -> list[Variable]:
    """The variables of the groups in ``vary``, in the order of the parameter vector.

    Parameters
    ----------
    vary : tuple of str
        Groups from :data:`VARY`.
    n_ei, n_rhoa, n_masses : int
        Numbers of EI and rhoA entries and of added masses in the parameter vector.
    link_ei, link_rhoa : bool
        One EI (rhoA) variable, EI_1 (rhoA_1), the others keeping their starting ratios.
    ei_bounds, rhoa_bounds, mass_bounds, position_bounds : (float, float)
        Bounds of every EI [N m^2], rhoA [kg/m], added mass [kg] and centre [x/L].
    mass_width : float
        Width of each added mass's strip [x/L] (narrows ``position_bounds``).
    law : ContactLaw or None
        The ball/string law (None: the paper's linear law).
    law_start : list of float
        The starting values of the law's entries of p.
    string_bounds, cubic_bounds : (float, float) or None
        Bounds of the string-bed variables (None: 0.5-2 and 0-2 times the start).
    """
    n, r, a = n_ei, n_rhoa, n_masses
    variables: list[Variable] = []
    if "ei" in vary:
        if link_ei:
            variables.append(Variable("ei", 0, *ei_bounds, "N m^2", log=True))
        else:
            variables += [Variable(f"ei_{k + 1}", k, *ei_bounds, "N m^2", True) for k in range(n)]
    if "rhoa" in vary and link_rhoa:
        variables.append(Variable("rhoa", n, *rhoa_bounds, "kg/m"))
    elif "rhoa" in vary:
        variables += [Variable(f"rhoa_{k + 1}", n + k, *rhoa_bounds, "kg/m") for k in range(r)]
    if "mass" in vary:
        variables += [Variable(f"mass_{k + 1}", n + r + k, *mass_bounds, "kg") for k in range(a)]
    if "position" in vary:
        bounds = _strip_bounds(position_bounds, mass_width)
        variables += [Variable(f"pos_{k + 1}", n + r + a + k, *bounds, "x/L") for k in range(a)]
    variables += _law_variables(vary, law, law_start, n + r + 2 * a, string_bounds, cubic_bounds)
    return variables


def _strip_bounds(bounds: tuple[float, float], width: float) -> tuple[float, float]:
    """Position bounds x/L narrowed so that the whole strip (``width`` x/L) lies on the frame:
    beyond them the strip is pushed back inside and its position no longer matters."""
    lo, hi = bounds
    if not 0.0 <= lo < hi <= 1.0:
        return lo, hi  # refused by the problem with the bounds as given
    return max(lo, 0.5 * width), min(hi, 1.0 - 0.5 * width)


def _law_variables(
    vary: tuple[str, ...],
    law: ContactLaw | None,
    start: list[float],
    index: int,
    string_bounds: tuple[float, float] | None,
    cubic_bounds: tuple[float, float] | None,
) -> list[Variable]:
    """The string-bed variables: K_CB factor (linear law) or k_s, k_3 (series law)."""
    out: list[Variable] = []
    series = isinstance(law, SeriesBallString)
    if "string" in vary:
        if law is not None and not series:
            raise InputError(
                f"vary = 'string' is not allowed with law {law.name!r}: only the linear and "
                "series laws have a string-bed stiffness"
            )
        lo, hi = (0.5 * start[0], 2.0 * start[0]) if string_bounds is None else string_bounds
        if series:
            out.append(Variable("k_s", index, lo, hi, "N/m", log=True))
        else:
            out.append(Variable("kcb_factor", index, lo, hi, "-", log=True))
    if "string_cubic" in vary:
        if not series:
            raise InputError(
                "vary = 'string_cubic' is not allowed without law 'series': only its string "
                "bed hardens (k_3)"
            )
        default = (0.0, 2.0 * start[1] if start[1] > 0.0 else 1e9)
        lo, hi = default if cubic_bounds is None else cubic_bounds
        out.append(Variable("k_3", index + 1, lo, hi, "N/m^3"))
    return out
