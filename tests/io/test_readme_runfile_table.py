"""The README's run-file table lists exactly the keys each core table accepts
(:data:`fem_racket.io.config_keys.CORE_KEYS`), so it cannot go stale again (issue 21.8): a key
added to a table and not to its row, or a row naming a key the table refuses, fails here."""

from __future__ import annotations

import re
from pathlib import Path

from fem_racket.contact.registry import family_parameters
from fem_racket.impact.solvers import SOLVER_NAMES
from fem_racket.io.config_keys import COMMAND_TABLES, CORE_KEYS

README = Path(__file__).resolve().parents[2] / "README.md"
#: A backticked bare name (`speed_m_s`); quoted values (`"rigid"`) and options (`--x`) are not.
NAME = re.compile(r"`([a-z][a-z0-9_]*)`")
#: Bare names in a row that are no keys: the commands a table serves, TOML's booleans.
NOT_KEYS = {*COMMAND_TABLES, "true", "false"}
#: Names in the [frame] row inside its lead and segments tables (not keys of [frame] itself).
INNER = {"frame": {"place", "mass_g"}}


def rows() -> dict[str, str]:
    """Core table -> the text of its row in the README's run-file table."""
    text = README.read_text(encoding="utf-8")
    section = text[text.index("### Run files (`--config`)") :]
    out = {}
    for line in section.splitlines():
        m = re.match(r"\| `\[(\w+)\]` \| (.*) \|$", line)
        if m:
            out[m.group(1)] = m.group(2)
        elif out and not line.startswith("|"):
            break
    return out


def named(row: str, keys: set[str] = frozenset()) -> set[str]:
    """The bare names of ``row``, less those that are no keys (a command's name that is one of
    the table's ``keys`` counts: ``modes``)."""
    found = set(NAME.findall(row))
    return (found - NOT_KEYS) | (found & keys)


def test_every_core_table_has_a_row():
    assert set(rows()) == set(CORE_KEYS)


def test_each_row_names_exactly_its_tables_keys():
    found = rows()
    for table, keys in CORE_KEYS.items():
        listed = named(found[table], set(keys)) - INNER.get(table, set())
        if table == "contact":  # the law's own keys: a few named, every one a law's parameter
            laws = {p.key for declared in family_parameters().values() for p in declared}
            fixed = set(keys) - laws
            assert listed - fixed, "the row names a law parameter as an example"
            assert listed - fixed <= laws, (table, sorted(listed - set(keys)))
            listed = (listed & fixed) | laws
        assert listed == set(keys), (table, sorted(set(keys) ^ listed))


def test_the_solver_row_names_every_solver():
    quoted = re.findall(r'`"(\w+)"`', rows()["solver"])
    assert quoted == list(SOLVER_NAMES)


def test_the_check_sees_a_missing_key():
    # the row of [impact] as it was before (two of six keys) fails the comparison
    old = "`position_x_over_l`, `speed_m_s`"
    assert named(old) != set(CORE_KEYS["impact"])
