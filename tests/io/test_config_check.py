"""``config --check FILE`` runs each command's own checks (everything short of the computation)
and fails where the command would (issue 22.6): each case below is refused, in the same words, by
the command run on the file and by ``config --check``; neither leaves a file behind."""

from dataclasses import dataclass
from pathlib import Path

import pytest
from clirun import run

from fem_racket.io.config import example_config, parse_config
from fem_racket.validation import InputError


@dataclass(frozen=True)
class Case:
    id: str
    command: str
    toml: str
    says: tuple[str, ...]


CASES = [
    # law parameters of another family
    Case(
        "law-param-of-another-family",
        "simulate",
        '[contact]\nlaw = "series"\nhc_alpha_s_m = 0.5\n',
        ("hc_alpha", "not allowed with law 'series'"),
    ),
    Case(
        "swept-law-param-of-another-family",
        "sweep",
        '[contact]\nlaw = "series"\n[sweep]\nhc_alpha = [0.1, 0.2]\n',
        ("hc_alpha", "not allowed with law 'series'"),
    ),
    Case(
        "vtk-law-param-of-another-family",
        "export-vtk",
        '[contact]\nlaw = "hysteretic"\nstring_stiffness_n_m = 3e4\n',
        ("string_stiffness", "not allowed with law 'hysteretic'"),
    ),
    # the linear law's K_CB and zeta under another law (accepted and ignored before)
    Case(
        "kcb-with-a-law",
        "simulate",
        '[contact]\nlaw = "series"\nkcb_n_m = 3e4\n',
        ("contact.kcb_n_m = 30000", "not allowed with contact law 'series'"),
    ),
    Case(
        "clamped-cor-with-a-law",
        "simulate",
        '[contact]\nlaw = "hysteretic"\nclamped_cor = 0.8\n',
        ("contact.clamped_cor = 0.8", "not allowed with contact law 'hysteretic'"),
    ),
    Case(
        "map-kcb-with-a-law",
        "map",
        '[contact]\nlaw = "series"\nkcb_n_m = 3e4\n',
        ("contact.kcb_n_m = 30000", "not allowed with contact law 'series'"),
    ),
    # a hand: no other law, no solver keys it cannot use, a grip within the frame
    Case(
        "hand-with-a-law",
        "simulate",
        '[contact]\nlaw = "series"\n[hand]\ngrip = "firm"\n',
        ("law = 'series' is not allowed with a hand",),
    ),
    Case(
        "hand-with-modes",
        "simulate",
        '[hand]\ngrip = "firm"\n[solver]\nmodes = 10\n',
        ("solver.modes = 10", "not allowed with a hand"),
    ),
    Case(
        "hand-with-separation",
        "simulate",
        '[hand]\ngrip = "firm"\n[solver]\nseparation = "force"\n',
        ("solver.separation = 'force'", "not allowed with a hand"),
    ),
    Case(
        "hand-with-basis",
        "simulate",
        '[hand]\ngrip = "loose"\n[solver]\nbasis = "physical"\nname = "bdf"\n',
        ("solver.basis = 'physical'", "not allowed with a hand"),
    ),
    Case(
        "grip-beyond-the-frame",
        "simulate",
        "[hand]\ngrip_end_m = 5.0\n",
        ("hand.grip_end_m = 5.0 m", "beyond the frame (0.68 m)"),
    ),
    # a pivot at the reference point
    Case(
        "pivot-at-the-reference",
        "simulate",
        "[impact]\npivot_m = 0.51\nracket_speed_m_s = 10\n",
        ("impact.pivot_m = 0.51 m", "reference point"),
    ),
    Case(
        "map-pivot-at-the-reference",
        "map",
        "[impact]\npivot_m = 0.51\nracket_speed_m_s = 10\n",
        ("impact.pivot_m = 0.51 m", "reference point"),
    ),
    # design keys out of range
    Case(
        "design-ei-bounds",
        "optimize",
        "[design]\nei_bounds = [-1, 100]\n",
        ("ei_1 bounds = [-1.0, 100.0] N m^2", "0 < low < high"),
    ),
    Case(
        "design-zone-range",
        "optimize",
        "[design]\nzone_range = [0.5, 1.5]\n",
        ("zone high = 1.5 x/L", "[0, 1]"),
    ),
    Case(
        "sensitivity-designs",
        "sensitivity",
        "[sensitivity]\ndesigns = 0\n",
        ("designs = 0", ">= "),
    ),
    # map ranges
    Case(
        "map-positions",
        "map",
        '[map]\npositions = "0.5:1.5:5"\n',
        ("map.positions = 1.25 x/L", "[0, 1]"),  # named by its key (issue 21)
    ),
    Case(
        "map-power-fraction",
        "map",
        "[map]\npower_fraction = 0\n",
        ("power_fraction = 0.0", "(0, 1]"),
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_check_fails_where_the_command_fails(capsys, cwd, case):
    (cwd / "run.toml").write_text(case.toml)
    code, out, err = run(capsys, case.command, "--config", "run.toml")
    assert code == 2 and out == "" and len(err.splitlines()) == 1, err
    for words in case.says:
        assert words in err, err
    code, out, check = run(capsys, "config", "--check", "run.toml")
    assert code == 2 and out == "" and len(check.splitlines()) == 1, check
    assert "run.toml: fem-racket " in check and "would refuse it" in check
    for words in case.says:
        assert words in check, check
    assert sorted(p.name for p in cwd.rglob("*")) == ["run.toml"]


def test_the_check_creates_nothing_and_lists_what_each_command_takes(capsys, cwd):
    (cwd / "run.toml").write_text(example_config())
    code, out, err = run(capsys, "config", "--check", "run.toml")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0] == "run.toml: ok"
    # the table names the file must use, and the command reading it when they differ
    assert any(ln.startswith("[vtk] (fem-racket export-vtk) ") for ln in lines)
    assert any(ln.startswith("[design] (fem-racket optimize) ") for ln in lines)
    assert "[fit] not checked: no [fit] table (length, mass, balance, swing_weight needed)" in lines
    assert sorted(p.name for p in cwd.rglob("*")) == ["run.toml"]


def test_an_existing_output_is_the_folders_state_not_the_files(capsys, cwd):
    # The command refuses to replace it without --overwrite; the file itself is fine.
    (cwd / "run.toml").write_text("[simulate]\nout = 'r.json'\n")
    (cwd / "r.json").write_text("{}")
    assert run(capsys, "config", "--check", "run.toml")[0] == 0
    code, _, err = run(capsys, "simulate", "--config", "run.toml")
    assert code == 2 and "already exists" in err


@pytest.mark.parametrize(
    ("table", "meant"), [("export-vtk", "vtk"), ("optimize", "design")], ids=["vtk", "design"]
)
def test_a_command_named_table_gets_a_did_you_mean(table, meant):
    # config --check lists [vtk] (fem-racket export-vtk): a file saying [export-vtk] is told so
    with pytest.raises(InputError) as info:
        parse_config(f"[{table}]\nfoo = 1\n")
    assert f"did you mean '{meant}'? (the table of fem-racket {table})" in str(info.value)


def test_the_examples_mesh_exists_for_a_run_file_at_the_repository_root():
    root = Path(__file__).resolve().parents[2]
    line = next(ln for ln in example_config().splitlines() if ln.startswith("# mesh = "))
    mesh = line.split('"')[1]
    assert (root / mesh).is_file()
    cfg = parse_config(f'[frame]\nmesh = "{mesh}"\n', root / "run.toml")
    assert cfg.frame().n_elements > 0


def test_a_file_for_one_command_notes_what_another_would_refuse(capsys, cwd):
    # A file with a [sweep] table is meant for sweep: that simulate would refuse its law at
    # the default exponent (the sweep sweeps it) is a note, not a failure of the file.
    (cwd / "run.toml").write_text(
        '[contact]\nlaw = "hunt-crossley"\nhc_stiffness_n_m_n = 1e7\n'
        "[sweep]\nhc_exponent = [1.5, 2.0]\n"
    )
    code, out, err = run(capsys, "config", "--check", "run.toml")
    assert code == 0, err
    line = next(ln for ln in out.splitlines() if ln.startswith("[simulate]"))
    assert line.startswith("[simulate] not for this command: fem-racket simulate would refuse it")
    assert any(ln.startswith("[sweep] ") and "hc_exponent" in ln for ln in out.splitlines())
    # the same file with a [sweep] the sweep refuses fails
    (cwd / "run.toml").write_text('[contact]\nlaw = "series"\n[sweep]\nhc_exponent = [1.5, 2.0]\n')
    code, _, err = run(capsys, "config", "--check", "run.toml")
    assert code == 2 and "fem-racket sweep would refuse it" in err
