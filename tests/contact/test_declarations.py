"""Every law's parameters as declared: a field and a key left out are derived (the field is the
name, the key the name and its unit's suffix), and nothing a user sees moves.

The table below is what the declarations held when each one still wrote its field and key out
(the run-file keys and JSON keys are part of the contract: renaming one breaks run files).
"""

import pytest

from fem_racket.contact.linear import LinearContact
from fem_racket.contact.parameters import KEY_SUFFIXES, LawParameter
from fem_racket.contact.registry import FAMILIES

#: Each declaration: law | name | field | unit | default | bounds (as messages show them,
#: :meth:`LawParameter.interval`) | key. The defaults of linear: the paper's K_CB at 20 m/s and
#: zeta_from_cor(0.83), eq (4).
EXPECTED = """
linear | kcb | stiffness | N/m | 27400.0 | [100, 1e+07] | kcb_n_m
linear | zeta | zeta | - | 0.05920650167927682 | [0, 1) | zeta
hunt-crossley | hc_stiffness | stiffness | N/m^n | 2.978e+24 | [100, 1e+40] | hc_stiffness_n_m_n
hunt-crossley | hc_exponent | exponent | - | 14.87 | [1, 20] | hc_exponent
hunt-crossley | hc_alpha | alpha | s/m | 0.009905 | [0, 10] | hc_alpha_s_m
hysteretic | k1 | k1 | N/m^n | 3182000000000000.0 | [100, 1e+40] | k1_n_m_n
hysteretic | k2 | k2 | N/m^n | 8.816e+16 | [100, 1e+40] | k2_n_m_n
hysteretic | hyst_exponent | exponent | - | 8.913 | [1, 20] | hyst_exponent
series | ball_stiffness | ball_stiffness | N/m | 98230.0 | [1000, 1e+08] | ball_stiffness_n_m
series | ball_damping | ball_damping | N s/m | 17.06 | [0.01, 1000] | ball_damping_n_s_m
series | string_stiffness | string_stiffness | N/m | 1559.0 | [1, 1e+07] | string_stiffness_n_m
series | string_cubic | string_cubic | N/m^3 | 831700000.0 | [0, 1e+15] | string_cubic_n_m3
"""
#: Each parameter's ``--help`` line.
HELP = {
    "kcb": "ball/string stiffness K_CB",
    "zeta": "ball/string damping ratio",
    "hc_stiffness": "Hunt-Crossley stiffness k of F = k delta^n (1 + alpha delta')",
    "hc_exponent": "Hunt-Crossley exponent n",
    "hc_alpha": "Hunt-Crossley damping alpha = lambda / k",
    "k1": "hysteretic loading stiffness k1 (F = k1 delta^n)",
    "k2": "hysteretic unloading stiffness k2",
    "hyst_exponent": "hysteretic exponent n",
    "ball_stiffness": "series law: ball stiffness K_b",
    "ball_damping": "series law: ball damping C_b",
    "string_stiffness": "series law: string-bed stiffness k_s",
    "string_cubic": "series law: string-bed cubic stiffness k_3",
}
LAWS = (LinearContact, *FAMILIES.values())


def test_every_law_declares_the_same_keys_fields_units_defaults_and_bounds():
    declared = [
        (law.name, p.name, p.field, p.unit, repr(p.default), p.interval(), p.key)
        for law in LAWS
        for p in law.declared
    ]
    assert declared == [tuple(line.split(" | ")) for line in EXPECTED.strip().splitlines()]


def test_every_law_declares_the_same_help():
    assert {p.name: p.help for law in LAWS for p in law.declared} == HELP


def test_a_key_and_a_field_given_are_kept():
    p = LawParameter(
        name="toy_k", field="stiffness", unit="N/m", default=1.0, low=0.0, high=2.0,
        key="toy_k_in_n_m", help="h", why="w",
    )  # fmt: skip
    assert (p.field, p.key) == ("stiffness", "toy_k_in_n_m")


def test_a_unit_without_a_key_suffix_needs_its_key():
    assert "kg" not in KEY_SUFFIXES
    with pytest.raises(ValueError, match="unit 'kg' of 'toy_mass' has no key suffix: give key"):
        LawParameter(name="toy_mass", unit="kg", default=1.0, low=0.0, high=2.0, help="h", why="w")


def test_a_declaration_is_keywords_only():
    # the field and the key may be left out, so the order of the arguments carries no meaning
    with pytest.raises(TypeError):
        LawParameter("toy_k", "stiffness", "N/m", 1.0, 0.0, 2.0, "toy_k_n_m", "h", "w")
