"""Round 6b: the exact method's straight-line programs (stiefelsym/ir/straightline.py) and the derivative
transforms of coordinate reads, the symmetric operator, Jacobians and the free bracket (stiefelsym/ir/derivative.py),
each against a truth written out by hand (tests/adversary/README.md, the "Round 6b" table).  As before: every run
is the CLI in a fresh process (but the tests that run one graph several times in one process, so that it is
compiled, and that compare the two routes of a Jacobian), and each test asserts the CORRECT outcome."""
import re

from adversary_cli import HERE, PASSING, cli
from test_adversary_s34b import by_claim, fixed, run_all

FILE = "s36b_reads_and_programs.py"

TRUE = ("adv-s36b-gradient-off-diagonal", "adv-s36b-gradient-slices", "adv-s36b-gradient-operator",
        "adv-s36b-jacobian-directions", "adv-s36b-jacobian-upper-triangle", "adv-s36b-derivative-operator",
        "adv-s36b-derivative-cells", "adv-s36b-bracket-captured-half", "adv-s36b-program-cancellations",
        "adv-s36b-program-twice-a", "adv-s36b-program-twice-b")
FALSE = ("adv-s36b-gradient-off-diagonal-transposed", "adv-s36b-gradient-slices-unreversed",
         "adv-s36b-gradient-operator-transposed", "adv-s36b-jacobian-directions-permuted",
         "adv-s36b-jacobian-upper-triangle-order", "adv-s36b-derivative-operator-other",
         "adv-s36b-derivative-cells-transposed", "adv-s36b-bracket-captured-whole", "adv-s36b-program-big-off-by-one",
         "adv-s36b-program-big-square-off-by-one", "adv-s36b-program-sign-pattern", "adv-s36b-program-order",
         "adv-s36b-program-coefficients", "adv-s36b-program-twice-false")
#: the true claims the free method proves for every n, r (the others read entries or Jacobians: undecided)
FREE_PROVED = ("adv-s36b-gradient-operator", "adv-s36b-derivative-operator", "adv-s36b-bracket-captured-half",
               "adv-s36b-program-cancellations", "adv-s36b-program-twice-a", "adv-s36b-program-twice-b")


def test_reads_operators_jacobians_and_programs_against_their_truths():
    """Gradients of entries off the diagonal and of blocks read by slices with steps and reversals, the
    gradient through the symmetric operator (x̄ = 𝔸(ȳ)), Jacobians (the order of the 2nr directions, the upper
    triangle's rows), derivatives of the operator and of matrices of given entries, a bracket of a function
    that captures the claim's Φ, and graphs of the compiled algebra (x − x, 0·x, 2²⁰⁰ + 1, entries equal up to
    sign, integer coefficients, the order of a matrix product): every true claim passes and every false one
    fails under exact, modular, rational, float, ball and auto at (3,2); free proves the true ones that need
    no coordinates and passes no false one.  No hole: this pins the verdicts."""
    got = by_claim(run_all(FILE, size="3,2"))
    assert set(got) == set(TRUE) | set(FALSE), sorted(set(got) ^ (set(TRUE) | set(FALSE)))
    for c in TRUE:
        assert fixed(got[c]) <= set(PASSING) and len(got[c]) == 6, (c, got[c])   # auto names the method it chose
        assert got[c]["free"] == ("proved" if c in FREE_PROVED else "undecided"), (c, got[c])
    for c in FALSE:
        assert fixed(got[c]) == {"fails"}, (c, got[c])
        assert got[c]["free"] not in PASSING, (c, got[c])


def test_a_correction_with_the_graph_of_a_true_claim_of_the_same_run():
    """The correction of adv-s36b-program-twice-false has the very graph of adv-s36b-program-twice-a and -b (one
    digest: one straight-line program for the three in a worker): proved / checked / numeric, while the printed
    formula fails."""
    out = cli("verify", "adv-s36b-program-twice-a", "adv-s36b-program-twice-b", "adv-s36b-program-twice-false",
              "--claims", str(HERE / FILE), "--size", "3,2", "--jobs", "1", "--method", "exact", "--method", "modular",
              "--method", "float").stdout
    corrected = re.findall(r"^adv-s36b-program-twice-false \[the commutator's sign restored\] \(3,2\) (\w+): (\w+)",
                           out, re.M)
    assert sorted(corrected) == [("exact", "proved"), ("float", "numeric"), ("modular", "checked")], out
    printed = re.findall(r"^adv-s36b-program-twice-false \(3,2\) (\w+): (\w+)", out, re.M)
    assert sorted(printed) == [("exact", "fails"), ("float", "fails"), ("modular", "fails")], out


def test_one_graph_evaluated_again_in_one_process_keeps_its_verdict():
    """In one process the exact method compiles a graph on its second evaluation (per digest and chart) and
    runs the program afterwards: the verdicts of a true and a false claim of the compiled algebra (large integer
    coefficients, entries of Φ equal up to sign, a derivative along a flow) are the same on the first
    (interpreted), second (compiled) and third (program) evaluation, at (3,2), (2,2) and (3,1), and the program
    is used."""
    from stiefelsym.claims import Claim, Size, admissible
    from stiefelsym.methods import fixed_size as fs
    from stiefelsym.run.runner import run_one
    big = 2 ** 200 + 1

    def true(s):
        X, P, A, M = s.X, s.P, s.A, s.X.T @ s.P
        flow = {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}
        return {"big": (big * M - (big - 1) * M) - M, "skew": s.Phi + s.Phi.T,
                "flow": s.d(lambda t: t.Phi, flow) - (X @ X.T @ A - A @ X @ X.T)}

    def false(s):
        M = s.X.T @ s.P
        return {"big": (big * M - (big - 2) * M) - M, "skew": s.Phi - s.Phi.T}
    compiled = []
    for func, want in ((true, "proved"), (false, "fails")):
        c = Claim(id=f"adv-s36b-inprocess-{want}", paper=(), kind="id", section="test", func=func, sizes=admissible(3))
        for size in (Size(3, 2), Size(2, 2), Size(3, 1)):
            assert [run_one(c, size, "exact", 0).verdict for _ in range(3)] == [want] * 3, (want, size)
        compiled += [v for k, v in fs._STRAIGHT.items() if type(v) is fs._Straight]
    assert len(compiled) >= 6


def test_a_symmetric_jacobian_of_a_function_that_is_not_symmetric_is_refused():
    """s.jacobian(F, True) reads each matrix of F by its upper triangle (meant for symmetric F, the constraints').
    For F = XᵀP (r x r, not symmetric) the claim "the 4 entries of XᵀP have 3 independent differentials" was
    proved (exact) and checked (modular, rational, auto) at (3,2): they have 4 (the control, read entry by entry,
    is proved with 4).  Closed: the scene refuses a Jacobian read by upper triangles of a matrix whose derivative
    along a unit direction is not symmetric (Scene._symmetric_derivative, in the graph's and the scene's own
    routes): error.  A non-square F was refused when traced already."""
    got = by_claim(run_all("s36b_jacobian_symmetric.py", size="3,2", methods=("exact", "modular", "rational", "auto"),
                           free=False))
    assert fixed(got["adv-s36b-jacobian-symmetric-control"]) <= set(PASSING)
    assert fixed(got["adv-s36b-jacobian-symmetric-wide"]) == {"error"}
    assert fixed(got["adv-s36b-jacobian-symmetric-not-symmetric"]) == {"error"}, got


def test_the_symmetry_check_in_both_routes():
    """The same check where the graph computes the Jacobian (its columns) and where the scene does (a body the
    pass leaves to the scene: a nested gradient); a symmetric F (XᵀAX, PᵀP, a number; Xᵀ∇(tr XᵀAX) + XᵀX) passes
    in both."""
    import sys
    sys.path.insert(0, str(HERE.parent))
    from test_ir_derivative import STANDARD, _both, compile_claim, coverage
    nested = lambda t: t.gradient(lambda u: u.tr(u.X.T @ u.A @ u.X))[0]      # noqa: E731
    cases = {
        (None, "error"): lambda s: {"j": s.jacobian(lambda t: t.X.T @ t.P, True)},
        ("s.gradient inside the function (a nested gradient)", "error"):
            lambda s: {"j": s.jacobian(lambda t: t.X.T @ nested(t) + t.X.T @ t.P, True)},
        ("s.gradient inside the function (a nested gradient)", "ok"):
            lambda s: {"j": s.jacobian(lambda t: t.X.T @ nested(t) + t.X.T @ t.X, True)},
        (None, "ok"): lambda s: {"j": s.jacobian(lambda t: [t.X.T @ t.A @ t.X, t.P.T @ t.P, t.tr(t.Psi @ t.Psi)], True)},
    }
    for (route, want), func in cases.items():
        g = compile_claim(func, 3, 2, STANDARD)
        assert [why for _, why in coverage(g, "jacobian")] == [route]
        got = _both(g, 3, 2)
        assert [o[0] for o in got] == [want, want], (route, got)
        if want == "error":
            assert [o[1] for o in got] == ["ValueError", "ValueError"], got
