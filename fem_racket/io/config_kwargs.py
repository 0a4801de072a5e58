"""A run file's impact as keywords of :func:`fem_racket.simulate`
(:meth:`~fem_racket.io.config_file.RunFile.simulate_kwargs`), or a refusal naming the keys that
keywords cannot carry.

``fem_racket.simulate(**kw)`` takes the impact point, the ball, the contact law and the solver's
options from keywords; the file's frame (beyond ``frame.elements``), swing, hand, string bed,
oblique ball and ``[simulate] output_step`` are objects :meth:`RunConfig.simulate` builds. A file
setting any of those to other than its default is refused rather than dropped (the keywords
gave another COR than ``.simulate()`` and the CLI, silently); a key at its default changes
nothing, as on the command line.
"""

from __future__ import annotations

from typing import Any

from fem_racket.io.config_defaults import DEFAULT_STEP, given
from fem_racket.io.config_named import file_keys
from fem_racket.validation import InputError, show

__all__ = ["KEYWORDS", "keyword_law", "simulate_keywords"]

#: The argparse dests of the core tables that are keywords of :func:`fem_racket.simulate` under
#: the same name (the contact table's law and its parameters make ``law``).
KEYWORDS = (
    "position",
    "offset",
    "speed",
    "ball_mass",
    "kcb",
    "zeta",
    "elements",
    "solver",
    "separation",
    "basis",
    "modes",
    "tolerance",
    "rtol",
    "atol",
    "t_max",
)


def simulate_keywords(cfg: Any) -> dict[str, Any]:
    """The keywords of :func:`fem_racket.simulate` the run file ``cfg`` (a RunFile) sets.

    Raises
    ------
    InputError
        The file sets a key keywords cannot carry (module docstring), in one line naming the
        keys and pointing to ``load_config(path).simulate()``.
    """
    d = cfg.defaults()
    keys = file_keys(cfg.values)
    carried = set(KEYWORDS) | {dest for dest, key in keys.items() if key.startswith("contact.")}
    carried |= {dest for dest, key in keys.items() if key.startswith("output.")}
    left = sorted(keys[dest] for dest in given(d) - carried if dest in keys)
    shown = [f"{key} = {show(cfg.get(key))}" for key in left]
    step = cfg.table("simulate").get("output_step", DEFAULT_STEP)
    shown += [f"simulate.output_step = {show(step)}"] if step != DEFAULT_STEP else []
    if shown:
        where = f" ({cfg.source})" if cfg.source is not None else ""
        raise InputError(
            f"{', '.join(shown)}{where} is not allowed in simulate_kwargs(): fem_racket.simulate's "
            "keywords cannot carry it; use load_config(path).simulate(), which applies every table"
        )
    out = {n: d[n] for n in KEYWORDS if n in d}
    law = keyword_law(d)
    return out if law is None else out | {"law": law}


def keyword_law(d: dict[str, Any]) -> Any:
    """The contact law a run file's ``defaults()`` ``d`` names (None when it names none)."""
    if "law" not in d:
        return None
    from fem_racket.contact.presets import get_law, law_parameters

    return get_law(d["law"], **law_parameters(d))
