"""The Python module against the library's settings (``Fairing_settings.h``, through
``_core.default_settings`` and ``_core.named_settings``): the keywords of `fair` and how they are
read, their docstrings' defaults, and the tolerance of the batch. A default changed in the code
fails here until every docstring that states it is changed too; the C++ texts (the manuals, the
README, the tool's usage) are checked by test/test_documented_defaults.cpp."""

import inspect
import re

import cgal_constrained_fairing as cf
from cgal_constrained_fairing import _core
from cgal_constrained_fairing._fairing import SETTING_ARGUMENTS
from cgal_constrained_fairing.batch import fair_files


QUASI_NEWTON = _core.default_settings(_core.Method.QUASI_NEWTON)
PAPER = _core.default_settings(_core.Method.ACTIVE_SET_NEWTON)


def percent(fraction):
    """A fraction as the texts state it, in percent: ``0.01`` as ``"1 %"``, ``0.005`` as
    ``"0.5 %"``."""
    return f"{round(100 * fraction, 12):g} %"


def number(x):
    """``1000``, ``1.25e-4``, ``1e-3``: integers as integers, others in the shortest
    scientific form."""
    if float(x).is_integer():
        return str(int(x))
    mantissa, exponent = f"{x:.15e}".split("e")
    return f"{float(mantissa):g}e{int(exponent)}"


def test_the_paper_s_methods_share_their_defaults():
    assert PAPER == _core.default_settings(_core.Method.PROJECTED_GRADIENT)


def _docstring_sections(function):
    """Each parameter's text in a numpy-style docstring."""
    doc = inspect.getdoc(function)
    parameters = doc.split("Parameters\n----------\n", 1)[1].split("\n\n")[0]
    sections = re.split(r"\n(?=\w+ :)", parameters)
    return {section.split(" :", 1)[0]: " ".join(section.split()) for section in sections}


def test_fair_docstring():
    sections = _docstring_sections(cf.fair)
    q, p = QUASI_NEWTON, PAPER
    expected = {
        "fidelity_weight": f"(default {number(q['fidelity_weight'])})",
        "max_iterations": f"(default {q['max_iterations']} for the default method, "
                          f"{p['max_iterations']} for the paper's)",
        "energy_decrease_threshold": f"(averaged over {q['energy_decrease_window']} iterations for "
                                     f"the default method; default "
                                     f"{number(q['energy_decrease_threshold'])}, and "
                                     f"{number(p['energy_decrease_threshold'])} for the paper's",
        "sliver_barrier_weight": f"(default {number(q['sliver_barrier_weight'])}, per triangle)",
        "initial_smoothing_steps": f"(default {q['initial_smoothing_steps']} for the default "
                                   f"method, {p['initial_smoothing_steps']} for the paper's",
        "conjugate_gradient_iterations": f"default {p['conjugate_gradient_iterations']})",
    }
    for name, text in expected.items():
        assert text in sections[name], (name, sections[name])
    remaining = f"still to come is at most {percent(q['energy_remaining_fraction'])} of the energy"
    assert remaining in " ".join(sections["energy_decrease_threshold"].split())
    assert p["remaining_motion"] == 0 < q["remaining_motion"]
    motion = f"left to move across itself is at most {percent(q['remaining_motion'])} of `epsilon`"
    assert motion in " ".join(sections["energy_decrease_threshold"].split())
    assert f'``"{q["objective"].name.lower()}"`` (the default)' in sections["objective"]


def test_named_settings_are_the_keywords_of_fair():
    """The C++ table of named settings, the keywords that `fair` reads them from and how it reads
    each one (``SETTING_ARGUMENTS``) agree, and each keyword is documented."""
    names = [name for name, _ in _core.named_settings()]
    assert sorted(names) == sorted(SETTING_ARGUMENTS)
    assert set(names) == set(QUASI_NEWTON) - {"energy_decrease_window", "energy_remaining_fraction",
                                              "remaining_motion"}
    keywords = inspect.signature(cf.fair).parameters
    sections = _docstring_sections(cf.fair)
    for name in names:
        assert keywords[name].kind == inspect.Parameter.KEYWORD_ONLY and keywords[name].default is None
        assert name in sections, name


def test_default_tolerance_of_the_front_ends():
    assert inspect.signature(fair_files).parameters["eps"].default == _core.default_epsilon
    assert f'(default ``"{_core.default_epsilon}"``)' in " ".join(inspect.getdoc(fair_files).split())
