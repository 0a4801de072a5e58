"""K_CB has a physical range, checked where kcb is validated (the LinearContact's declared
parameter), so the library, the CLI, a run file and a sweep axis refuse alike (audit F15):
``--kcb 1e12`` gave a COR set by the mesh (-0.563 / -0.778 / -0.888 / -0.914 at 10 / 20 / 40 /
80 elements), ``--kcb 1`` a 655 ms contact that CVODE took minutes over."""

import pytest

from fem_racket import LinearContact, load_config, simulate
from fem_racket.contact.linear import KCB_SPEED_RANGE, PAPER_KCB_POINTS, kcb_from_speed
from tests.clirun import file_refused_alike, refused_alike

RANGE = "must lie in [100, 1e+07]"


@pytest.mark.parametrize(
    ("kcb", "shown"), [(1e12, "1000000000000.0"), (1.0, "1.0"), (99.0, "99.0")]
)
def test_kcb_outside_its_range_is_refused_alike(capsys, cwd, kcb, shown):
    words = f"kcb = {shown} N/m is not allowed: {RANGE}"
    refused_alike(capsys, ["simulate", "--kcb", kcb], lambda: simulate(kcb=kcb), words, start=True)
    refused_alike(capsys, ["sweep", "--kcb", f"3e4,{kcb}"], lambda: LinearContact(kcb), words)
    text = f"[contact]\nkcb_n_m = {kcb!r}\n"
    argv = ["simulate", "--config", "run.toml"]
    file_refused_alike(capsys, text, argv, _simulate, f"contact.{words.replace('kcb', 'kcb_n_m')}")


def _simulate(config):
    return config.simulate()


def test_the_papers_k_cb_lies_inside_the_range():
    # Kawazoe & Kanda 1997 section 2.1.1: 2.74e4-8.33e4 N/m at 20-40 m/s, and its K_CB(V)
    # extended over the speeds it is allowed for, 1-100 m/s (322 to 4.2e5 N/m).
    for _, kcb in PAPER_KCB_POINTS:
        assert LinearContact(kcb).stiffness == kcb
    for speed in KCB_SPEED_RANGE:
        LinearContact(kcb_from_speed(speed))
    assert LinearContact(100.0).stiffness == 100.0 and LinearContact(1e7).stiffness == 1e7


def test_the_stiffest_allowed_kcb_is_resolved_by_the_coarsest_mesh():
    # At 1e7 N/m (a 0.24 ms contact) the COR of a 10-element frame is within 2e-3 of 80
    # elements' (measured -0.2126 vs -0.2134); at 1e12 they differed by 0.35.
    coarse, fine = (simulate(kcb=1e7, elements=e, output_step=None).cor for e in (10, 80))
    assert coarse == pytest.approx(fine, abs=2e-3)
    assert fine == pytest.approx(-0.2134, abs=5e-4)


def test_a_run_file_at_the_top_of_the_range_runs(cwd):
    with open("run.toml", "w") as f:
        f.write("[contact]\nkcb_n_m = 1e7\n")
    assert load_config("run.toml").simulate().cor == pytest.approx(-0.2134, abs=5e-4)
