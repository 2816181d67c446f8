"""The defaults as the documentation states them, against the library's settings
(``Fairing_settings.h``, through ``_core.default_settings``): the docstring of `fair`, the
reference manual's named parameters (``constrained_fairing.h``), the user manual, the README,
and the tolerance of the tool and the batch. A default changed in the code fails here until
every text that states it is changed too."""

import functools
import inspect
import math
import re

import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing import _core
from cgal_constrained_fairing.batch import fair_files

from conftest import ROOT

QUASI_NEWTON = _core.default_settings(_core.Method.QUASI_NEWTON)
PAPER = _core.default_settings(_core.Method.ACTIVE_SET_NEWTON)
WORDS = {3: "three"}


def percent(fraction):
    """A fraction as the texts state it, in percent: ``0.01`` as ``"1 %"``."""
    return f"{number(round(100 * fraction, 12))} %"


def number(x):
    """``1000``, ``1.25e-4``, ``1e-3``: integers as integers, others in the shortest
    scientific form."""
    if float(x).is_integer():
        return str(int(x))
    mantissa, exponent = f"{x:.15e}".split("e")
    return f"{float(mantissa):g}e{int(exponent)}"


def test_the_paper_s_methods_share_their_defaults():
    assert PAPER == _core.default_settings(_core.Method.PROJECTED_GRADIENT)


def test_number_format():
    assert (number(1000), number(1.25e-4), number(1e-3), number(1e4)) == ("1000", "1.25e-4", "1e-3",
                                                                          "10000")


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
    assert inspect.signature(cf.fair).parameters["objective"].default == q["objective"].name.lower()


@functools.lru_cache(maxsize=None)
def _reference_manual():
    """The text of constrained_fairing.h, read once for the tests that check it."""
    return (ROOT / "include/CGAL/Polygon_mesh_processing/constrained_fairing.h").read_text()


def _reference_defaults():
    """``\\cgalParamDefault{...}`` of each named parameter of constrained_fairing.h."""
    blocks = re.findall(r"\\cgalParamNBegin\{(\w+)\}(.*?)\\cgalParamNEnd", _reference_manual(), re.S)
    return {name: re.search(r"\\cgalParamDefault\{(.*)\}", block).group(1) for name, block in blocks}


def test_reference_manual():
    defaults = _reference_defaults()
    q, p = QUASI_NEWTON, PAPER

    def per_method(key):
        return f"`{number(q[key])}` for `QUASI_NEWTON`, `{number(p[key])}` for the paper's methods"

    header = " ".join(_reference_manual().split())
    remaining = percent(q["energy_remaining_fraction"])
    assert f"is at most {remaining} of the energy) or the last three" in header
    assert f"decrease still to come is at most {remaining} of the energy" in header
    assert p["energy_remaining_fraction"] == 0
    assert defaults["number_of_iterations"] == per_method("max_iterations")
    assert defaults["energy_decrease_threshold"] == per_method("energy_decrease_threshold")
    assert defaults["initial_smoothing_steps"] == per_method("initial_smoothing_steps")
    assert defaults["fidelity_weight"] == f"`{number(q['fidelity_weight'])}`"
    assert defaults["sliver_barrier_weight"] == f"`{number(q['sliver_barrier_weight'])}`"
    assert defaults["conjugate_gradient_iterations"] == f"`{p['conjugate_gradient_iterations']}`"
    assert defaults["fairing_objective"] == f"`Constrained_fairing_objective::{q['objective'].name}`"


def test_user_manual_and_readme():
    manual = " ".join((ROOT / "doc/Constrained_fairing/Constrained_fairing.txt").read_text().split())
    q, p = QUASI_NEWTON, PAPER
    exponent = round(math.log10(q["fidelity_weight"]))
    assert 10.0 ** exponent == q["fidelity_weight"]
    for text in (f"by default `{number(q['energy_decrease_threshold'])}` over the last "
                 f"{q['energy_decrease_window']} iterations for the quasi-Newton method",
                 f"`{number(p['energy_decrease_threshold'])}` over the last "
                 f"{WORDS.get(p['energy_decrease_window'], p['energy_decrease_window'])} for the "
                 "paper's methods",
                 f"`number_of_iterations` (default {q['max_iterations']} for the quasi-Newton method, "
                 f"{p['max_iterations']} for the others)",
                 f"`conjugate_gradient_iterations` (default {p['conjugate_gradient_iterations']})",
                 f"`sliver_barrier_weight` (default {number(q['sliver_barrier_weight'])};",
                 f"`fidelity_weight` (default \\f$ 10^{exponent} \\f$;",
                 f"waits until what is left to gain is at most {percent(q['energy_remaining_fraction'])} "
                 "of the energy"):
        assert text in manual, text
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert f"`number_of_iterations` (default {q['max_iterations']})" in readme
    assert f"is at most {percent(q['energy_remaining_fraction'])} of the energy" in readme


def test_default_tolerance_of_the_front_ends():
    assert inspect.signature(fair_files).parameters["eps"].default == _core.default_epsilon
    assert f'(default ``"{_core.default_epsilon}"``)' in " ".join(inspect.getdoc(fair_files).split())
    usage = (ROOT / "tools/constrained_fairing.cpp").read_text()
    assert f"Default: {_core.default_epsilon}," in usage
