"""Reproduce every analysis of Kawazoe & Kanda (1997): all figures, their data and a report.

:func:`reproduce` computes each figure of :data:`fem_racket.figures.FIGURES`, writes its CSV
tables and figure (PNG by default, or SVG, PDF) into an output folder, writes ``values.json``
(every scalar and the list of files, with provenance) there, and writes a Markdown report
(``REPRODUCTION.md``) setting each statement of the paper beside our value and a verdict
(:mod:`fem_racket.paper.claims`). The report links the figures by paths relative to its own
folder, so a report at the repository root shows the figures of ``output/paper/`` (committed, so
that it reads well right after ``git clone``).

Its own earlier outputs are replaced without ``overwrite`` (recognised by their provenance,
:func:`fem_racket.paper.owned.written_by_fem_racket`); any other existing file is refused before
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

from fem_racket.display import number, short_repr
from fem_racket.io.figure_files import DEFAULT_DPI, check_dpi, check_figure_format
from fem_racket.outputs import atomic_output, check_output_path, provenance
from fem_racket.paper.claims import AGREES, DIFFERS, NOT_CHECKABLE, Claim, build_claims
from fem_racket.paper.figures import (
    FIGURES,
    FigureData,
    expected_files,
    used_settings,
    write_figure,
)
from fem_racket.paper.owned import written_by_fem_racket
from fem_racket.progress import progress_bar
from fem_racket.validation import InputError

__all__ = ["Reproduction", "render_report", "reproduce"]

log = logging.getLogger(__name__)

#: Paper section of each figure (the report shows a figure after its section's table).
SECTION_OF = {
    "fig02_03": "2",
    "fig04": "2",
    "fig05": "3",
    "fig06": "3",
    "fig07": "3",
    "fig08": "3",
    "fig09": "3",
    "fig11": "4",
    "fig12": "4",
    "fig13": "5",
}
SECTIONS = {
    "2": "2. Impact model (Figs 2-4)",
    "3": "3. Simulation results (Figs 5-9)",
    "4": "4. Rigid-frame and modal analysis (eqs 5-16, Figs 11-12)",
    "5": "5. Frame rigidity (Fig. 13)",
    "6": "6. Conclusions (1)-(4)",
}


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


def _section(c: Claim) -> str:
    if c.section.startswith("Concl"):
        return "6"
    head = c.section[0]
    return "2" if head == "1" else head


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _figure_link(title: str, path: str) -> str:
    """Markdown that shows a PNG or SVG, and links a PDF (which a Markdown viewer cannot show)."""
    if path.endswith(".pdf"):
        return f"[{title} (PDF)]({path})"
    return f"![{title}]({path})"


def _check_targets(targets: list[Path], overwrite: bool) -> None:
    """Before any work: every existing target must be one of our own outputs, or ``overwrite``."""
    for p in targets:
        if overwrite or not p.exists() or p.is_dir() or written_by_fem_racket(p):
            check_output_path(p, overwrite=True)  # a folder, an unwritable place
            continue
        raise InputError(
            f"output = '{p}' already exists and is not a file fem-racket reproduce wrote "
            "(no fem_racket provenance in it): pass --overwrite to replace it"
        )


def render_report(
    figures: dict[str, FigureData],
    claims: list[Claim],
    image_dir: str,
    *,
    quick: bool = False,
    fmt: str = "png",
) -> str:
    """The Markdown report; ``image_dir`` is the figures' folder relative to the report, ``fmt``
    their format (a PDF is linked, PNG and SVG are shown)."""
    counts = {k: sum(c.verdict == k for c in claims) for k in (AGREES, DIFFERS, NOT_CHECKABLE)}
    img = image_dir.rstrip("/") or "."
    lines = [
        "# Reproduction of Kawazoe & Kanda (1997)",
        "",
        "Generated by `fem-racket reproduce`; do not edit by hand. Each statement of sections "
        "2-6 and conclusions (1)-(4) of the paper (JSME Int. J. C 40(1), 1997) is set beside the "
        "value this project computes, with a verdict. The check behind every verdict is in "
        "`fem_racket/claims/`; the numbers come from `fem_racket/figures/`.",
        "",
        f"**{len(claims)} statements: {counts[AGREES]} agree, {counts[DIFFERS]} differ, "
        f"{counts[NOT_CHECKABLE]} cannot be checked.**",
        "",
        "**Regenerate**: from the repository root (about 15 s here),",
        "",
        "```bash",
        "fem-racket reproduce          # or: python -m fem_racket reproduce",
        "```",
        "",
        f"This writes the figures, one CSV per table (units in the column names) and "
        f"`values.json` into `{img}/`, and rewrites this file. The PNGs are committed (so this "
        f"page shows them right after `git clone`), the CSVs and `values.json` are not. It "
        f"replaces the files it wrote before (recognised by their provenance), never another "
        f"file (`--overwrite` forces that). `--out DIR` picks another folder (the image links "
        f"follow it), `--format svg|pdf` and `--dpi N` the figures' format and resolution, "
        f"`--quick` a coarse grid for tests.",
        "",
        "**Model and assumptions.** Stepped free-free beam, 20 cubic Hermite elements (as the "
        "paper); ball mass m_B = 0.057 kg, **not stated in the paper** (the rules allow "
        "56.0-59.4 g; contact times scale as sqrt(m_B) and the COR depends on m_B / m_R); "
        "K_CB from the paper's three points, piecewise power law between them; zeta = 0.0592 "
        "from the clamped COR 0.83; exact (closed-form modal) solution with all 40 flexible "
        "modes; impact ends when the spring deflection returns to zero (the paper's criterion).",
    ]
    if quick:
        lines += ["", "> **Quick run**: coarse grids (test resolution); numbers are approximate."]
    for sec, title in SECTIONS.items():
        rows = [c for c in claims if _section(c) == sec]
        lines += [
            "",
            f"## {title}",
            "",
            "| § | paper | this project | verdict | reason |",
            "|---|---|---|---|---|",
        ]
        for c in rows:
            verdict = f"**{c.verdict}**" if c.verdict != AGREES else c.verdict
            fig = f" ([{c.figure}](#{c.figure}))" if c.figure else ""
            lines.append(
                f"| {_cell(c.section)} | {_cell(c.paper)} | {_cell(c.ours)}{fig} | "
                f"{verdict} | {_cell(c.reason)} |"
            )
        for key, data in figures.items():
            if SECTION_OF.get(key) != sec:
                continue
            spec = FIGURES[key]
            files = ", ".join(f"`{spec.name}_{t}.csv`" for t in spec.tables)
            lines += [
                "",
                f'<a id="{key}"></a>',
                f"### {data.title}",
                "",
                _figure_link(data.title, f"{img}/{spec.name}.{fmt}"),
                "",
                f"Data: {files}.",
            ]
    lines += [
        "",
        "## Notes",
        "",
        "- Beyond about 0.93 L the standard frame's COR is slightly negative (Fig. 8): at "
        "separation the ball is still moving forwards, more slowly than the strings. The paper "
        "plots Fig. 8 without printing values, so this cannot be compared; it follows from the "
        "linear ball/string law, the assumed m_B and the flexible tip.",
        "- Fig. 11/12 use our mode-1 node (0.7697 L, 20 elements) rather than the paper's "
        "rounded 0.769 L, so that V_1 vanishes exactly; values at 0.769 L are in `values.json` "
        "(`fig11`/`fig12`, keys ending `_0769`).",
        "- Fig. 13 is drawn at 0.60, 0.75 and 0.90 L; the paper's figure does not name its impact "
        "points in the text.",
        "",
    ]
    return "\n".join(lines)


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
    figures : list of str, optional
        Subset of :data:`fem_racket.figures.FIGURES` keys; all by default (a report needs all).
    parameters : dict, optional
        Extra provenance (e.g. the command's options), in ``values.json``, every figure's
        metadata and a comment at the end of the report. Every provenance also records what
        the figures used (``"used"``: :func:`fem_racket.paper.figures.used_settings`).
    fmt : {"png", "svg", "pdf"}
        Format of the figures (the report shows PNG and SVG, and links PDF).
    dpi : float
        Resolution of the figures [dots per inch].
    progress : bool or None
        A progress bar over the figures on stderr (None: when stderr is a terminal).
    """
    from fem_racket.validation import check_choice

    keys = (
        list(FIGURES) if figures is None else [check_choice("figure", k, FIGURES) for k in figures]
    )
    if report is not None and set(keys) != set(FIGURES):
        raise InputError("figures is not allowed with a report: the report needs every figure")
    fmt = check_figure_format(fmt)
    dpi = check_dpi(dpi)
    out = Path(out_dir)
    written = [p for k in keys for p in expected_files(FIGURES[k], out, fmt)]
    targets = [*written, out / "values.json"]
    if report is not None:
        targets.append(Path(report))
    _check_targets(targets, overwrite)
    meta = provenance(
        {"quick": quick, "figures": keys, "format": fmt, "dpi": dpi, **(parameters or {})}
    )
    meta["used"] = used_settings()
    done: dict[str, FigureData] = {}
    files: list[Path] = []
    seconds: dict[str, float] = {}
    for key in progress_bar(keys, desc="reproduce", unit="figure", enabled=progress):
        t0 = time.perf_counter()
        data = FIGURES[key].compute(quick)
        files += write_figure(FIGURES[key], data, out, overwrite=True, meta=meta, fmt=fmt, dpi=dpi)
        done[key] = data
        seconds[key] = time.perf_counter() - t0
        log.info("%s: %.2f s", key, seconds[key])
    values = {k: d.values for k, d in done.items()}
    listing = [p.name for p in written]
    with atomic_output(out / "values.json", overwrite=True) as tmp:
        tmp.write_text(
            json.dumps({"provenance": meta, "files": listing, "values": values}, indent=1)
        )
    files.append(out / "values.json")
    claims = build_claims(values) if report is not None else []
    if report is not None:
        rel = os.path.relpath(out.resolve(), Path(report).resolve().parent).replace(os.sep, "/")
        text = render_report(done, claims, rel, quick=quick, fmt=fmt)
        text += f"\n<!-- provenance: {json.dumps(meta, sort_keys=True, default=str)} -->\n"
        with atomic_output(report, overwrite=True) as tmp:
            tmp.write_text(text)
        files.append(Path(report))
    return Reproduction(done, claims, files, seconds)
