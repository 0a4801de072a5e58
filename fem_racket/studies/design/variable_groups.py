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
from fem_racket.studies.design.options import VariableOptions
from fem_racket.studies.design.variables import Variable
from fem_racket.validation import InputError

__all__ = ["VARY", "design_variables"]

#: Parameter groups a design may vary.
VARY = ("ei", "rhoa", "mass", "position", "string", "string_cubic")


def design_variables(
    options: VariableOptions,
    layout: tuple[int, int, int],
    length: float,
    law: ContactLaw | None,
    law_start: list[float],
) -> list[Variable]:
    """The variables of the groups in ``options.vary``, in the order of the parameter vector.

    Parameters
    ----------
    options : VariableOptions
        The groups varied (:data:`VARY`), linked EI or rhoA, the bounds of every EI [N m^2],
        rhoA [kg/m], added mass [kg], centre [x/L] and string-bed variable (None: 0.5-2 and
        0-2 times the start), the added masses' strip width [m] (narrows the centres' bounds).
    layout : (int, int, int)
        Numbers of EI and rhoA entries and of added masses in the parameter vector.
    length : float
        Length L of the frame [m].
    law : ContactLaw or None
        The ball/string law (None: the paper's linear law).
    law_start : list of float
        The starting values of the law's entries of p.
    """
    o, (n, r, a) = options, layout
    variables: list[Variable] = []
    if "ei" in o.vary:
        if o.link_ei:
            variables.append(Variable("ei", 0, *o.ei_bounds, "N m^2", log=True))
        else:
            variables += [Variable(f"ei_{k + 1}", k, *o.ei_bounds, "N m^2", True) for k in range(n)]
    if "rhoa" in o.vary and o.link_rhoa:
        variables.append(Variable("rhoa", n, *o.rhoa_bounds, "kg/m"))
    elif "rhoa" in o.vary:
        variables += [Variable(f"rhoa_{k + 1}", n + k, *o.rhoa_bounds, "kg/m") for k in range(r)]
    if "mass" in o.vary:
        variables += [Variable(f"mass_{k + 1}", n + r + k, *o.mass_bounds, "kg") for k in range(a)]
    if "position" in o.vary:
        bounds = _strip_bounds(o.position_bounds, o.mass_width / length)
        variables += [Variable(f"pos_{k + 1}", n + r + a + k, *bounds, "x/L") for k in range(a)]
    variables += _law_variables(o, law, law_start, n + r + 2 * a)
    return variables


def _strip_bounds(bounds: tuple[float, float], width: float) -> tuple[float, float]:
    """Position bounds x/L narrowed so that the whole strip (``width`` x/L) lies on the frame:
    beyond them the strip is pushed back inside and its position no longer matters."""
    lo, hi = bounds
    if not 0.0 <= lo < hi <= 1.0:
        return lo, hi  # refused by the problem with the bounds as given
    return max(lo, 0.5 * width), min(hi, 1.0 - 0.5 * width)


def _law_variables(
    options: VariableOptions, law: ContactLaw | None, start: list[float], index: int
) -> list[Variable]:
    """The string-bed variables: K_CB factor (linear law) or k_s, k_3 (series law)."""
    out: list[Variable] = []
    series = isinstance(law, SeriesBallString)
    vary, string_bounds, cubic_bounds = options.vary, options.string_bounds, options.cubic_bounds
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
