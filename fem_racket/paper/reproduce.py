"""Reproduce every analysis of Kawazoe & Kanda (1997): all figures, their data and a report.

:func:`reproduce` computes each figure of :data:`fem_racket.paper.figures.FIGURES`, writes its CSV
tables and figure (PNG by default, or SVG, PDF) into an output folder, writes ``values.json``
(every scalar and the list of files, with provenance) there, and writes a Markdown report
(``REPRODUCTION.md``) setting each statement of the paper beside our value and a verdict
(:mod:`fem_racket.paper.claims`). The report links the figures by paths relative to its own
folder, so a report at the repository root shows the figures of ``output/paper/`` (committed, so
that it reads well right after ``git clone``).

With a contact ``law`` (``reproduce(..., law="kawazoe-1997-nonlinear")``) the figures are drawn
with that law instead of the paper's per-speed linear K_CB, those that have no meaning under it
are left out with the reason, and the report is the law's
(:func:`fem_racket.paper.law_report.render_law_report`): conclusions (1)-(4) re-checked and the
contact times against the paper's 6-3 ms. Its outputs belong in their own folder (the command's
default: ``output/paper/<law>/``).

Its own earlier outputs are replaced without ``overwrite`` (recognised by their provenance,
:func:`fem_racket.outputs.owned.written_by_fem_racket`); any other existing file is refused before
any work unless ``overwrite``.
"""

from __future__ import annotations

import json
import logging
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.display import number, short_repr
from fem_racket.io.figure_files import DEFAULT_DPI, check_dpi, check_figure_format
from fem_racket.outputs import Target, atomic_outputs, provenance
from fem_racket.paper.claims import AGREES, DIFFERS, NOT_CHECKABLE, Claim, build_claims
from fem_racket.paper.claims.conclusions import conclusion_claims, contact_time_claim
from fem_racket.paper.figures import (
    FIGURES,
    FigureData,
    expected_files,
    used_settings,
    write_figure_into,
)
from fem_racket.paper.law_report import render_law_report
from fem_racket.paper.owned import check_replaceable
from fem_racket.paper.report import render_report
from fem_racket.progress import progress_bar
from fem_racket.validation import InputError

__all__ = ["Reproduction", "render_report", "reproduce"]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Reproduction:
    """What :func:`reproduce` did.

    Attributes
    ----------
    figures : dict of str to FigureData
    claims : list of Claim
    files : list of Path
        Every file written (figure data and PNGs, values.json, the report).
    seconds : dict of str to float
        Wall time of each figure (compute + write) [s].
    """

    figures: dict[str, FigureData]
    claims: list[Claim]
    files: list[Path]
    seconds: dict[str, float]

    def __repr__(self) -> str:
        c = self.counts()
        return short_repr(
            "Reproduction",
            [
                ("figures", str(len(self.figures))),
                ("claims", f"{len(self.claims)} ({c[AGREES]} agree, {c[DIFFERS]} differ, "
                 f"{c[NOT_CHECKABLE]} not checkable)"),
                ("files", str(len(self.files))),
                ("seconds", number(sum(self.seconds.values()), 3)),
            ],
        )  # fmt: skip

    def counts(self) -> dict[str, int]:
        """Number of claims per verdict."""
        return {
            k: sum(c.verdict == k for c in self.claims) for k in (AGREES, DIFFERS, NOT_CHECKABLE)
        }


def _same_report(path: Path, text: str) -> bool:
    """True if the report at ``path`` says ``text`` (its closing provenance comment aside)."""
    try:
        old = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    return old[: old.rfind("\n<!-- provenance: ")] == text


def _claims(values: dict[str, dict[str, float]], law: ContactLaw | None) -> list[Claim]:
    """The report's claims: every statement of the paper (its linear law), or under another
    law conclusions (1)-(4) and the contact-time statement."""
    if law is None:
        return build_claims(values)
    return [*conclusion_claims(values), contact_time_claim(values)]


def reproduce(
    out_dir: str | os.PathLike,
    report: str | os.PathLike | None = None,
    *,
    quick: bool = False,
    overwrite: bool = False,
    figures: list[str] | None = None,
    parameters: dict[str, Any] | None = None,
    fmt: str = "png",
    dpi: float = DEFAULT_DPI,
    progress: bool | None = None,
    law: ContactLaw | str | None = None,
) -> Reproduction:
    """Compute every figure, write data + figures + ``values.json`` to ``out_dir``, and the report.

    Parameters
    ----------
    out_dir : path
        Folder for the figures' data and PNGs (created if needed).
    report : path, optional
        Markdown report to write (e.g. ``REPRODUCTION.md``); none when None.
    quick : bool
        Coarse grids (for tests); the report says so.
    overwrite : bool
        Replace any existing file. Otherwise only the files an earlier reproduction wrote (its
        figures, CSVs listed in its ``values.json``, ``values.json``, the report: recognised by
        their provenance) are replaced, and any other existing output is an error, raised
        before any computation.
        Every file - figures, CSVs, ``values.json``, the report - is written after all figures
        are computed, as one set: all of them or, on any failure or interruption, none (old
        files kept); every destination is checked before the work.
    figures : list of str, optional
        Subset of :data:`fem_racket.paper.figures.FIGURES` keys; all by default (a report needs
        all).
    parameters : dict, optional
        Extra provenance (e.g. the command's options), in ``values.json``, every figure's
        metadata and a comment at the end of the report. Every provenance also records what
        the figures used (``"used"``: :func:`fem_racket.paper.figures.used_settings`).
    fmt : {"png", "svg", "pdf"}
        Format of the figures (the report shows PNG and SVG, and links PDF).
    dpi : float
        Resolution of the figures [dots per inch].
    progress : bool or None
        A progress bar over the whole work on stderr, naming its phase: computing each
        figure, checking the statements, drawing each figure (None: when stderr is a terminal).
    law : ContactLaw or str, optional
        Draw the figures with this contact law (or the law of that name,
        :data:`fem_racket.contact.presets.LAW_NAMES`) instead of the paper's linear K_CB;
        None or ``"linear"``: the paper's. Figures without meaning under a law
        (:attr:`FigureSpec.law_skip`) are left out, and the report is the law's
        (:func:`fem_racket.paper.law_report.render_law_report`). Every provenance records the
        law (``"law"``, and its parameters under ``"used"``).
    """
    from fem_racket.contact.presets import get_law
    from fem_racket.paper.figures.law_runs import law_title
    from fem_racket.validation import check_choice, work_begins

    if isinstance(law, str):
        law = get_law(law)
    drawable = [k for k in FIGURES if law is None or not FIGURES[k].law_skip]
    keys = (
        list(drawable) if figures is None else [check_choice("figure", k, FIGURES) for k in figures]
    )
    for k in keys:
        if k not in drawable:
            raise InputError(
                f"figure = {k!r} is not allowed with law {law_title(law)!r}: {FIGURES[k].law_skip}"
            )
    if report is not None and set(keys) != set(drawable):
        raise InputError("figures is not allowed with a report: the report needs every figure")
    fmt = check_figure_format(fmt)
    dpi = check_dpi(dpi)
    out = Path(out_dir)
    groups = {k: expected_files(FIGURES[k], out, fmt) for k in keys}
    written = [p for paths in groups.values() for p in paths]
    targets = [Target(p, name="out") for p in [*written, out / "values.json"]]
    if report is not None:
        targets.append(Target(Path(report), name="report"))
    check_replaceable(targets, overwrite=overwrite)
    work_begins()
    described = {"law": "linear"} if law is None else {**law.describe(), "name": law_title(law)}
    meta = provenance(
        {"quick": quick, "figures": keys, "format": fmt, "dpi": dpi, **(parameters or {})}
    )
    meta["law"] = described
    meta["used"] = used_settings(law)
    done: dict[str, FigureData] = {}
    seconds: dict[str, float] = {}
    # One bar over the whole work, its phase named: computing each figure, checking the
    # statements, drawing each figure (the drawing takes most of the time).
    bar = progress_bar(total=2 * len(keys) + (report is not None), unit="step", enabled=progress)
    for key in keys:
        bar.set_description_str(f"reproduce: computing {key}")
        t0 = time.perf_counter()
        done[key] = FIGURES[key].compute(quick, law)
        seconds[key] = time.perf_counter() - t0
        log.info("%s: %.2f s", key, seconds[key])
        bar.update()
    values = {k: d.values for k, d in done.items()}
    listing = [p.name for p in written]
    claims = []
    if report is not None:
        bar.set_description_str("reproduce: checking the statements")
        claims = _claims(values, law)
        bar.update()
    # Every file of the reproduction moved into place together (check_replaceable above did the
    # --overwrite check: what remains is ours to replace); unchanged ones are left as they are.
    with atomic_outputs(targets, overwrite=True) as temps:
        pending = iter(temps)
        for key, paths in groups.items():
            bar.set_description_str(f"reproduce: drawing {key}")
            t0 = time.perf_counter()
            mine = [next(pending) for _ in paths]
            write_figure_into(
                FIGURES[key], done[key], mine, paths, meta, dpi=dpi, keep_unchanged=True
            )
            seconds[key] += time.perf_counter() - t0
            bar.update()
        bar.close()
        listed = {"provenance": meta, "files": listing, "values": values}
        next(pending).write_text(json.dumps(listed, indent=1))
        if report is not None:
            rel = os.path.relpath(out.resolve(), Path(report).resolve().parent).replace(os.sep, "/")
            if law is None:
                text = render_report(done, claims, rel, quick=quick, fmt=fmt)
            else:
                text = render_law_report(
                    law_title(law), law, done, claims, values, rel, quick=quick, fmt=fmt
                )
            tmp = next(pending)
            if _same_report(Path(report), text):
                tmp.unlink()  # left as it is
            else:
                stamp = f"\n<!-- provenance: {json.dumps(meta, sort_keys=True, default=str)} -->\n"
                tmp.write_text(text + stamp)
    files = [*written, out / "values.json"] + ([Path(report)] if report is not None else [])
    return Reproduction(done, claims, files, seconds)
