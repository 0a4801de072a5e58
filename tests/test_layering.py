"""The layering, one way: frame/contact/strings -> impact -> studies -> io -> paper -> cli.

Reads the imports of every module with :mod:`ast` (module level, inside functions and under
``TYPE_CHECKING`` alike) and fails on an import from a higher layer into a lower one, on an import
between the lowest folders (frame, contact and strings are independent), and on any import cycle
between modules.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "fem_racket"

#: Rank of each top-level part of the package: a module may import only parts of lower or equal
#: rank (equal: its own folder), never one of higher rank. The base modules are importable by all.
LAYERS = {
    "validation": 0,
    "outputs": 0,
    "version": 0,
    "progress": 0,
    "display": 0,
    "extras": 0,
    "lanczos": 0,
    "frame": 1,
    "contact": 1,
    "strings": 1,
    "impact": 2,
    "studies": 3,
    "io": 4,
    "paper": 5,
    "cli": 6,
    "__init__": 7,
    "__main__": 8,
}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def part(module: str) -> str:
    """The layer a module belongs to: its top-level folder or base module."""
    pieces = module.split(".")
    return pieces[1] if len(pieces) > 1 else "__init__"


def imports(path: Path) -> set[str]:
    """Every fem_racket module named by an import in ``path`` (absolute, as the house writes)."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            assert node.level == 0, f"{path}: relative import; the house uses absolute imports"
            if node.module and node.module.split(".")[0] == "fem_racket":
                found.add(node.module)
                # "from fem_racket.paper import plots" imports the submodule fem_racket.paper.plots
                found.update(f"{node.module}.{a.name}" for a in node.names)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] == "fem_racket")
    return found


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}
GRAPH = {name: imports(path) for name, path in MODULES.items()}


def test_every_part_has_a_layer():
    assert {part(m) for m in MODULES} <= set(LAYERS)
    assert all(t in MODULES or t.rsplit(".", 1)[0] in MODULES for m in GRAPH for t in GRAPH[m])


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_upward_import(module):
    here = part(module)
    for target in GRAPH[module]:
        there = part(target)
        assert LAYERS[there] <= LAYERS[here], f"{module} imports {target} from a higher layer"
        if LAYERS[here] == LAYERS[there] == 1:
            assert there == here, (
                f"{module} imports {target}: frame, contact and strings are independent"
            )


def test_no_import_cycle():
    # Resolve "from fem_racket.x import y" to the module fem_racket.x (or fem_racket.x.y when y
    # is a submodule); a package's __init__ counts as the package module.
    def edges(module: str) -> set[str]:
        return {t for t in GRAPH[module] if t in MODULES and t != module}

    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> None:
        state[m] = 1
        stack.append(m)
        for t in edges(m):
            if t.startswith(m + "."):
                continue  # a package importing its own submodules (its public names)
            if state.get(t) == 1:
                cycle = stack[stack.index(t) :] + [t]
                pytest.fail("import cycle: " + " -> ".join(cycle))
            if t not in state:
                visit(t)
        stack.pop()
        state[m] = 2

    for m in sorted(MODULES):
        if m not in state:
            visit(m)


#: The rooms of impact/, lowest first: the base modules (the problem and its checks, the coupled
#: system, the mode reduction, the modal data at impact points on and off the axis, the swing, the
#: incidence, the result) at the root; the methods (closed forms, the exact solution, the general
#: integrator) independent of each other; the ODE integrators (which take the exact solution's
#: modal form) and the tangential contact of oblique impacts (on a given normal force history);
#: the structures built on the methods, independent of each other: the hand-held racket and the
#: strung racket (frame and string bed); the oblique ball (its normal impact on any of them, then
#: the tangential contact); and at the top the dispatch (solvers, simulate and its paths, the law
#: path, the oblique entry points), which alone chooses a method.
IMPACT_ROOMS = {
    "base": 0,
    "analytic": 1,
    "exact": 1,
    "general": 1,
    "ode": 2,
    "tangential": 2,
    "held": 3,
    "strung": 3,
    "oblique": 4,
    "top": 5,
}
IMPACT_TOP = {
    "batch_solve",
    "clamped_solve",
    "engine_calls",
    "law_impact",
    "simulate",
    "simulate_law",
    "simulate_linear",
    "simulate_oblique",
    "simulate_stroke",
    "solver_base",
    "solvers",
}
#: Which rooms of impact/ each room may import besides the base modules and itself (stricter
#: than the ranks above: a room takes only what it is built on). Only the dispatch takes them all.
IMPACT_MAY_IMPORT = {
    "base": set(),
    "analytic": set(),
    "exact": set(),
    "general": set(),
    "ode": {"exact"},
    "tangential": set(),
    "held": {"exact", "ode"},
    "strung": {"exact", "general", "ode"},
    "oblique": {"analytic", "held", "tangential"},
    "top": set(IMPACT_ROOMS) - {"base", "top"},
}


def inner_imports(module: str, name: str):
    """What ``module`` imports from the part ``name`` of fem_racket (a module, or a name taken
    from one), leaving out what resolves to ``module`` itself."""
    for target in GRAPH[module]:
        if part(target) != name or target not in MODULES and target.rsplit(".", 1)[0] == module:
            continue
        yield target


def room(module: str) -> str:
    """The room of a module of fem_racket.impact."""
    pieces = module.split(".")
    if len(pieces) < 3:
        return "top"  # the package itself: its public names
    if pieces[2] in IMPACT_ROOMS:
        return pieces[2]
    return "top" if pieces[2] in IMPACT_TOP else "base"


IMPACT = sorted(m for m in MODULES if part(m) == "impact")


def test_every_impact_module_has_a_room():
    names = {m.split(".")[2] for m in IMPACT if m.count(".") >= 2}
    pkg_rooms = {n for n in names if (PACKAGE / "impact" / n).is_dir()}
    assert pkg_rooms <= set(IMPACT_ROOMS), f"impact/ rooms without a rank: {pkg_rooms}"


@pytest.mark.parametrize("module", IMPACT)
def test_impact_rooms(module):
    here = room(module)
    for target in inner_imports(module, "impact"):
        there = room(target)
        assert IMPACT_ROOMS[there] <= IMPACT_ROOMS[here], (
            f"{module} ({here}) imports {target} ({there}) from a higher room of impact/"
        )
        if there != here and IMPACT_ROOMS[there] == IMPACT_ROOMS[here] > 0:
            pytest.fail(f"{module} imports {target}: the rooms {here} and {there} are independent")


@pytest.mark.parametrize("module", IMPACT)
def test_impact_room_imports_only_what_it_is_built_on(module):
    here = room(module)
    for target in inner_imports(module, "impact"):
        there = room(target)
        assert there in {"base", here} | IMPACT_MAY_IMPORT[here], (
            f"{module} ({here}) imports {target} ({there}): {here} may import only "
            f"{sorted(IMPACT_MAY_IMPORT[here]) or 'the base modules'}"
        )


def test_impact_room_rules_agree_with_the_ranks():
    # Every allowed import goes down (so the rules have no cycle), and every room has its rule.
    assert set(IMPACT_MAY_IMPORT) == set(IMPACT_ROOMS)
    for here, allowed in IMPACT_MAY_IMPORT.items():
        assert all(IMPACT_ROOMS[there] < IMPACT_ROOMS[here] for there in allowed), here


def test_the_layering_test_sees_an_upward_import(tmp_path):
    # The checker itself: a frame module importing from impact is found.
    bad = tmp_path / "bad.py"
    bad.write_text("from fem_racket.impact.simulate import simulate\n")
    found = imports(bad)
    assert "fem_racket.impact.simulate" in found
    assert all(LAYERS[part(t)] > LAYERS[part("fem_racket.frame.mesh")] for t in found)


#: The rooms of cli/, lowest first: the parser, signals and notes; the option groups (and
#: ``common``, which re-exports them); the commands, one module each, independent of each other;
#: the package itself (``main``), which alone knows every command.
CLI_ROOMS = {"base": 0, "options": 1, "commands": 2, "top": 3}
CLI_BASE = {"parser", "signals", "text"}
#: ``config --check`` prints what each command would take from a run file: it asks the top-level
#: parser (inside a function), the one import of the package from below.
CLI_UPWARD = {("fem_racket.cli.commands.config", "fem_racket.cli")}


def cli_room(module: str) -> str:
    """The room of a module of fem_racket.cli."""
    pieces = module.split(".")
    if len(pieces) < 3:
        return "top"
    if pieces[2] in ("options", "commands"):
        return pieces[2]
    return "base" if pieces[2] in CLI_BASE else "options"


CLI = sorted(m for m in MODULES if part(m) == "cli")


def test_every_cli_module_has_a_room():
    folders = {
        p.name for p in (PACKAGE / "cli").iterdir() if p.is_dir() and p.name != "__pycache__"
    }
    assert folders <= set(CLI_ROOMS), f"cli/ folders without a rank: {folders}"


@pytest.mark.parametrize("module", CLI)
def test_cli_rooms(module):
    here = cli_room(module)
    for target in inner_imports(module, "cli"):
        if (module, target) in CLI_UPWARD or (module, target.rsplit(".", 1)[0]) in CLI_UPWARD:
            continue
        there = cli_room(target)
        assert CLI_ROOMS[there] <= CLI_ROOMS[here], (
            f"{module} ({here}) imports {target} ({there}) from a higher room of cli/"
        )
        if here == there == "commands" and target.count(".") >= 3:
            assert target.split(".")[3] == module.split(".")[3], (
                f"{module} imports {target}: commands are independent of each other"
            )
