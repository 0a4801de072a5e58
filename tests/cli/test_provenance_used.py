"""Every provenance records what the run used, as ``simulate --json`` prints it for that run.

The options may ask for more than is used (``--modes 80`` on a 20-element mesh keeps its 40
flexible modes) or leave values to be derived (zeta from the clamped COR 0.83, K_CB from the
speed): the provenance's ``"used"`` must hold the values the run actually took.
"""

import json

import pytest

from fem_racket.cli import main
from tests.clirun import run_json

# --tolerance 0: every mode, so that the printed run (the batched engine, no histories) and the
# runs that write histories (the closed-form path) use the same modes and agree to round-off.
OPTIONS = ["--speed", "30", "--position", "0.7", "--modes", "80", "--tolerance", "0"]


@pytest.fixture(scope="module")
def printed():
    """``simulate --json`` for OPTIONS (a module fixture cannot use capsys: parse here)."""
    import contextlib
    import io

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(["simulate", "--json", *OPTIONS]) == 0
    return json.loads(buf.getvalue())


#: What simulate --json prints beside the settings: the results and the swing (at rest here).
RESULTS = ("cor", "apparent_cor", "ball_speed_out_m_s", "racket_speed_at_impact_m_s",
           "contact_time_s", "rebound_speed_m_s", "peak_force_n")  # fmt: skip
SWING = ("racket_butt_speed_m_s", "racket_angular_speed_rad_s", "pivot_m",
         "racket_cg_speed_before_m_s", "racket_cg_speed_after_m_s",
         "racket_angular_speed_after_rad_s")  # fmt: skip


def used_keys(printed):
    return {k: v for k, v in printed.items() if k not in RESULTS + SWING}


def test_simulate_json_prints_what_was_used(printed):
    assert printed["modes"] == 40  # 80 asked, a 20-element mesh has 40 flexible modes
    assert printed["zeta"] == pytest.approx(0.0592, abs=5e-5)  # clamped COR 0.83 (eqs 1-4)
    assert printed["kcb_n_m"] == pytest.approx(5.0e4)  # the paper's K_CB at 30 m/s (§2.1.1)
    assert printed["solver"] == "exact" and printed["rtol"] is None  # no tolerance in use


def test_simulate_out_provenance_matches(printed, capsys, tmp_path):
    out = tmp_path / "impact.json"
    assert main(["simulate", "--out", str(out), *OPTIONS]) == 0
    meta = json.loads(out.read_text())["provenance"]
    assert meta["used"] == used_keys(printed)
    # engine and closed form, every mode: the same eigen-solution by two paths (1e-9, issue 13)
    assert meta["results"]["cor"] == pytest.approx(printed["cor"], abs=1e-9)
    assert meta["parameters"]["modes"] == 80  # the request is kept beside what was used


def test_export_vtk_and_animate_provenance_match(printed, capsys, tmp_path):
    assert main(["export-vtk", "--out", str(tmp_path / "vtk"), "--frames", "3", *OPTIONS]) == 0
    meta = json.loads((tmp_path / "vtk" / "provenance.json").read_text())
    assert meta["used"] == used_keys(printed)
    gif = tmp_path / "a.gif"
    argv = ["animate", "--out", str(gif), "--frames", "2", "--size", "160x160", *OPTIONS]
    assert main(argv) == 0
    meta = json.loads((tmp_path / "a.gif.json").read_text())
    assert meta["used"] == used_keys(printed)
    assert meta["results"]["cor"] == pytest.approx(printed["cor"], abs=1e-9)


def test_cvode_run_records_its_tolerances(capsys, tmp_path):
    # without --tolerance 0 (every mode), which cvode keeps anyway and now refuses given
    argv = ["--solver", "cvode", "--rtol", "1e-8", "--atol", "1e-10", *OPTIONS[:-2]]
    printed = run_json(capsys, "simulate", *argv)
    assert printed["solver"] == "cvode" and printed["rtol"] == 1e-8 and printed["atol"] == 1e-10
    out = tmp_path / "impact.csv"
    assert main(["simulate", "--out", str(out), *argv]) == 0
    meta = json.loads((tmp_path / "impact.csv.json").read_text())
    assert meta["used"] == used_keys(printed)


def test_a_swing_is_recorded_as_used(capsys, tmp_path):
    argv = [*OPTIONS, "--racket-speed", "15"]
    printed = run_json(capsys, "simulate", *argv)
    assert printed["swing"]["racket_angular_speed_rad_s"] == printed["racket_angular_speed_rad_s"]
    out = tmp_path / "impact.json"
    assert main(["simulate", "--out", str(out), *argv]) == 0
    meta = json.loads(out.read_text())["provenance"]
    assert meta["used"] == used_keys(printed)
    assert meta["used"]["swing"]["racket_butt_speed_m_s"] == pytest.approx(
        15.0
    )  # no pivot: a translation
