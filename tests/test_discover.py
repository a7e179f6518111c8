"""Discovery of conserved quantities: the space found is verified, its dimension is exact at the
points sampled, and a corrupted flow or a corrupted integral is told apart."""
from fractions import Fraction

from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.discover import Integral, Monomial, ansatz, closed_words, conserved, resolve_flow
from stiefelsym.runner import run_one


def test_closed_words_are_one_per_trace_class_and_reduced():
    words = closed_words(2, 1)
    assert ("P", "Pt") in words and ("A", "X", "Xt") in words
    assert all(not any(a == "Xt" and b == "X" for a, b in zip(w, w[1:] + w[:1])) for w in words)
    # tr(PPᵀ) and tr(PᵀP) are one class (rotation), tr(XPᵀ) and tr(PXᵀ) too (transposition)
    assert len({frozenset(w) for w in words}) <= len(words)
    assert len(ansatz(4)) == 25


def test_the_euclidean_neumann_flow_has_its_hamiltonian_and_the_right_momentum():
    flow, _ = resolve_flow("neumann-euclidean")
    d = conserved(flow, Size(4, 2), degree=4, verify=("auto", "free"))
    texts = {I.text() for I in d.integrals}
    assert texts == {"tr(AXXᵀ) + tr(PPᵀ)", "tr(PXᵀPXᵀ)"}, texts
    assert all(I.verified for I in d.integrals)


def test_a_corrupted_flow_loses_the_energy():
    good, _ = resolve_flow("neumann-euclidean")

    def bad(s):
        v = good(s)
        return {"X": v["X"], "P": v["P"] + s.A @ s.X * 2}     # the force with the wrong sign
    d = conserved(bad, Size(4, 2), degree=2, verify=("auto",))
    assert "tr(AXXᵀ) + tr(PPᵀ)" not in {I.text() for I in d.integrals}


def test_a_corrupted_integral_fails_verification():
    flow, _ = resolve_flow("neumann-euclidean")
    wrong = Integral([(Fraction(1), Monomial((("A", "X", "Xt"),))), (Fraction(2), Monomial((("P", "Pt"),)))])
    F = wrong.function()
    claim = Claim(id="wrong-integral", paper=("t",), kind="id", section="t",
                  func=lambda s: {"dI/dt": s.d(F, flow(s))}, sizes=admissible(4))
    assert run_one(claim, Size(4, 2), "auto", 0).verdict == "fails"


def test_a_users_flow_from_a_file_through_the_command_line(tmp_path):
    from pathlib import Path
    from click.testing import CliRunner
    from stiefelsym.cli import main
    example = Path(__file__).resolve().parent.parent / "examples" / "my_flow.py"
    r = CliRunner().invoke(main, ["discover", f"{example}:flow_A2", "--max-a", "2", "--degree", "2"])
    assert r.exit_code == 0, r.output
    assert "I1 = tr(AAXXᵀ) + tr(PPᵀ)    [auto proved, free (all n, r) proved]" in r.output
    bad = CliRunner().invoke(main, ["discover", "no-such-flow"])
    assert bad.exit_code == 2 and "unknown flow" in bad.output


def test_the_lax_partner_of_la2_is_found_and_proved_for_all_sizes():
    from stiefelsym.discover import LAX, lax_partner, resolve_function
    flow, _ = resolve_flow("neumann-normal")
    space, verdicts = lax_partner(resolve_function("LA2", LAX), flow, Size(4, 2), degree=2)
    assert space.text() == "−XPᵀ + PXᵀ − λ·A"
    assert sorted(space.text(b) for b in space.basis) == ["I_n", "λ·I_n"]
    assert verdicts == {"auto": "proved", "free (all n, r)": "proved"}


def test_an_empty_space_is_certified_by_a_rank():
    from stiefelsym.discover import lax_partner
    flow, _ = resolve_flow("geodesic-normal")
    space, verdicts = lax_partner(lambda s: s.X @ s.X.T, flow, Size(4, 2), degree=0)
    assert space.particular is None and not verdicts
    assert space.certificate().startswith("no formula in this 4-term space holds") and space.rank < space.rank_augmented
