"""The complex point of the exact method reduced by U(r) acting on the right (S11 = 0; Z = I at r = n):
the pass accepts the graphs covariant under (Z, Ż) -> (Z R(h), Ż R(h)) and refuses a graph that joins a
side of C^r to its conjugate (tr ZᵀZ) or reads an entry; the reduction is stated in the record; a
corrupted claim is refuted exactly on the reduced chart, and a statement true on the reduced chart only
(Z = I at r = n, read through tr ZᵀZ) is refused the reduction and fails."""
from __future__ import annotations

import pytest

import stiefelsym.proofs.app2_double_coupled_complex as c
from stiefelsym import admissible
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.methods import complex_right
from stiefelsym.methods.complex_right import unitary_right_breaks
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.scene import REALIZATIONS, Scene
from stiefelsym.systems import complex_point, ctranspose, derivative, re_trace

UNITARY = "reduced by U(r) acting on the right"


def _claim(func, cid="t-unitary-right"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _graph(func, n, r):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def _psi0_without_conjugation(s):
    """ψ₀ written ZᵀŻ − ŻᵀZ (the conjugations forgotten) conserved along (W-eq): false (its derivative is
    ZᵀZΛ − ΛᵀZᵀZ), and covariant (h acts on it as hᵀ(.)h): the reduction applies."""
    z = complex_point(s)
    psi0 = lambda t, w: ctranspose(t, w["Z"]) @ w["Zdot"] - ctranspose(t, w["Zdot"]) @ w["Z"]
    return {"d psi_0/dt": derivative(s, psi0, z, c.flow_complex(s, z))}


def _z_is_one_at_r_n(s):
    """Re tr(ZᵀZ) = r: true at Z = I (the reduced chart at r = n), false on W(n, n) (Z = e^{iθ}I gives
    r cos 2θ): tr(h^T M h) is not tr M, and the pass must see it (a side joined to its conjugate)."""
    Z = s.Zc
    return {"Re tr(Z^T Z) - r": re_trace(s, ctranspose(s, Z) @ Z) - s.q(s.r)}


def _entry_of_z(s):
    """An entry of Z read: not covariant (the top-left entry of Z is real on the reduced chart at r = n)."""
    Z = s.Zc
    return {"Im Z_11": Z[s.n, 0] + (s.A - s.A)[0, 0]}


def test_the_complex_claims_graphs_are_typed():
    reg = load_catalog()
    mom = reg.get("complex-neumann-momenta")
    lax = reg.get("complex-neumann-dual-lax")
    for f in (mom.func, lax.func, lax.corrections[0].func):
        assert unitary_right_breaks(_graph(f, 3, 2), 3, 2) == [], f.__name__
    # the Euler-Lagrange equations read the coordinates of W(n, r): refused
    assert unitary_right_breaks(_graph(reg.get("complex-neumann-flow").func, 3, 2), 3, 2)
    # a graph without the complex point: no reduction to make
    assert not complex_right.applies(_graph(reg.get("neumann-lax").func, 3, 2), "standard", 3, 2)


@pytest.mark.parametrize("func", [_z_is_one_at_r_n, _entry_of_z])
def test_a_graph_that_is_not_covariant_is_refused_and_its_statement_fails(func):
    g = _graph(func, 3, 3)
    assert unitary_right_breaks(g, 3, 3)
    assert not complex_right.applies(g, "standard", 3, 3)
    s = Scene(2, 2, SymbolicField(), chart="cayley", unitary_right=True)
    assert s.Zc._a[0, 0] == 1 and s.Zc._a[2, 0] == 0         # Z = I on the reduced chart at r = n
    assert all(v == 0 for v in func(s).values())              # so the statement holds there
    res = run_exact(_claim(func), 2, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert not any(UNITARY in x for x in res.reductions), res.reductions


@pytest.mark.parametrize("size", [(2, 2), (3, 2), (3, 3), (5, 5)])
def test_a_corrupted_claim_is_refuted_on_the_reduced_chart(size):
    n, r = size
    assert complex_right.applies(_graph(_psi0_without_conjugation, n, r), "standard", n, r)
    res = run_exact(_claim(_psi0_without_conjugation), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any(UNITARY in x for x in res.reductions), res.reductions


@pytest.mark.parametrize("size", [(3, 2), (3, 3), (6, 6)])
def test_the_momenta_are_proved_on_the_reduced_chart(size):
    n, r = size
    claim = load_catalog().get("complex-neumann-momenta")
    res = run_exact(claim, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(UNITARY in x for x in res.reductions), res.reductions


def test_the_reduced_point_is_on_w_n_r():
    for n, r in ((3, 2), (4, 3), (3, 3), (4, 1), (4, 2)):
        s = Scene(n, r, SymbolicField(), chart="cayley", unitary_right=True)
        Z, Zd = s.Zc, s.Zc_dot
        I = s.identity(2 * r)
        assert ((Z.T @ Z) - I)._a.tolist() == (I - I)._a.tolist()
        N = Z.T @ Zd + Zd.T @ Z          # Z*Ż + Ż*Z = 0
        assert all(x == 0 for x in N._a.flat)


def test_a_correction_widens_its_budget_at_r_close_to_n():
    claim = load_catalog().get("complex-neumann-dual-lax")
    fixed = claim.corrected(0)
    assert not claim.exact_at(5, 5) and fixed.exact_at(5, 5) and fixed.exact_at(7, 7)
    assert not fixed.exact_at(4, 2) and not fixed.exact_at(3, 2)
    with pytest.raises(ValueError):
        claim.correction("t: a corank of n at n", exact_corank={4: 4})
    res = run_exact(fixed, 4, 4, 0, func=claim.corrections[0].func)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(UNITARY in x for x in res.reductions), res.reductions


def test_a_correction_budget_at_r_close_to_n_reaches_a_claims_file(tmp_path):
    from click.testing import CliRunner

    from stiefelsym import cli
    from stiefelsym.api import load
    path = tmp_path / "budget.py"
    path.write_text("from stiefelsym import admissible, claim\n"
                    "@claim('c', paper='t', kind='id', section='9', sizes=admissible(n_max=5), exact_max_n=3,\n"
                    "       fails_at=lambda n, r: True, erratum='X^T X is I_r, not 2 I_r.')\n"
                    "def c(s):\n    return {'XtX': s.X.T @ s.X - 2 * s.Ir}\n"
                    "@c.claim.correction('I_r in place of 2 I_r', exact_corank={5: 1})\n"
                    "def c_corrected(s):\n    return {'XtX': s.X.T @ s.X - s.Ir}\n")
    c = load([path], catalog=False).get("c")
    assert c.corrections[0].exact_corank == ((5, 1),) and not c.exact_at(5, 4)
    assert c.corrected(0).exact_at(5, 4) and c.corrected(0).exact_at(5, 5) and not c.corrected(0).exact_at(5, 3)
    out = CliRunner().invoke(cli.main, ["show", "--claims", str(path), "c"]).output
    assert "correction:  I_r in place of 2 I_r; exact symbolic method also at n - r <= 1 at n = 5" in out
