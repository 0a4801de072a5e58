"""Safe output files: checked before the work, written all-or-nothing, with provenance.

Every file or folder the library or CLI writes goes through :func:`atomic_outputs` (or its
one-target forms :func:`atomic_output` and :func:`atomic_folder`): each output of a command -
main file, sidecars, reports, plots - is written to a temporary name beside its target, and all
of them are moved into place only when every one is complete. On any failure (an exception in the
block, a full disk, an interruption) the temporaries are removed, folders the write created are
removed again and every old output is left as it was. :func:`provenance` is the metadata every
output carries (package version, date, parameters, solver and tolerances).

The conventions, the same for every command (README, "Outputs, --overwrite and provenance"):

1. Library functions take the output path; only the CLI and scripts default to ``output/``.
2. Check every destination with :func:`check_output_path` (or :func:`check_targets`) *before*
   the work: an existing file is refused unless ``overwrite``; a name longer than the file
   system allows, a folder that cannot be created and a folder that does not take a new file
   (tested by creating and deleting one: the permission bits alone do not tell, e.g. as root or
   under ``/proc``) are an :class:`~fem_racket.validation.InputError` naming the option, the path
   and the reason. Nothing is left by the check.
3. Write inside ``with atomic_outputs([...], overwrite=...) as temporaries:``. An ``OSError``
   while writing becomes an :class:`OutputError` naming the target (not the temporary) and the
   reason.
4. Temporary names are ``.<name>.<pid>-<random>.part<suffix>``, never longer than the target's
   folder allows (a long name is cut and completed by a hash). Temporaries left by a run that
   was killed (its process is gone) are removed by the next run writing the same target.
5. Put ``provenance(parameters)`` in the output: JSON a ``"provenance"`` object; netCDF global
   attributes; PNG text chunks (:func:`add_png_provenance`); a folder a ``provenance.json`` in
   it; formats that cannot hold it (CSV, GIF, MP4) a sidecar ``<file>.json``
   (:func:`sidecar_path`), written in the same :func:`atomic_outputs` set as the file.

:func:`fem_racket.outputs.netcdf.write_netcdf` writes a netCDF file from plain arrays as xarray
would, without xarray's imports (import it from its module: netCDF4 loads only when used).
"""

from fem_racket.outputs.atomic import (
    atomic_folder,
    atomic_output,
    atomic_outputs,
    deferred_interrupts,
    deferring,
    record_interrupt,
)
from fem_racket.outputs.checks import (
    OutputError,
    Target,
    check_output_folder,
    check_output_path,
    check_targets,
)
from fem_racket.outputs.jsonable import json_ready
from fem_racket.outputs.provenance import add_png_provenance, provenance, sidecar_path

__all__ = [
    "OutputError",
    "Target",
    "add_png_provenance",
    "atomic_folder",
    "atomic_output",
    "atomic_outputs",
    "check_output_folder",
    "check_output_path",
    "check_targets",
    "provenance",
    "deferred_interrupts",
    "deferring",
    "json_ready",
    "record_interrupt",
    "sidecar_path",
]
