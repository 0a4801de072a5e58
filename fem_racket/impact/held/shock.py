"""Handle shock: what the hand feels of an impact, from the held racket's exact grip force.

The grip force on the hand F_h(t) (:mod:`fem_racket.impact.held.modal`: during contact and in
the free vibration after it) is split into its rigid part, the push that carries the hand along
with a rigid racket (ending at separation), and its vibration part F_v = F_h - rigid (the
frame's bending and the hand's own motion on the grip layer). Two measures over a window
[0, T] from the start of contact:

- peak grip force ``max |F_h(t)|`` [N] (the shock's peak; Hatze 1976 measured grip forces);
- vibration RMS ``sqrt((1/T) int_0^T F_v(t)^2 dt)`` [N], i.e. the vibration energy
  ``int F_v^2 dt`` [N^2 s] per unit time: the RMS measure of hand-arm vibration exposure
  (ISO 5349-1), applied here to the force on the hand, without the standard's frequency
  weighting. Racket vibrations reach the forearm at the frame's first modes (Hennig, Rosenbaum
  & Milani 1992, Med. Sci. Sports Exerc. 24) and last tens of milliseconds, so the default
  window T = 50 ms (an assumption) spans ~6 periods of the 120-150 Hz first mode.

Each phase is a sum of exponentials F_v = Re sum_j w_j exp(lambda_j s), real, so its energy
over a phase of length tau is exact::

    int_0^tau F_v^2 ds = Re sum_jk w_j w_k (exp(s_jk tau) - 1) / s_jk,   s_jk = lambda_j + lambda_k

The peak is the largest |F_h| on a grid of :data:`GRID` points per contact time, refined on a
grid 128 times finer around it.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.constants import DEFAULT_WINDOW
from fem_racket.impact.held.modal import HeldContact
from fem_racket.validation import InputError, show

__all__ = ["DEFAULT_WINDOW", "contact_peak", "grip_peak", "vibration_energy", "vibration_rms"]

#: Grid points per contact time of the peak search.
GRID = 256


def _energy(lam: np.ndarray, w: np.ndarray, tau: float) -> float:
    """int_0^tau (Re sum_j w_j exp(lambda_j s))^2 ds for a real signal (module docstring)."""
    z = lam[:, None] + lam[None, :]
    with np.errstate(invalid="ignore", divide="ignore"):
        e = np.where(z == 0.0, tau, np.expm1(z * tau) / z)
    return float(np.real(w @ e @ w))


def _check_window(c: HeldContact, window: float) -> float:
    if not window > c.contact_time:
        raise InputError(
            f"window = {show(window)} s is not allowed: must exceed the contact time "
            f"({c.contact_time:.4g} s)"
        )
    return float(window)


def vibration_energy(c: HeldContact, window: float = DEFAULT_WINDOW) -> float:
    """int_0^T F_v^2 dt [N^2 s] of the grip force's vibration part over the window T [s]."""
    t = _check_window(c, window)
    return _energy(c.lam, c.vib, c.contact_time) + _energy(c.mu, c.free, t - c.contact_time)


def vibration_rms(c: HeldContact, window: float = DEFAULT_WINDOW) -> float:
    """RMS of the grip force's vibration part over the window T [s]: sqrt(energy / T) [N]."""
    return float(np.sqrt(max(vibration_energy(c, window), 0.0) / window))


def _on_grid(lam: np.ndarray, w: np.ndarray, t0: float, dt: float, num: int) -> np.ndarray:
    """Re sum_j w_j exp(lambda_j (t0 + k dt)), k < num (powers by repeated doubling)."""
    E = np.empty((num, lam.size), dtype=complex)
    E[0] = np.exp(lam * t0)
    power, filled = np.exp(lam * dt), 1
    while filled < num:
        m = min(filled, num - filled)
        np.multiply(E[:m], power, out=E[filled : filled + m])
        filled += m
        power = power * power
    return np.real(E @ w)


def _peak(lam: np.ndarray, w: np.ndarray, tau: float, step: float) -> float:
    """max |Re sum_j w_j exp(lambda_j s)| over [0, tau]: a grid of ``step``, then a zoom."""
    num = max(int(np.ceil(tau / step)), 2) + 1
    dt = tau / (num - 1)
    i = int(np.argmax(np.abs(_on_grid(lam, w, 0.0, dt, num))))
    lo, hi = max(i - 1, 0) * dt, min(i + 1, num - 1) * dt
    return float(np.max(np.abs(_on_grid(lam, w, lo, (hi - lo) / 256, 257))))


def grip_peak(c: HeldContact, window: float | None = DEFAULT_WINDOW) -> float:
    """Largest |F_h| [N] over [0, T] (the contact only when ``window`` is None)."""
    step = c.contact_time / GRID
    peak = _peak(c.lam, c.vib + c.rigid, c.contact_time, step)
    if window is not None:
        t = _check_window(c, window)
        peak = max(peak, _peak(c.mu, c.free, t - c.contact_time, step))
    return peak


def contact_peak(c: HeldContact) -> float:
    """Largest contact force |F| [N] during the contact."""
    return _peak(c.lam, c.force, c.contact_time, c.contact_time / GRID)
