"""The determinism check: a claim is traced twice and the two graphs must have the same text (the lines the digest
hashes).  The second graph is compared with the first node by node (Graph.same_lines), which says the texts are the
same only where they are: 1, True and Fraction(1) differ as their texts do, and wherever the comparison cannot tell
the second digest decides, so a claim whose two traces differ gets the same refusal as before."""
from __future__ import annotations

import itertools
from fractions import Fraction

import pytest

from stiefelsym.ir import NotDeterministic, compile_claim
from stiefelsym.ir.graph import Graph, Named, Size, _ref
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)


def _graph(*nodes, output=None):
    g = Graph()
    for op, args in nodes:
        g.ops.append(op)
        g.args.append(args)
    g.output = _ref(len(nodes) - 1) if output is None else output
    return g


BASE = (("scene", (0,)), ("attr", (_ref(0), "X")), ("mul", (_ref(1), 1)))


@pytest.mark.parametrize("other", [1, True, Fraction(1), 1.0, "1", (1,), None, Size(1, "n", None), Named("1")])
def test_arguments_equal_in_python_but_not_in_text_are_different_graphs(other):
    a = _graph(*BASE)
    b = _graph(*BASE[:2], ("mul", (_ref(1), other)))
    same_text = other == 1 and type(other) is int
    assert a.same_lines(b) is same_text
    if type(other) is float:
        with pytest.raises(TypeError, match="not an IR argument"):     # no text: the second digest raises
            b.digest()
    else:
        assert (a.lines() == b.lines()) is same_text


def test_a_size_is_compared_by_its_text_and_the_output_and_ops_too():
    a = _graph(("scene", (0,)), ("zeros", (_ref(0), Size(2, "n", 6), Size(1, "r", None))))
    b = _graph(("scene", (0,)), ("zeros", (_ref(0), Size(2, "n", None), Size(1, "r", 2))))
    assert a.lines() == b.lines()           # the value of a size is not in the text: the second digest says so
    assert not a.same_lines(b)              # (equal sizes with other values are left to it)
    assert a.same_lines(_graph(("scene", (0,)), ("zeros", (_ref(0), Size(2, "n", 6), Size(1, "r", None)))))
    c = _graph(("scene", (0,)), ("zeros", (_ref(0), Size(2, "n", 6), Size(1, "n", None))))
    assert not a.same_lines(c)
    other_output = _graph(("scene", (0,)), ("zeros", (_ref(0), Size(2, "n", 6), Size(1, "r", None))), output=_ref(0))
    assert not a.same_lines(other_output) and a.lines() != other_output.lines()
    other_op = _graph(("scene", (0,)), ("ones", (_ref(0), Size(2, "n", 6), Size(1, "r", None))))
    assert not a.same_lines(other_op) and a.lines() != other_op.lines()


class _Op(str):
    """An op that is a str to ==, not to the text."""


def test_what_it_cannot_tell_is_left_to_the_text():
    a = _graph(*BASE)
    b = _graph(*BASE)
    b.ops[2] = _Op("mul")
    assert not a.same_lines(b)                # the digests decide (here: the same text)
    assert a.digest() == b.digest()
    deep: tuple = ()
    for _ in range(5000):
        deep = (deep,)
    c, d = _graph(("nest", (deep,))), _graph(("nest", (deep,)))
    assert not c.same_lines(d)                # too deep to compare here: the text decides


def test_a_claim_whose_traces_differ_only_in_the_type_of_a_constant_is_not_deterministic():
    it = itertools.cycle((1, Fraction(1)))

    def alternating(s):
        """X^T X k - I k, k = 1 then Fraction(1)."""
        k = next(it)
        return {"r": (s.X.T @ s.X) * k - s.Ir * k}
    with pytest.raises(NotDeterministic, match="the claim is not deterministic: two tracings at the same size gave "
                                               "different graphs"):
        compile_claim(alternating, None, None, CONS)

    def steady(s):
        """X^T X - I (deterministic)."""
        return {"r": s.X.T @ s.X - s.Ir}
    assert compile_claim(steady, None, None, CONS).digest()
