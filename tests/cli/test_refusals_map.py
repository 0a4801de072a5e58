"""Options the maps, compare, simulate and fit would drop or misname (issue 21.3, audit items
4, 5, 8, 10, 11, 12): each refused in one line naming the option given and why, exit 2, no file
written; and the same options where they do act still accepted."""

from __future__ import annotations

import json

import pytest
from clirun import run, run_json

from fem_racket.frame.model import DEFAULT_MODES
from fem_racket.studies.map_options import MAX_MAP_POINTS

MAP = ("map", "--no-files", "--positions", "0.5:0.9:3")
CMP = ("compare", "standard", "rigid", "--positions", "0.5:0.9:3")

CASES = {
    # item 4: what the law or the mesh cannot use
    "map-law-modes": (
        (*MAP, "--law", "hunt-crossley", "--modes", "10"),
        ("modes = 10 is not allowed with solver 'general'",),
    ),
    "map-law-separation": (
        (*MAP, "--law", "hunt-crossley", "--separation", "force"),
        ("separation = 'force' is not allowed with contact law 'hunt-crossley'", "own condition"),
    ),
    "map-spin-law-modes": (
        (*MAP, "--angle", "30", "--law", "hunt-crossley", "--modes", "10"),
        ("modes is not allowed with --law hunt-crossley",),
    ),
    "map-mesh-elements": (
        (*MAP, "--mesh", "racket.vtu", "--elements", "10"),
        ("--elements is not allowed with --mesh", "mesh file gives the cells"),
    ),
    # item 5: a swing's point without a swing
    "map-reference-at-rest": ((*MAP, "--reference", "0.5"), ("reference = 0.5 x/L", "swing")),
    "simulate-reference-at-rest": (("simulate", "--reference", "0.5"), ("reference = 0.5",)),
    "simulate-pivot-at-rest": (("simulate", "--pivot", "0.1"), ("pivot = 0.1 m", "swing")),
    "sweep-reference-at-rest": (("sweep", "--reference", "0.5"), ("reference = 0.5", "swing")),
    "sweep-pivot-at-rest": (("sweep", "--pivot", "0.1"), ("pivot = 0.1 m", "racket_speed")),
    "compare-reference-at-rest": ((*CMP, "--reference", "0.5"), ("reference = 0.5", "swing")),
    "compare-pivot-at-rest": ((*CMP, "--pivot", "0.1"), ("pivot = 0.1 m", "--racket-speed")),
    # item 8: output options with no output
    "simulate-output-step-no-out": (
        ("simulate", "--output-step", "1e-4"),
        ("--output-step 0.0001 is not allowed without --out",),
    ),
    "simulate-held-output-step-no-out": (
        ("simulate", "--grip", "firm", "--output-step", "1e-4"),
        ("--output-step 0.0001 is not allowed without --out",),
    ),
    "simulate-overwrite-no-out": (
        ("simulate", "--overwrite"),
        ("--overwrite is not allowed without --out",),
    ),
    "map-overwrite-no-files": ((*MAP, "--overwrite"), ("--overwrite is not allowed without",)),
    # item 10: sizes, before any array
    "map-positions-too-many": (
        ("map", "--no-files", "--positions", "0.5:0.9:10000000"),
        ("positions = 10000000 values", f"at most {MAX_MAP_POINTS} points"),
    ),
    "map-offsets-too-many": (
        ("map", "--no-files", "--positions", "0.5:0.9:10", "--offsets", "-0.1:0.1:100000"),
        ("offsets = 100000 values with positions = 10", f"at most {MAX_MAP_POINTS}"),
    ),
    "map-spin-too-many": (
        ("map", "--no-files", "--angle", "30", "--positions", "0.5:0.9:1000000"),
        ("positions = 1000000 values with offsets = ", f"at most {MAX_MAP_POINTS}"),
    ),
    "compare-positions-too-many": (
        ("compare", "standard", "rigid", "--positions", "0.5:0.9:10000000"),
        ("positions = 10000000 values", f"at most {MAX_MAP_POINTS}"),
    ),
    # item 11: bounds where the model's assumptions end, stated in the line
    "spin-bound": (("simulate", "--angle", "30", "--spin", "1e12"), ("spin = ", "[-50000, 50000]")),
    "side-spin-bound": (
        ("simulate", "--angle", "30", "--side-spin", "-1e6"),
        ("side_spin = -1000000.0 rpm", "[-50000, 50000]"),
    ),
    "radius-bound": (("simulate", "--angle", "30", "--ball-radius", "10"), ("radius = 10.0 m",)),
    "friction-bound": (("simulate", "--angle", "30", "--friction", "1e9"), ("friction", "[0, 5]")),
    "compliance-bound": (
        ("simulate", "--angle", "30", "--compliance-ratio", "1e9"),
        ("compliance_ratio", "[0, 15]"),
    ),
    "tension-bound": (
        ("simulate", "--string-tension", "1e9"),
        ("string tension = 1000000000.0 N", "[1, 2000]"),
    ),
    "lead-bound": (("simulate", "--add-mass", "12:1e9"), ("add-mass = '12:1e9'", "1000 g")),
    # item 12: the option given named, not what it derives
    "angle-names-the-angle": (
        ("simulate", "--angle", "89.999"),
        ("angle = 89.999 deg is not allowed with speed = 20.0 m/s", "normal speed 0.000349"),
    ),
    "racket-speed-bound": (
        ("simulate", "--racket-speed", "1e6"),
        ("racket_speed = 1000000.0 m/s", "[-100, 100]"),
    ),
    "racket-speed-closing": (
        ("simulate", "--racket-speed", "90"),
        ("racket_speed = 90.0 m/s is not allowed with speed = 20.0", "closing speed 110"),
    ),
    "head-area-names-the-area": (
        ("simulate", "--string-tension", "250", "--head-area", "1e9"),
        ("head area = 1000000000.0 cm^2", "405.8 m long"),
    ),
    "fit-f1": (
        (
            "fit",
            "--length",
            "0.685",
            "--mass",
            "0.318",
            "--balance",
            "0.32",
            "--swing-weight",
            "316",
            "--f1",
            "1e9",
        ),
        ("f1 = 1000000000.0 Hz", "(0, 3000]"),
    ),  # fmt: skip
}


@pytest.mark.parametrize("case", list(CASES))
def test_refused_in_one_line(capsys, tmp_path, monkeypatch, case):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "racket.vtu").write_text("")  # the --elements refusal comes before reading it
    argv, needles = CASES[case]
    code, out, err = run(capsys, *argv)
    assert code == 2, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    for needle in needles:
        assert needle in lines[0], f"{needle!r} not in {lines[0]!r}"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["racket.vtu"]  # nothing written


def test_run_file_reference_without_a_swing_is_refused_on_map(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text("[impact]\nreference_x_over_l = 0.6\n")
    code, _, err = run(capsys, *MAP, "--config", path)
    assert (
        code == 2
        and "run.toml: impact.reference_x_over_l = 0.6 x/L is not allowed without a swing" in err
    )


def test_what_acts_is_still_accepted(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # the pivot sets the map's centre of percussion at rest: accepted, and it shows
    data = run_json(capsys, *MAP, "--pivot", "0.1")
    assert data["cop_x_over_l"] == pytest.approx(0.7387, abs=1e-4)
    # --elements meshes a preset next to a mesh; a law's map without the linear law's options;
    # --output-step with --out; a swing with its reference point; the largest map allowed
    ok = [
        (*MAP, "--law", "hunt-crossley"),
        ("simulate", "--output-step", "1e-4", "--out", tmp_path / "o.json"),
        ("simulate", "--racket-speed", "10", "--reference", "0.6", "--pivot", "0.1"),
        ("simulate", "--angle", "30", "--spin", "3000", "--friction", "0.6"),
        ("simulate", "--angle", "87"),
    ]
    for argv in ok:
        code, _, err = run(capsys, *argv)
        assert code == 0, (argv, err)


def test_defaults_print_the_same_numbers(capsys):
    # the map's options given at their defaults change nothing (passed on only when given)
    a = json.loads(run(capsys, *MAP, "--json")[1])
    given = ("--modes", DEFAULT_MODES, "--separation", "displacement", "--tolerance", 1e-6)
    b = json.loads(run(capsys, *MAP, "--json", *given)[1])
    assert a == b
