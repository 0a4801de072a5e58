"""What the commands print and write: JSON on stdout, ``--out``/``--overwrite``, the run's
parameters for provenance, atomic text and JSON files.

Numbers go through :func:`fem_racket.outputs.json_ready` (NaN as ``null``, a short decimal
plus rounding noise as that decimal).
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from fem_racket.cli.text import significant
from fem_racket.outputs.jsonable import json_ready

__all__ = [
    "add_output_options",
    "add_overwrite_json",
    "core_rows",
    "offset_rows",
    "overwrite_of",
    "print_json",
    "print_result",
    "print_written",
    "print_written_folder",
    "run_parameters",
    "write_json",
    "write_result_files",
    "write_text",
]


def print_written(paths: Any) -> None:
    """The success line of every file a command wrote, sidecars included: ``wrote PATH``."""
    for path in paths:
        print(f"wrote {path}")


def print_written_folder(folder: str | Path, note: str = "") -> None:
    """The success line of a folder a command wrote: ``wrote DIR/ (N files[; note])``."""
    n = sum(1 for p in Path(folder).rglob("*") if p.is_file())
    print(f"wrote {Path(folder)}/ ({n} files{'; ' + note if note else ''})")


def print_json(data: Any) -> None:
    """Print ``data`` as JSON (NaN and inf become null)."""
    json.dump(json_ready(data), sys.stdout, indent=2)
    sys.stdout.write("\n")


def print_result(
    args: argparse.Namespace,
    summary: dict[str, Any],
    rows: Callable[[dict[str, Any]], Iterable[tuple[str, str, str]]],
    files: Iterable[Any],
) -> int:
    """Print one impact's result, the last step of ``simulate``'s runs: ``summary`` as JSON
    with ``--json``, else the table of ``rows(summary)`` (name, value, unit), a line each, and
    the ``wrote`` line of each of ``files``. Returns the exit code, 0."""
    if args.json:
        print_json(summary)
        return 0
    for name, value, unit in rows(summary):
        print(f"{name:<28} {value:>14} {unit}".rstrip())
    print_written(files)
    return 0


def core_rows(summary: dict[str, Any], rebound_unit: str = "m/s") -> list[tuple[str, str, str]]:
    """The first rows of a head-on impact's table (``simulate``, on a frame or a string bed):
    COR [-], contact time [ms], rebound speed [m/s] (its unit shown as ``rebound_unit``), peak
    force [N] and impact point [x/L], as (name, value, unit) for :func:`print_result`."""
    return [
        ("coefficient of restitution", significant(summary["cor"], 6), "-"),
        ("contact time", significant(summary["contact_time_s"] * 1e3, 5), "ms"),
        ("rebound speed", significant(summary["rebound_speed_m_s"], 5), rebound_unit),
        ("peak force", significant(summary["peak_force_n"], 4), "N"),
        ("impact point", significant(summary["position_x_over_l"], 4), "x/L"),
    ]


def offset_rows(summary: dict[str, Any]) -> list[tuple[str, str, str]]:
    """The rows of an off-axis head-on impact (``simulate --offset``, on a frame or a string
    bed): the offset from the long axis [m] and the racket's roll rate after impact [rad/s]."""
    return [
        ("offset from the axis", significant(summary["offset_m"], 4), "m"),
        ("roll rate after impact", significant(summary["roll_rate_rad_s"], 4), "rad/s"),
    ]


def add_output_options(
    parser: argparse.ArgumentParser, default: str | None = None, what: str = "output file"
) -> argparse._ArgumentGroup:
    """``--out FILE`` (``default``: None means the command writes no file unless asked) and
    ``--overwrite``; ``what`` starts the help text and must say it is a file. Relative paths are
    relative to the working directory. Returns the group (for more output options)."""
    g = parser.add_argument_group("output")
    where = f"default {default}" if default else "default: none, print only"
    g.add_argument("--out", default=default, metavar="FILE", help=f"{what} ({where})")
    g.add_argument("--overwrite", action="store_true", help="replace the output file if it exists")
    return g


def add_overwrite_json(group: argparse._ArgumentGroup, printed: str = "a JSON summary") -> None:
    """``--overwrite`` (existing files are refused by default) and ``--json`` (printing
    ``printed`` instead of the table): the end of the output group of the commands that write
    files and print a table (fit, customise, compare)."""
    group.add_argument(
        "--overwrite", action="store_true", help="replace existing files (default: refuse)"
    )
    group.add_argument("--json", action="store_true", help=f"print {printed} (default: a table)")


def overwrite_of(args: argparse.Namespace, writes: bool, output: str = "--out") -> bool:
    """``--overwrite`` where the command writes something (``writes``), else False; given on
    the command line or in the run file (the command's own table or ``[output]``) with nothing
    written it is refused (it would be ignored)."""
    from fem_racket.cli.options.runfile import option_name
    from fem_racket.validation import InputError

    if not args.overwrite or writes:
        return bool(args.overwrite)
    key = getattr(args, "file_options", {}).get("overwrite")
    if "overwrite" in getattr(args, "explicit_options", ()):
        raise InputError(f"--overwrite is not allowed without {output}: nothing is written")
    if key is not None:
        name = option_name(args, "overwrite")
        raise InputError(f"{name} is not allowed without {output}: nothing is written")
    return False


def run_parameters(args: argparse.Namespace) -> dict[str, Any]:
    """The parsed options as a JSON-ready dict for :func:`fem_racket.outputs.provenance`."""

    def plain(v: Any) -> Any:
        if v is None or isinstance(v, (bool, int, float, str)):
            return v
        if isinstance(v, Path):
            return str(v)
        if isinstance(v, (list, tuple)):
            return [plain(x) for x in v]
        if isinstance(v, (set, frozenset)):
            return sorted(plain(x) for x in v)
        if hasattr(v, "__dataclass_fields__"):
            return {k: plain(getattr(v, k)) for k in v.__dataclass_fields__}
        return repr(v)

    return {k: plain(v) for k, v in sorted(vars(args).items()) if k != "func" and not callable(v)}


def write_text(path: str | Path, text: str, *, overwrite: bool = False) -> Path:
    """Write ``text`` to ``path`` atomically (refusing an existing file unless ``overwrite``)."""
    from fem_racket.outputs import atomic_output

    with atomic_output(path, overwrite=overwrite) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def write_json(path: str | Path, data: Any, *, overwrite: bool = False) -> Path:
    """Write ``data`` as JSON to ``path`` atomically (NaN and inf become null)."""
    return write_text(path, json.dumps(json_ready(data), indent=2) + "\n", overwrite=overwrite)


def write_result_files(
    args: argparse.Namespace,
    meta: dict[str, Any],
    summary: dict[str, Any],
    files: list[Path],
    history: dict[str, Any],
) -> None:
    """Write ``--out`` of one impact: JSON (provenance ``meta``, summary, histories), or the
    histories as CSV and ``meta`` with the summary in its JSON sidecar, as one set (both or
    neither); ``files`` the one or two paths."""
    import csv

    from fem_racket.outputs import Target, atomic_outputs

    if len(files) == 1:
        data = {"provenance": meta, "summary": summary}
        history = {k: v.tolist() for k, v in history.items()}
        write_json(args.out, {**data, "history": history}, overwrite=args.overwrite)
        return
    with atomic_outputs([Target(f) for f in files], overwrite=args.overwrite) as (tmp, side):
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(history)
            for row in zip(*history.values(), strict=True):
                w.writerow([repr(float(v)) for v in row])
        text = json.dumps(json_ready({**meta, "summary": summary}), indent=2, default=str)
        side.write_text(text + "\n", encoding="utf-8")
