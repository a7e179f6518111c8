"""A pairing <x, y> = -1/2 tr(x y) of a product or commutator that no other node reads is reassociated.

The evaluator computes <x, a b> as <x a, b>, and <x, [a, b]> as <[x, a], b>, when the product (or the
commutator) is read by the pairing alone, on the fixed-size scenes whose backend fuses traces: a Lie-Poisson
bracket -<ξ, [∇f, ∇g]> of many pairs of functions then computes [ξ, ∇f] once per function, and one pairing
per pair (the chain algebra of §2 at n = 7: 12-19 s before, 1.5 s after).  The value is the same rational
function (tr(x(ab - ba)) = tr((xa - ax)b)), so verdicts, residuals and witnesses do not change, and a
corrupted bracket is still refuted.
"""
from __future__ import annotations

import pytest

from stiefelsym import admissible, comm
from stiefelsym.claims import Claim
from stiefelsym.ir.evaluate import _deps, _paired_products
from stiefelsym.methods.fixed_size import run_exact, run_points


def _claim(func, cid="paired-product"):
    return Claim(id=cid, paper=("test",), kind="id", section="t", func=func, sizes=admissible(4))


def _gradients(s):
    """Two matrices of so(n) from the point and a generic n x n matrix M (each read by several pairings)."""
    F = s.X @ s.P.T - s.P @ s.X.T
    G = s.A @ F - F @ s.A
    return F, G, s.generic("M", "n", "n")


def bracket_vs_entries(s):
    """<M, [F, G]> and <A + M, F M> (fused) against -1/2 the traces of the same products made otherwise
    (not fused: the diagonal of (M F) G - (M G) F, and the trace of ((A + M) F) M)."""
    F, G, M = _gradients(s)
    H = (M @ F) @ G - (M @ G) @ F
    diag = s.q(0)
    for i in range(s.n):
        diag = diag + H[i, i]
    return {"<M, [F, G]> + 1/2 tr(M F G - M G F)": s.killing(M, comm(F, G)) + diag / 2,
            "<A + M, F M> + 1/2 tr((A + M) F M)": s.killing(s.A + M, F @ M) + s.tr(((s.A + M) @ F) @ M) / 2}


def ad_invariance(s):
    """<x, [a, b]> = <[x, a], b> for the pairing (both sides fused, each as a commutator)."""
    F, G, M = _gradients(s)
    return {"<M, [F, G]> - <[M, F], G>": s.killing(M, comm(F, G)) - s.killing(comm(M, F), G)}


def bracket_sign_flipped(s):
    """False: <M, [F, G]> = <[M, G], F> (ad-invariance with a sign lost)."""
    F, G, M = _gradients(s)
    return {"<M, [F, G]> - <[M, G], F>": s.killing(M, comm(F, G)) - s.killing(comm(M, G), F)}


def product_order_swapped(s):
    """False: <A, F M> = <A, M F> (the pairing of a product is not symmetric in the product's factors)."""
    F, _, M = _gradients(s)
    return {"<A, F M> - <A, M F>": s.killing(s.A, F @ M) - s.killing(s.A, M @ F)}


def product_plus_as_commutator(s):
    """False: <M, F G + G F> = <M, [F, G]> (a sum of products is not a commutator)."""
    F, G, M = _gradients(s)
    return {"<M, FG + GF> - <[M, F], G>": s.killing(M, F @ G + G @ F) - s.killing(comm(M, F), G)}


def shared_product(s):
    """<M, F G> + <A, F G>: the product F G is read by two pairings (not reassociated), and <A, [F, M]> is."""
    F, G, M = _gradients(s)
    P = F @ G
    return {"pairings": s.killing(M, P) + s.killing(s.A, P) + s.killing(s.A, comm(F, M))}


def sum_of_commutators(s):
    """<M, [F, G] + [Φ, A] − [G, Φ] + Φ F> (three commutators and a product, one of them negated; fused) against
    −1/2 the traces of the same products associated otherwise, (M F) G, ... (other nodes: not fused)."""
    F, G, M = _gradients(s)
    whole = (s.tr((M @ F) @ G) - s.tr((M @ G) @ F) + s.tr((M @ s.Phi) @ s.A) - s.tr((M @ s.A) @ s.Phi)
             - s.tr((M @ G) @ s.Phi) + s.tr((M @ s.Phi) @ G) + s.tr((M @ s.Phi) @ F))
    return {"<M, sum> + 1/2 tr(M sum)": s.killing(M, comm(F, G) + comm(s.Phi, s.A) - comm(G, s.Phi) + s.Phi @ F)
            + whole / 2}


def commutator_negative_first(s):
    """<M, −F G + G F> (the commutator [G, F] with its negative product first: paired as −<[M, F], G>)
    against −1/2 the trace of the same products associated otherwise."""
    F, G, M = _gradients(s)
    return {"<M, -FG + GF> + 1/2 tr(M (GF - FG))": s.killing(M, -(F @ G) + G @ F)
            + s.tr((M @ G) @ F - (M @ F) @ G) / 2}


def sum_of_commutators_one_sign_lost(s):
    """False: <M, [F, G] + [Φ, A]> = <M, [F, G] − [Φ, A]>."""
    F, G, M = _gradients(s)
    return {"<M, [F, G] + [Phi, A]> - <M, [F, G] - [Phi, A]>":
            s.killing(M, comm(F, G) + comm(s.Phi, s.A)) - s.killing(M, comm(F, G) - comm(s.Phi, s.A))}


def negated_commutator_as_product(s):
    """False: <M, −[F, G]> = <M, −Φ F> (a negated commutator against a negated product)."""
    F, G, M = _gradients(s)
    return {"<M, -[F, G]> - <M, -Phi F>": s.killing(M, -comm(F, G)) - s.killing(M, -(s.Phi @ F))}


@pytest.mark.parametrize("n,r", [(3, 1), (3, 2), (4, 2)])
def test_a_fused_pairing_equals_the_pairing_computed_whole(n, r):
    assert run_exact(_claim(bracket_vs_entries), n, r, 0).verdict == "proved"
    assert run_exact(_claim(ad_invariance), n, r, 0).verdict == "proved"
    assert run_exact(_claim(sum_of_commutators), n, r, 0).verdict == "proved"
    assert run_exact(_claim(commutator_negative_first), n, r, 0).verdict == "proved"


@pytest.mark.parametrize("func", [bracket_sign_flipped, product_order_swapped, product_plus_as_commutator,
                                  sum_of_commutators_one_sign_lost, negated_commutator_as_product])
def test_a_corrupted_pairing_is_refuted_by_every_method(func):
    c = _claim(func, "paired-product-false")
    assert run_exact(c, 3, 2, 0).verdict == "fails"
    assert run_points(c, 3, 2, "modular", 0).verdict == "fails"
    assert run_points(c, 3, 2, "rational", 0).verdict == "fails"


def test_only_a_product_read_by_the_pairing_alone_is_reassociated():
    """A product that another node reads too is computed as it is (the same node: hash-consed)."""
    from stiefelsym.ir import compile_claim
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]
    for func, fused in ((bracket_vs_entries, 2), (ad_invariance, 2), (product_plus_as_commutator, 2),
                        (shared_product, 1), (sum_of_commutators, 1), (negated_commutator_as_product, 2),
                        (commutator_negative_first, 1)):
        g = compile_claim(func, 3, 2, (cons.name, cons.build))
        assert len(_paired_products(g, _deps(g))) == fused, func.__name__


# -- traces of a sum of products, and products a pairing shares with others (stop 83) ------------------------

def _family(s):
    """Six matrices of so(n) and two points x, x − A of gl(n), as the Lie-Poisson forms of §6 pair them."""
    F, G, M = _gradients(s)
    S, K = s.Phi - s.Phi.T, M - M.T
    return [F, G, S, K, comm(F, S), comm(G, K)], M, M - s.A


def forms_on_a_family(s):
    """tr(x [z, w]) − tr((x − A) [z, w]) = tr(A [z, w]) for every pair of a family, the commutators shared by the two
    traces ([z, z] cancels uncomputed in both), against the same traces computed otherwise."""
    zs, x, y = _family(s)
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            c = comm(z, w)
            out[f"({i},{j})"] = s.tr(x @ c) - s.tr(y @ c) - s.tr((s.A @ z) @ w) + s.tr((s.A @ w) @ z)
    return out


def forms_on_a_family_swapped(s):
    """False: tr(x [z, w]) − tr((x − A) [z, w]) = tr(A [w, z])."""
    zs, x, y = _family(s)
    return {f"({i},{j})": s.tr(x @ comm(z, w)) - s.tr(y @ comm(z, w)) - s.tr(s.A @ comm(w, z))
            for i, z in enumerate(zs) for j, w in enumerate(zs) if i != j}


def self_commutator(s):
    """tr(x [z, z]) = 0: the product z z and its negative cancel and are not computed."""
    zs, x, y = _family(s)
    return {"tr(x [z, z])": [s.tr(x @ comm(z, z)) for z in zs], "tr(z [y, y])": s.tr(zs[0] @ comm(y, y))}


def self_commutator_of_a_pole(s):
    """tr(x [z, z]) with z = (0 · M)⁻¹: a factor of a cancelled product is still computed, and it has no value."""
    _, x, _ = _family(s)
    z = (s.generic("M", "n", "n") * 0).inv()
    return {"tr(x [z, z])": s.tr(x @ comm(z, z))}


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_traces_of_a_cancelled_commutator_are_fused_and_equal(n, r):
    from stiefelsym.ir import compile_claim
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]
    g = compile_claim(forms_on_a_family, n, r, (cons.name, cons.build))
    fused = _paired_products(g, _deps(g))
    # tr(x[z,z]) and tr((x−A)[z,z]): their products cancel, nothing is multiplied; tr(x[z,w]) for z ≠ w is not
    # reassociated (fewer products are not less work where [x, z] has larger entries than z w)
    assert sum(1 for v in fused.values() if v[3] == "tr") == 12
    assert run_exact(_claim(forms_on_a_family), n, r, 0).verdict == "proved"
    assert run_exact(_claim(self_commutator), n, r, 0).verdict == "proved"


def test_a_corrupted_trace_of_a_commutator_is_refuted():
    c = _claim(forms_on_a_family_swapped, "paired-trace-false")
    assert run_exact(c, 3, 2, 0).verdict == "fails"
    assert run_points(c, 3, 2, "modular", 0).verdict == "fails"


def test_a_cancelled_product_still_computes_its_factors():
    """The commutator [z, z] is 0 without its products, but z itself must exist: the pole is met."""
    res = run_exact(_claim(self_commutator_of_a_pole, "paired-pole"), 3, 1, 0)
    assert res.verdict != "proved", res
