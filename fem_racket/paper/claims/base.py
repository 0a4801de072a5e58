"""A claim of the paper with our value and verdict; helpers to decide the verdict."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["AGREES", "DIFFERS", "NOT_CHECKABLE", "Claim", "below", "claim", "close"]

AGREES, DIFFERS, NOT_CHECKABLE = "agrees", "differs", "not checkable"


@dataclass(frozen=True)
class Claim:
    """One statement of the paper and our verdict on it.

    Attributes
    ----------
    section : str
        Where the paper says it ("2.2", "4.2", "Concl. (1)").
    paper : str
        The statement, quoted or closely paraphrased.
    ours : str
        What this project computes (with units).
    verdict : str
        ``"agrees"``, ``"differs"`` or ``"not checkable"``.
    reason : str
        How it was checked and, when it differs, why.
    figure : str
        Key of the figure holding the evidence (``"fig08"``), or ``""``.
    """

    section: str
    paper: str
    ours: str
    verdict: str
    reason: str
    figure: str = ""


def claim(
    section: str,
    paper: str,
    ours: str,
    ok: bool | None,
    reason: str,
    figure: str = "",
    differs_reason: str = "",
) -> Claim:
    """A :class:`Claim` whose verdict is ``ok`` (None: not checkable); ``differs_reason``
    replaces ``reason`` when the check fails."""
    if ok is None:
        return Claim(section, paper, ours, NOT_CHECKABLE, reason, figure)
    verdict = AGREES if ok else DIFFERS
    return Claim(section, paper, ours, verdict, reason if ok else differs_reason or reason, figure)


def close(ours: float, paper: float, unit: float) -> bool:
    """Equal to within one unit of the paper's last printed digit (plus round-off)."""
    return abs(ours - paper) <= unit * (1.0 + 1e-9)


def below(value: float, floor: float) -> str:
    """``"= 1.2e-05"``, or ``"< 1e-12"`` when ``|value|`` is under ``floor`` (round-off level,
    whose digits would change from machine to machine)."""
    if abs(value) < floor:
        return f"< {floor:.0e}"
    return f"= {value:.1e}"
