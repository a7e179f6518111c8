"""Generic symmetric and skew matrices (s.generic(name, m, m, "sym" | "skew")): the same matrix under every
method, refused alike when ill-formed, told apart from the general matrix of the same name, and declared in a
dimension-free certificate so that no general letter can pass for one."""
from __future__ import annotations

import json

import pytest

from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.ir import compile_claim
from stiefelsym.ir.replay import GraphClaim
from stiefelsym.ir.trace import TraceRefused, trace
from stiefelsym.run.runner import run_one
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
POINT_METHODS = ("exact", "rational", "modular", "float")


def _claim(func, cid="kinds-toy", kind="id"):
    return Claim(id=cid, paper=("toy",), kind=kind, section="", func=func, sizes=admissible(n_max=4))


def sym_and_skew(s):
    S, K = s.generic("S", "n", "n", "sym"), s.generic("K", "r", "r", "skew")
    return {"S - S^T": S - S.T, "K + K^T": K + K.T, "tr(S xi)": s.tr(S @ s.xi),
            "tr(K Psi-sym)": s.tr(K @ (s.Psi + s.Psi.T)),
            # residuals that need the constraint XᵀX = I: the certificate then writes the letters
            "S X XtX - S X": S @ s.X @ s.X.T @ s.X - S @ s.X, "X K XtX - X K": s.X @ K @ s.X.T @ s.X - s.X @ K}


def not_symmetric(s):
    return {"tr(S S)": s.tr(s.generic("S", "n", "n", "sym") @ s.generic("S", "n", "n", "sym"))}


def skew_is_not_symmetric(s):
    K = s.generic("K", "n", "n", "skew")
    return {"K - K^T": K - K.T}


def general_is_not_symmetric(s):
    """A general matrix and a symmetric one are two matrices (under two names: one name names one parameter)."""
    return {"G - G_sym": s.generic("G", "n", "n") - s.generic("H", "n", "n", "sym")}


def general_and_symmetric_of_one_name(s):
    """Two parameters of one name (stop 88, h1 I1: they printed alike, G − G read 0): refused when traced."""
    return {"G - G_sym": s.generic("G", "n", "n") - s.generic("G", "n", "n", "sym")}


@pytest.mark.parametrize("method", (*POINT_METHODS, "free"))
def test_two_kinds_of_one_name_are_refused_under_every_method(method):
    r = run_one(_claim(general_and_symmetric_of_one_name), None if method == "free" else Size(4, 2), method, 0)
    assert r.verdict == "error" and "needs a name of its own" in r.message, (method, r.verdict, r.message)


@pytest.mark.parametrize("method", POINT_METHODS)
def test_symmetric_and_skew_hold_under_every_point_method(method):
    r = run_one(_claim(sym_and_skew), Size(4, 2), method, 0)
    assert r.verdict in ("proved", "checked", "numeric"), (method, r.verdict, r.message)


@pytest.mark.parametrize("func", [not_symmetric, skew_is_not_symmetric, general_is_not_symmetric])
@pytest.mark.parametrize("method", POINT_METHODS)
def test_negative_controls_fail_with_a_witness(method, func):
    r = run_one(_claim(func), Size(4, 2), method, 0)
    assert r.verdict == "fails", (method, func.__name__, r.verdict, r.message)
    assert r.witness


def test_the_free_method_proves_it_for_every_size_with_an_accepted_certificate():
    r = run_one(_claim(sym_and_skew), None, "free", 0)
    assert r.verdict == "proved", r.message
    data = json.loads(json.dumps(r.certificate_data))
    assert check_certificate(data).accepted
    assert data["letters"]["gen:S[nxn]:sym"] == {"kind": "generic", "row": "n", "col": "n",
                                                 "transpose": "gen:S[nxn]:sym", "sign": 1}
    assert data["letters"]["gen:K[rxr]:skew"]["sign"] == -1
    for func in (not_symmetric, skew_is_not_symmetric, general_is_not_symmetric):
        assert run_one(_claim(func), None, "free", 0).verdict != "proved", func.__name__


def _forged(data: dict, name: str, change: dict) -> dict:
    out = json.loads(json.dumps(data))
    out["letters"][name] = {**out["letters"][name], **change}
    return out


def test_the_checker_refuses_a_letter_declared_its_own_transpose_against_its_name():
    data = run_one(_claim(sym_and_skew), None, "free", 0).certificate_data
    for name, change in (("gen:S[nxn]:sym", {"sign": -1}), ("gen:S[nxn]:sym", {"col": "r"}),
                         ("gen:K[rxr]:skew", {"sign": 1}), ("gen:S[nxn]:sym", {"sign": 2})):
        rep = check_certificate(_forged(data, name, change))
        assert not rep.accepted, (name, change)
    # a letter whose name is not a symmetric or skew one cannot be declared its own transpose
    forged = json.loads(json.dumps(data))
    forged["letters"]["gen:G"] = {"kind": "generic", "row": "n", "col": "n", "transpose": "gen:G", "sign": 1}
    assert not check_certificate(forged).accepted
    # nor can a general letter take another letter for its transpose (a symmetric one, or another general one)
    for t in ("gen:S[nxn]:sym", "gen:H[nxn]", "gen:G[nxn]^T^T"):
        forged = json.loads(json.dumps(data))
        forged["letters"]["gen:G[nxn]"] = {"kind": "generic", "row": "n", "col": "n", "transpose": t}
        assert not check_certificate(forged).accepted, t


@pytest.mark.parametrize("bad", [("S", "n", "r", "sym"), ("S", "n", "n", "hermitian"), ("S", "n", "n", 1)])
def test_an_ill_formed_kind_is_refused_when_traced_the_same_for_every_method(bad):
    def claim(s):
        return {"x": s.generic(*bad)}
    with pytest.raises(TraceRefused, match="the kinds are 'general', 'sym' and 'skew'"):
        compile_claim(claim, None, None, CONS)
    messages = {run_one(_claim(claim), Size(3, 3), m, 0).message for m in POINT_METHODS}
    assert len(messages) == 1, messages


def test_a_general_matrix_keeps_its_node_and_the_kind_replays():
    def general(s):
        return {"G": s.generic("G", "n", "r")}
    g = compile_claim(general, None, None, CONS)
    assert [a[2] for op, a in zip(g.ops, g.args) if op == "call" and a[1] == "generic"] == [("G", "n", "r")]
    h = compile_claim(sym_and_skew, None, None, CONS)
    assert ("S", "n", "n", "sym") in [a[2] for op, a in zip(h.ops, h.args) if op == "call" and a[1] == "generic"]
    assert trace(GraphClaim(h), None, None, CONS).digest() == h.digest()


def test_the_rank_of_lambda1_on_gl7_is_proved_exactly_and_a_wrong_rank_is_not():
    """pencil-leaves-singular at n = 7: the kernel certificate in powers of y + yᵀ = 2S (S generic symmetric)."""
    from stiefelsym.claims import load_catalog
    c = next(c for c in load_catalog() if c.id == "pencil-leaves-singular")
    r = run_one(c, Size(7, 1), "exact", 0)
    assert r.verdict == "proved", r.message
    assert any("kernel vector" in x for x in r.checks.values()) if isinstance(r.checks, dict) else True

    import sys
    from stiefelsym import Rank
    mod = sys.modules[c.func.__module__]     # the catalog's module (imported once: its claims are registered)
    generic_gl, kernel_generic_lambda1, lambda1 = mod.generic_gl, mod.kernel_generic_lambda1, mod.lambda1

    def wrong(s):
        y = generic_gl(s)
        return {"rank": Rank(lambda1(s, y), s.n * s.n - s.n + 1, generic=True, kernel=kernel_generic_lambda1(s, y))}
    bad = Claim(id="wrong-rank", paper=("toy",), kind="dim", section="", func=wrong, sizes=admissible(n_max=7))
    assert run_one(bad, Size(6, 1), "exact", 0).verdict == "fails"


def transpose_under_the_trace(s, kind):
    """tr(GM) = tr(GᵀM): true for a symmetric M, false for a skew one (there tr(GᵀK) = −tr(GK)); read entry by
    entry as well, so that the exact method takes the unconstrained chart beside the algebra."""
    G, M = s.generic("G", "n", "n"), s.generic("M", "n", "n", kind)
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.n):
            acc = acc + G[i, j] * M[j, i] - G[j, i] * M[j, i]
    return {"tr(GM) - tr(G^T M)": s.tr(G @ M) - s.tr(G.T @ M), "by entries": acc * s.X[0, 0]}


@pytest.mark.parametrize("method", POINT_METHODS + ("free",))
def test_a_careless_symmetry_is_refuted_and_the_true_one_passes(method):
    size = None if method == "free" else Size(3, 2)
    true = run_one(_claim(lambda s: transpose_under_the_trace(s, "sym")), size, method, 0)
    false = run_one(_claim(lambda s: transpose_under_the_trace(s, "skew")), size, method, 0)
    assert false.verdict not in ("proved", "checked", "numeric"), (method, false.verdict)
    if method != "free":
        assert false.verdict == "fails" and true.verdict in ("proved", "checked", "numeric"), (method, true.verdict)
