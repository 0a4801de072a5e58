"""The CLI style (README, "CLI style") held for every command: this walks each command's parser
and fails on a departure, so a new command or option that breaks the convention is caught."""

from __future__ import annotations

import argparse
import inspect
import re

import pytest

from fem_racket.cli import COMMANDS, build_parser
from fem_racket.cli.options.lists import _NumberList


def _commands() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(sub.choices)


PARSERS = _commands()
#: Integer counts given as a sweep's VALUES: a count has no unit.
COUNTS = {"elements"}


def _options(p: argparse.ArgumentParser) -> list[argparse.Action]:
    return [a for a in p._actions if a.option_strings and a.help != argparse.SUPPRESS]


def _flags(p: argparse.ArgumentParser) -> set[str]:
    return {s for a in p._actions for s in a.option_strings}


def _real_valued(a: argparse.Action) -> bool:
    """An option taking real numbers: a float, a list of floats, or a sweep's VALUES."""
    if a.type is float or (isinstance(a.type, _NumberList) and a.type.item is float):
        return True
    return a.metavar == "VALUES" and a.dest not in COUNTS


def test_the_walk_sees_every_command():
    assert set(PARSERS) == set(COMMANDS)


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_option_names_are_lower_case_words_joined_by_hyphens(name):
    for flag in _flags(PARSERS[name]):
        assert re.fullmatch(r"-[hv]|--[a-z][a-z0-9]*(-[a-z0-9]+)*", flag), f"{name} {flag}"


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_real_valued_options_state_their_unit(name):
    for a in _options(PARSERS[name]):
        if _real_valued(a):
            assert re.search(r"\[[^\]]+\]", a.help), f"{name} {a.option_strings[0]}: no [unit]"


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_dimensionless_is_written_as_a_dash(name):
    for a in _options(PARSERS[name]):
        assert "[1]" not in (a.help or "") and "[]" not in (a.help or ""), a.option_strings


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_every_option_states_its_default(name):
    for a in _options(PARSERS[name]):
        if a.nargs != 0 and not a.required:
            assert "default" in a.help, f"{name} {a.option_strings[0]}: no default stated"


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_choices_are_listed_once(name):
    for a in _options(PARSERS[name]):
        if a.choices is not None:
            choices = list(a.choices)
            assert len(choices) == len(set(choices)), f"{name} {a.option_strings[0]}: {choices}"


@pytest.mark.parametrize("name", sorted(set(PARSERS) - {"config"}))
def test_every_command_that_computes_takes_a_run_file(name):
    assert "--config" in _flags(PARSERS[name])


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_a_command_with_a_progress_bar_has_quiet_and_no_other_spelling(name):
    import importlib

    module = importlib.import_module(COMMANDS[name].module_path)
    flags = _flags(PARSERS[name])
    assert not flags & {"--progress", "--no-progress"}
    if "progress_of(" in inspect.getsource(module):
        assert "--quiet" in flags, f"{name} shows a progress bar without --quiet"


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_out_goes_with_overwrite(name):
    flags = _flags(PARSERS[name])
    if flags & {"--out", "--csv", "--plot"}:
        assert "--overwrite" in flags, name
    if "--overwrite" in flags:
        assert flags & {"--out", "--csv", "--plot"}, name


@pytest.mark.parametrize("name", sorted(PARSERS))
def test_a_list_takes_the_singular_and_the_plural(name):
    # map --positions, sweep --position, refine both: whichever a command takes several values
    # of, both spellings work.
    for a in _options(PARSERS[name]):
        several = a.metavar == "VALUES" or a.nargs in ("+", "*")
        for one, many in (("--position", "--positions"), ("--speed", "--speeds")):
            if several and {one, many} & set(a.option_strings):
                assert {one, many} <= set(a.option_strings), f"{name} {a.option_strings}"


#: Docstring markup that must not leak into --help: ``literal``, :role:`target`, *emphasis*.
MARKUP = re.compile(r"``|:\w+:`|(?<!\w)\*\w")
DESCRIBED = sorted(name for name, p in PARSERS.items() if p.description)
#: The commands' descriptions under their usage line, as --help prints them, pinned: a change
#: of the help text must be made here too, on purpose.
DESCRIPTIONS = {
    "closest": (
        "Rank the rackets of a CSV list (name, length_m, mass_kg, balance_m, "
        "swing_weight_kg_cm2; optional\n"
        "twist_weight_kg_cm2, stiffness_ra, f1_hz) by their distance to the targets (each a "
        "value or\n"
        "LOW:HIGH) and find the least lead bringing each of the nearest to the mass, "
        "balance, swing-weight\n"
        "and twistweight targets. Example: fem-racket closest meshes/rackets.csv "
        "--swing-weight 330\n"
        "--balance 0.32"
    ),
    "compare": (
        "Compare set-ups (presets, mesh files or run files with their own strings and ball;\n"
        "SOURCE+LOCATION:GRAMS adds lead) played alike: specs, e_A and v_out maps with their "
        "differences,\n"
        "sweet spots, power region, handle shock and contact time. Example: fem-racket "
        "compare standard\n"
        "standard+12:10 --out cmp.png cmp.nc"
    ),
    "customise": (
        "Find the least added mass (lead tape) at the allowed places that gives the racket "
        "the target specs\n"
        "(each a value or LOW:HIGH), write the customised racket as a mesh file and map it "
        "before and\n"
        "after. Example: fem-racket customise --swing-weight 310 --balance 0.3079 --places "
        "12,handle --out\n"
        "custom.vtu"
    ),
    "fit": (
        "Fit a three-segment frame (handle 0-0.3 L, throat 0.3-0.6 L, head 0.6-1 L; EI with "
        "the paper's\n"
        "0.88 step) to a racket's specification and write it as a mesh file for --mesh. "
        "Example:\n"
        "fem-racket fit --length 0.685 --mass 0.318 --balance 0.320 --swing-weight 316 --f1 "
        "150 --out\n"
        "racket.vtu"
    ),
    "map": (
        "e_A (the free racket's COR at the closing speed) and the ball's speed after impact\n"
        "v_out = e_A v_in + (1 + e_A) v_r along the frame, for a ball speed and a swing; "
        "sweet spots:\n"
        "centre of percussion (with --pivot), mode-1 node, max e_A, max v_out, power region; "
        "under the\n"
        "paper's linear law or another (--law). Example: fem-racket map --speed 20 "
        "--racket-speed 25\n"
        "--pivot 0.1 --law kawazoe-1997-nonlinear"
    ),
    "reproduce": (
        "Compute every figure of the paper, write its data (CSV) and figure (PNG, SVG or "
        "PDF) into --out,\n"
        "and write the side-by-side report --report (image links relative to it). Files an "
        "earlier run\n"
        "wrote are replaced (recognised by their provenance); any other existing file needs "
        "--overwrite.\n"
        "With --law NAME the figures are drawn with that contact law instead of the paper's "
        "linear K_CB\n"
        "and the report says which of the paper's conclusions (1)-(4) still hold and how the "
        "contact times\n"
        "compare with the paper's 6-3 ms. About 15 s on a quiet 2-core machine (--law\n"
        "kawazoe-1997-nonlinear: about 20 s), several times that under load.\n"
    ),
    "sweep": (
        "Simulate every combination of the given values. Each parameter takes a number, a "
        "comma list\n"
        "(20,30,40) or start:stop:num with an optional :log (50:3000:60:log); so do the "
        "contact law's\n"
        "parameters (--law hunt-crossley --hc-exponent 1.3:1.7:5). Example: fem-racket sweep "
        "--position\n"
        "0.55:0.95:9 --speed 20,30,40 --ei1 50:3000:60:log --out fig13.nc\n"
    ),
}


def test_commands_with_a_description_are_found():
    # These describe themselves below their usage line: the walk must see them.
    assert {"closest", "compare", "customise", "fit", "map", "reproduce", "sweep"} <= set(DESCRIBED)


def test_the_descriptions_are_the_pinned_texts():
    assert {name: PARSERS[name].description for name in DESCRIPTIONS} == DESCRIPTIONS


@pytest.mark.parametrize("name", DESCRIBED)
def test_a_description_is_plain_text(name):
    description = PARSERS[name].description
    assert MARKUP.search(description) is None, f"{name}: markup in --help: {description}"


def test_the_walk_fails_on_a_departure():
    # The checks themselves: a float option without a unit, a duplicated choice.
    p = argparse.ArgumentParser()
    bad = p.add_argument("--speed", type=float, default=1.0, help="speed (default 1)")
    twice = p.add_argument("--solver", choices=["a", "a"], default="a", help="(default a)")
    assert _real_valued(bad) and not re.search(r"\[[^\]]+\]", bad.help)
    assert len(list(twice.choices)) != len(set(twice.choices))
    assert MARKUP.search("see :mod:`fem_racket.io.setups`") and MARKUP.search("``--out``")
    assert MARKUP.search("Example: fem-racket map --speed 20 (1 + e_A) v_r, 2 * 3") is None
