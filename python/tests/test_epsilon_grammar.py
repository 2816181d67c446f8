"""One table of tolerances written as text (test/epsilon_grammar_cases.tsv), run against both
front ends that read them: the batch's ``eps`` and the command-line tool's ``--eps``. A text
must mean the same number to both, down to the bit, or be refused by both."""

import os
import subprocess

import numpy as np
import pytest

import cgal_constrained_fairing as cf
from cgal_constrained_fairing.batch._epsilon import mesh_epsilon, parse_eps

from conftest import DATA, ROOT


def _cases():
    with open(ROOT / "test" / "epsilon_grammar_cases.tsv", encoding="utf-8") as table:
        rows = [line.rstrip("\n").split("\t") for line in table if not line.startswith("#")]
    return [pytest.param(text, meaning, id=repr(text)) for text, meaning in rows]


CASES = _cases()
TOOL = os.environ.get("CONSTRAINED_FAIRING_TOOL")
MESH = DATA / "head.off"


@pytest.fixture(scope="module")
def head():
    return cf.read_mesh(MESH)


def _expected(meaning, V, F):
    kind, _, number = meaning.partition(" ")
    if kind == "auto":
        return cf.estimate_noise_level(V, F)
    if kind == "h":
        return float(number) * cf.mean_edge_length(V, F)
    return float(number)


def test_the_table_covers_every_kind():
    kinds = {meaning.partition(" ")[0] for _, meaning in (case.values for case in CASES)}
    assert kinds == {"value", "h", "auto", "error"}


@pytest.mark.parametrize("text,meaning", CASES)
def test_batch(text, meaning, head):
    V, F = head
    if meaning == "error":
        with pytest.raises(ValueError, match="eps"):
            parse_eps(text)
        return
    assert mesh_epsilon(parse_eps(text), V, F) == _expected(meaning, V, F)


@pytest.mark.skipif(TOOL is None, reason="CONSTRAINED_FAIRING_TOOL names no built tool")
@pytest.mark.parametrize("text,meaning", CASES)
def test_tool(text, meaning, head, tmp_path):
    out = tmp_path / "faired.off"
    run = subprocess.run([TOOL, "--eps", text, str(MESH), str(out)], capture_output=True, text=True)
    if meaning == "error":
        assert run.returncode != 0
        assert run.stderr.startswith("error: --eps ") and run.stderr.count("\n") == 1, run.stderr
        assert not out.exists()
        return
    assert run.returncode == 0, run.stderr
    V, F = head
    # The tool's result is that of the library called with the batch's epsilon, bit for bit.
    W, _ = cf.fair(V, F, mesh_epsilon(parse_eps(text), V, F))
    assert np.array_equal(cf.read_mesh(out)[0], W)
