"""The commands of a run file in Python: one method of :class:`~fem_racket.io.config.RunConfig`
per command that takes ``--config`` (``load_config(f).simulate()`` = ``fem-racket simulate
--config f``, ...), each computing what the command computes from the same file, with the same
checks and refusals, and writing the same files where it writes any.

``fem-racket reproduce --config`` is the one command without a method here: its work (the
paper's figures, :mod:`fem_racket.paper`) sits above the run files in the layering; its Python
equal is :func:`fem_racket.paper.config_reproduce.reproduce_file`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from fem_racket.io.config_named import core_keys_named

__all__ = ["CommandMethods"]

#: An output path, as the methods take it.
PathLike = str | os.PathLike


class CommandMethods:
    """The methods of :class:`~fem_racket.io.config.RunConfig`, one per command (see the module
    docstring); each names the function doing its work, and its refusal of a value of the file's
    core tables names the key, as the command's (:func:`.config_named.core_keys_named`)."""

    @core_keys_named
    def simulate(self, *, histories: bool | None = None) -> Any:
        """The impact the file describes, every table applied: the result of
        ``fem-racket simulate --config FILE`` (an ImpactResult, or a HeldRun with a ``[hand]``);
        see :func:`fem_racket.io.config_run.simulate_file`."""
        from fem_racket.io.config_run import simulate_file

        return simulate_file(self, histories=histories)

    @core_keys_named
    def sweep(self, *, backend: str | None = None, workers: int | None = None) -> Any:
        """The dataset ``fem-racket sweep --config FILE`` writes (not written here): the
        ``[sweep]`` grids over the core tables; see :func:`fem_racket.io.config_sweep.sweep_file`.
        ``backend``/``workers``: where the cases run (as :func:`fem_racket.sweep`), over
        ``[sweep]``'s ``serial``, ``workers`` and ``scheduler`` (taken as the command takes
        them)."""
        from fem_racket.io.config_sweep import sweep_file

        return sweep_file(self, backend=backend, workers=workers)

    @core_keys_named
    def map(self) -> list[Any]:
        """The maps ``fem-racket map --config FILE`` computes (no file written): a RacketMap
        per racket (a FaceMap with ``offsets``, a SpinMap with an oblique ball); see
        :func:`fem_racket.io.config_studies.map_file`."""
        from fem_racket.io.config_studies import map_file

        return map_file(self)

    @core_keys_named
    def refine(self) -> dict[str, Any]:
        """The refinement studies ``fem-racket refine --config FILE`` computes (no file
        written): family -> RefinementStudy; see
        :func:`fem_racket.io.config_studies.refine_file`."""
        from fem_racket.io.config_studies import refine_file

        return refine_file(self)

    @core_keys_named
    def export_vtk(self, out: PathLike | None = None) -> Path:
        """Write the VTK series ``fem-racket export-vtk --config FILE`` writes (into ``out``,
        else ``[vtk] out``); the ``.pvd`` path. See
        :func:`fem_racket.io.config_drawings.vtk_file`."""
        from fem_racket.io.config_drawings import vtk_file

        return vtk_file(self, out)

    @core_keys_named
    def animate(self, out: PathLike | None = None) -> Path:
        """Render the animation ``fem-racket animate --config FILE`` renders (to ``out``, else
        ``[animate] out``); its path. See :func:`fem_racket.io.config_drawings.animate_file`."""
        from fem_racket.io.config_drawings import animate_file

        return animate_file(self, out)

    @core_keys_named
    def optimize(self, out: PathLike | None = None) -> Any:
        """The optimisation ``fem-racket optimize --config FILE`` runs (files into ``out``,
        else ``[design] out``, else output/design); see :func:`.config_design.optimize_file`."""
        from fem_racket.io.config_design import optimize_file

        return optimize_file(self, out)

    @core_keys_named
    def sensitivity(self, out: PathLike | None = None) -> Any:
        """The Sobol indices of ``fem-racket sensitivity --config FILE`` (chart in ``out``)."""
        from fem_racket.io.config_design import sensitivity_file

        return sensitivity_file(self, out)

    @core_keys_named
    def modes(self) -> Any:
        """The free-free modal analysis ``fem-racket modes --config FILE`` reports.

        Returns
        -------
        RacketModes
            Of the file's frame (``[frame]`` with its lead), ``[modes] count`` flexible modes
            (4 by default): ``bending`` (a FreeModes: frequencies [Hz], shapes, mass
            properties: mass [kg], centre of gravity [m], inertia [kg m^2]), ``nodes`` of each
            mode [x/L], the swing weight and twistweight [kg m^2] (``catalogue``) and, on a
            frame with torsion data, ``torsion`` (a TorsionModes: frequencies [Hz], polar
            moment [kg m^2]; else None). ``.frequencies`` and ``.props`` are the bending
            ones; ``.summary()`` is the command's ``--json``. See
            :func:`fem_racket.io.config_modes.modes_file`.
        """
        from fem_racket.io.config_modes import modes_file

        return modes_file(self)

    @core_keys_named
    def fit(self, out: PathLike | None = None) -> Any:
        """The frame ``fem-racket fit --config FILE`` fits to ``[fit]``'s length [m], mass
        [kg], balance [m], swing weight [kg cm^2] (and f1 [Hz], twistweight [kg cm^2]).

        Parameters
        ----------
        out : path, optional
            Mesh file to write, with its sidecar ``out.json``, as the command writes them
            (else ``[fit] out``; neither: nothing written). Both or neither; existing files are
            refused as the command refuses them: replaced with ``overwrite`` in the file, or
            when ``out`` is the command's default ``output/racket.vtu`` and holds an earlier
            fit (see :mod:`fem_racket.io.config_rerun`).

        Returns
        -------
        FittedRacket
            Everything the command reports (:class:`fem_racket.io.racket_files.FittedRacket`):
            the ``frame`` (three segments, :func:`fem_racket.frame.specs.fit_racket`; also
            ``.segments``), its ``mesh``, the ``target`` and ``fitted`` catalogue numbers;
            ``.summary()`` is the command's ``--json`` less the mesh's path. See
            :func:`fem_racket.io.config_racket.fit_file`.
        """
        from fem_racket.io.config_racket import fit_file

        return fit_file(self, out)

    @core_keys_named
    def customise(self, out: PathLike | None = None) -> Any:
        """The least lead ``fem-racket customise --config FILE`` adds to the file's frame to
        meet ``[customise]``'s targets at its ``places``.

        Parameters
        ----------
        out : path, optional
            The customised racket's mesh file (sidecar ``out.json``; the maps before and after
            to ``[customise] maps``, else beside the mesh as the command puts them), as the command
            writes them (else ``[customise] out``; neither: nothing written).

        Returns
        -------
        CustomisedRacket
            Everything the command reports
            (:class:`fem_racket.io.customise_files.CustomisedRacket`): ``customisation`` (of
            :func:`fem_racket.studies.customise.customise`: placement [kg], the racket before
            and after; also ``.added``, ``.mesh``, ``.before``, ``.after``, ``.total``), the
            ``maps`` before and after (sweet spots [x/L]) at the file's ball speed [m/s] and
            swing, the ``targets``; ``.summary()`` is the command's ``--json`` less the paths
            written. See
            :func:`fem_racket.io.config_racket.customise_file`.
        """
        from fem_racket.io.config_racket import customise_file

        return customise_file(self, out)

    @core_keys_named
    def closest(self, rackets: PathLike) -> list[Any]:
        """The rackets of the CSV list ``rackets`` nearest ``[closest]``'s targets, each with
        its least lead at ``places``: ``fem-racket closest RACKETS --config FILE``.

        Returns
        -------
        list of Match
            ``[closest] count`` of them (3 by default), nearest first
            (:func:`fem_racket.studies.closest.closest`). See
            :func:`fem_racket.io.config_racket.closest_file`.
        """
        from fem_racket.io.config_racket import closest_file

        return closest_file(self, rackets)

    @core_keys_named
    def compare(self, rackets: list[str], out: PathLike | list[PathLike] | None = None) -> Any:
        """The set-ups ``rackets`` (presets, mesh or run files, each optionally
        ``+LOCATION:GRAMS``) compared as ``fem-racket compare RACKETS --config FILE`` compares
        them, played at the file's ball speed [m/s] and swing.

        Parameters
        ----------
        rackets : list of str
            At least two.
        out : path or list of paths, optional
            Figure (.png, .svg, .pdf) and/or maps (.nc) to write, as the command writes them
            (else ``[compare] out``; neither: nothing written).

        Returns
        -------
        list of Report
            One per set-up (:func:`fem_racket.studies.compare.compare`); their differences:
            :func:`fem_racket.studies.compare.differences`. See
            :func:`fem_racket.io.config_reports.compare_file`.
        """
        from fem_racket.io.config_reports import compare_file

        return compare_file(self, rackets, out)

    @core_keys_named
    def calibrate(self, out: PathLike | None = None) -> Any:
        """The law ``fem-racket calibrate --config FILE`` fits: ``[calibrate] family`` to its
        ``targets``, with the ball of ``ball.mass_kg`` [kg].

        Parameters
        ----------
        out : path, optional
            Folder for the .toml, .json and .png the command writes there (else
            ``[calibrate] out``, else ``output.out``; none: nothing written).

        Returns
        -------
        Calibration
            Of :func:`fem_racket.studies.calibrate.calibrate`: the law, the targets and the
            model's values. See :func:`fem_racket.io.config_reports.calibrate_file`.
        """
        from fem_racket.io.config_reports import calibrate_file

        return calibrate_file(self, out)
