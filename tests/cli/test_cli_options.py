"""CLI usability: significant digits, negative COR, simulate's CSV and --output-step, help texts
with units and defaults, notes on truncated mode counts, comma lists in refine."""

import argparse
import csv
import json

import pytest
from clirun import run, run_json, run_ok

from fem_racket.cli import build_parser
from fem_racket.cli.common import significant


def table(out: str) -> dict[str, str]:
    """name -> the rest of the line, of simulate's table (names are the first 28 columns)."""
    return {ln[:28].strip(): ln[28:].strip() for ln in out.splitlines() if ln.strip()}


def commands() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(subs.choices)


# -- simulate's table --------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("value", "digits", "text"),
    [  # hand-rounded
        (608.14, 4, "608.1"),
        (0.30412, 4, "0.3041"),
        (27400.0, 4, "27400"),
        (12345.6, 4, "12350"),
        (0.376570146, 6, "0.376570"),
        (-5.01648, 5, "-5.0165"),
        (9.99996, 5, "10.000"),
        (3.2e-6, 4, "3.200e-06"),
        (0.0, 3, "0.00"),
    ],
)
def test_significant_digits(value, digits, text):
    assert significant(value, digits) == text


def test_small_peak_force_keeps_its_digits(capsys):
    # 1 m/s on a soft 100 N/m string (the softest allowed) with a 5 g ball: a peak force below
    # 1 N (0.64 N).
    argv = ["simulate", "--speed", "1", "--kcb", "100", "--ball-mass", "0.005"]
    _, out, _ = run(capsys, *argv)
    _, js, _ = run(capsys, *argv, "--json")
    peak = json.loads(js)["peak_force_n"]
    assert 0 < peak < 1
    value, unit = table(out)["peak force"].split()
    assert unit == "N"
    # 4 significant digits: within half a unit of the 4th digit.
    assert float(value) == pytest.approx(peak, rel=5e-4)
    assert len(value.lstrip("0.").replace(".", "")) == 4


def test_negative_cor_is_explained_and_json_keeps_its_keys(capsys):
    # zeta 0.999: the dashpot drags the ball on; it still moves forward at separation.
    _, out, _ = run(capsys, "simulate", "--zeta", "0.999")
    _, js, _ = run(capsys, "simulate", "--zeta", "0.999", "--json")
    data = json.loads(js)
    assert data["cor"] < 0 and data["rebound_speed_m_s"] < 0
    assert {"cor", "contact_time_s", "rebound_speed_m_s", "peak_force_n", "solver"} <= set(data)
    assert "negative: the ball keeps moving forward" in table(out)["rebound speed"]
    _, plain, _ = run(capsys, "simulate")
    assert table(plain)["rebound speed"].endswith("m/s")  # no note when COR > 0


def test_negative_rebound_of_a_receding_racket_is_not_called_a_negative_cor(capsys):
    # a racket receding at 10 m/s: COR > 0 (the ball rebounds from it), yet the ball keeps
    # moving forward; the note says why, not "COR < 0"
    data = run_json(capsys, "simulate", "--racket-speed", "-10")
    assert data["cor"] > 0 and data["rebound_speed_m_s"] < 0
    row = table(run_ok(capsys, "simulate", "--racket-speed", "-10"))["rebound speed"]
    assert row.endswith(
        "(negative: the ball keeps moving forward, the racket recedes faster than it rebounds)"
    )
    assert "COR < 0" not in row


# -- simulate --out and --output-step ----------------------------------------------------------
def test_simulate_csv_has_the_json_histories_and_a_sidecar(capsys, tmp_path):
    j, c = tmp_path / "r.json", tmp_path / "r.csv"
    assert run(capsys, "simulate", "--out", j, "--output-step", 5e-4)[0] == 0
    code, out, err = run(capsys, "simulate", "--out", c, "--output-step", 5e-4)
    assert code == 0, err
    assert f"wrote {c}\nwrote {c}.json\n" in out
    data = json.loads(j.read_text())
    with open(c, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == list(data["history"])  # the same columns, units in the names
    assert "time [s]" in rows[0] and "contact force [N]" in rows[0]
    columns = {name: [float(r[k]) for r in rows[1:]] for k, name in enumerate(rows[0])}
    assert columns == data["history"]  # repr() round-trips every float exactly
    side = json.loads((tmp_path / "r.csv.json").read_text())
    assert side["summary"] == data["summary"]
    assert side["parameters"]["output_step"] == 5e-4 and side["software"] == "fem_racket"


def test_output_step_spaces_the_histories(capsys, tmp_path):
    out = tmp_path / "r.json"
    assert run(capsys, "simulate", "--out", out, "--output-step", 1e-3)[0] == 0
    data = json.loads(out.read_text())
    t = data["history"]["time [s]"]
    # Output times k * 1e-3 s, then the contact end (4.04 ms on the standard racket).
    assert t[:-1] == pytest.approx([0.0, 1e-3, 2e-3, 3e-3, 4e-3], abs=1e-15)
    assert t[-1] == data["summary"]["contact_time_s"]


def test_output_step_is_one_option_definition():
    subs = commands()
    found = {
        name: next(a for a in subs[name]._actions if a.dest == "output_step")
        for name in ("simulate", "export-vtk", "animate")
    }
    first = found["simulate"]
    for action in found.values():
        assert (action.option_strings, action.default, action.type, action.help) == (
            first.option_strings,
            first.default,
            first.type,
            first.help,
        )


# -- help texts --------------------------------------------------------------------------------
def _in_required_group(parser: argparse.ArgumentParser, action: argparse.Action) -> bool:
    return any(g.required and action in g._group_actions for g in parser._mutually_exclusive_groups)


def test_every_option_states_its_default():
    for name, parser in commands().items():
        for action in parser._actions:
            if not action.option_strings or action.nargs == 0 or action.dest == "help":
                continue  # flags (store_true ...) and --help
            if _in_required_group(parser, action):
                continue  # config --check: one of --example/--check must be given
            assert "default" in (action.help or ""), f"{name} {action.option_strings[0]}"


def test_every_out_says_file_or_folder():
    folders = {"export-vtk", "reproduce", "calibrate", "optimize"}
    for name, parser in commands().items():
        for action in parser._actions:
            if "--out" not in action.option_strings:
                continue
            text = action.help.lower()
            assert ("folder" if name in folders else "file") in text, name
            assert ("file" if name in folders else "folder") not in text.split("(default")[0]


def test_refine_help_names_defaults_and_what_mesh_replaces():
    p = commands()["refine"]
    helps = {a.dest: a.help for a in p._actions}
    assert "(default 146" in helps["ei1"] and "0.88" in helps["ei2"]
    assert "(default 20)" in helps["speed"] and "0.057" in helps["ball_mass"]
    assert "from the speed" in helps["kcb"] and "0.0592" in helps["zeta"]
    assert "replaces --ei1 and --ei2" in helps["mesh"]
    assert "replaces --ei1, --ei2 and --elements" not in helps["mesh"]
    sweep = {a.dest: a.help for a in commands()["sweep"]._actions}
    assert "(default 80" in sweep["modes"] and "integrator" in sweep["solver"]


# -- mode counts above the mesh's ----------------------------------------------------------------
def test_modes_count_above_the_mesh_is_noted(capsys):
    code, out, err = run(capsys, "modes", "--count", "100", "--json")
    assert code == 0
    # 20 Hermite elements: 21 nodes x 2 DOFs, less the 2 rigid-body modes = 40 flexible modes.
    assert len(json.loads(out)["frequencies_hz"]) == 40
    assert err.strip() == (
        "fem-racket modes: note: count = 100: the 20-element mesh has 40 flexible modes; showing 40"
    )
    assert run(capsys, "modes", "--count", "40")[2] == ""


@pytest.mark.parametrize(
    ("argv", "noted"),
    [
        (["--modes", "200"], True),
        (["--modes", "41"], True),
        (["--modes", "40"], False),
        ([], False),  # the default 80 keeps every mode of small meshes by design
        (["--solver", "cvode", "--basis", "physical"], False),  # (modes: refused, unused)
    ],
)
def test_simulate_modes_above_the_mesh_is_noted(capsys, argv, noted):
    code, out, err = run(capsys, "simulate", "--json", *argv)
    assert code == 0
    if noted:
        assert err.strip() == (
            f"fem-racket simulate: note: modes = {argv[1]}: the 20-element mesh has 40 flexible "
            "modes; using all 40"
        )
        assert json.loads(out)["modes"] == 40
    else:
        assert err == ""


def test_sweep_modes_above_the_coarsest_mesh_is_noted(capsys, tmp_path):
    argv = ["sweep", "--serial", "--quiet", "--elements", "10,20", "--modes", "30"]
    code, _, err = run(capsys, *argv, "--out", tmp_path / "s.nc")
    assert code == 0
    assert "modes = 30: the 10-element mesh has 20 flexible modes; using all 20" in err


# -- list syntax ---------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "argv",
    [
        ["--elements", "5", "10", "20", "--positions", "0.6", "0.75"],
        ["--elements", "5,10,20", "--positions", "0.6,0.75"],
        ["--elements", "5,10", "20", "--position", "0.6,0.75"],  # mixed, sweep's option name
    ],
)
def test_refine_lists_take_spaces_or_commas(argv):
    args = build_parser().parse_args(["refine", *argv])
    assert args.elements == [5, 10, 20]
    assert args.positions == [0.6, 0.75]


def test_refine_list_replaces_its_default():
    args = build_parser().parse_args(["refine", "--elements", "5"])
    assert args.elements == [5]


def test_refine_comma_lists_run(capsys):
    common = ["refine", "--family", "uniform", "--no-files", "--json", "--count", "2"]
    _, a, _ = run(capsys, *common, "--elements", "5,10", "--position", "0.6,0.75")
    _, b, _ = run(capsys, *common, "--elements", "5", "10", "--positions", "0.6", "0.75")
    da, db = json.loads(a), json.loads(b)
    assert da["elements"] == [5, 10] and len(da["cor"][0]) == 2
    for key in ("elements", "frequencies_hz", "cor", "contact_time_s"):
        assert da[key] == db[key]
