"""Every method proves what holds and rejects what does not (negative controls)."""
import pytest

from stiefelsym import Count, Rank, admissible, comm
from stiefelsym.claims import Claim, Size, _mark_reviewed
from stiefelsym.methods.fixed_size import run_exact, run_float, run_points
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.run.runner import run_one


def H_normal(s):
    return s.killing(s.Phi, s.Phi) / 2


def projector_evolves(s):
    """d(XX^T)/dt = [Phi, XX^T] along the normal geodesic flow."""
    flow = s.dirac_flow(H_normal)
    return {"d(XX^T)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.Phi, s.X @ s.X.T)}


def projector_evolves_swapped(s):
    """Corrupted: the commutator in the wrong order."""
    flow = s.dirac_flow(H_normal)
    return {"d(XX^T)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.X @ s.X.T, s.Phi)}


def normal_flow_sign(s):
    """Corrupted: dX/dt = P + X P^T X (a flipped sign)."""
    flow = s.dirac_flow(H_normal)
    return {"dX/dt": flow.Xdot - (s.P + s.X @ s.P.T @ s.X)}


def resolvent_identity(s):
    """A (lambda - A)^{-1} = lambda (lambda - A)^{-1} - I."""
    R = s.resolvent(s.lam)
    return {"AR": s.A @ R - (s.lam * R - s.In)}


def resolvent_identity_sign(s):
    R = s.resolvent(s.lam)
    return {"AR": s.A @ R - (s.lam * R + s.In)}


def dimension_of_V(s):
    """The rank of the differential of X -> X^T X at a point of V is r(r+1)/2."""
    J = s.jacobian(lambda t: t.X.T @ t.X)
    rows = [row[: s.n * s.r] for i, row in enumerate(J) if i in _upper(s.r)]
    return {"rank": Rank(s.mat(rows), s.r * (s.r + 1) // 2),
            "dim V": Count(s.n * s.r - s.r * (s.r + 1) // 2, s.r * s.n - s.r * (s.r + 1) // 2)}


def dimension_of_V_wrong(s):
    J = s.jacobian(lambda t: t.X.T @ t.X)
    rows = [row[: s.n * s.r] for i, row in enumerate(J) if i in _upper(s.r)]
    return {"rank": Rank(s.mat(rows), s.r * (s.r + 1) // 2 + 1)}


def _upper(r):
    idx, k = set(), 0
    for i in range(r):
        for j in range(r):
            if j >= i:
                idx.add(k)
            k += 1
    return idx


def _claim(func, kind="id", cid="test", equivariance=""):
    """A test claim; a stated equivariance reason stands for a reviewed catalog claim's."""
    c = Claim(id=cid, paper=("prep",), kind=kind, section="t", func=func, sizes=admissible(4),
              equivariance=equivariance)
    return _mark_reviewed(c) if equivariance else c


GOOD = [projector_evolves, resolvent_identity]
BAD = [projector_evolves_swapped, normal_flow_sign, resolvent_identity_sign]
SIZES = [(3, 1), (3, 2), (3, 3)]


@pytest.mark.parametrize("n,r", SIZES)
@pytest.mark.parametrize("func", GOOD, ids=lambda f: f.__name__)
def test_true_identities_pass_every_method(func, n, r):
    c = _claim(func)
    assert run_exact(c, n, r, 0).verdict == "proved"
    assert run_points(c, n, r, "rational", 0).verdict == "checked"
    res = run_points(c, n, r, "modular", 0)
    assert res.verdict == "checked" and 0 < res.false_pass_bound < 1e-20
    assert run_float(c, n, r, 0).verdict == "numeric"


# the corruptions are harmless at some sizes (for r = n, XX^T = I; for r = 1, X^T P = 0)
@pytest.mark.parametrize("n,r", [(3, 2)])
@pytest.mark.parametrize("func", BAD, ids=lambda f: f.__name__)
def test_corrupted_identities_fail_every_method(func, n, r):
    c = _claim(func)
    assert run_exact(c, n, r, 0).verdict == "fails"
    for kind in ("rational", "modular"):
        res = run_points(c, n, r, kind, 0)
        assert res.verdict == "fails"
        assert res.witness and res.witness["seed"] == 0 and res.witness["point"]
    res = run_float(c, n, r, 0)
    assert res.verdict == "fails" and (res.witness["field"] == "rational" or res.witness["field"].startswith("arb"))


@pytest.mark.parametrize("n,r", [(4, 2), (5, 3), (5, 4)])
@pytest.mark.parametrize("func", BAD, ids=lambda f: f.__name__)
def test_corrupted_identities_fail_at_larger_sizes(func, n, r):
    assert run_points(_claim(func), n, r, "modular", 1).verdict == "fails"


@pytest.mark.parametrize("func", BAD, ids=lambda f: f.__name__)
def test_corrupted_identities_are_never_proved_dimension_free(func):
    assert run_free(_claim(func)).verdict == "undecided"


@pytest.mark.parametrize("func", GOOD, ids=lambda f: f.__name__)
def test_true_identities_are_proved_dimension_free(func):
    res = run_free(_claim(func))
    assert res.verdict == "proved" and res.n is None


def generic_resolvent_identity(s):
    """B (lambda - B)^{-1} = lambda (lambda - B)^{-1} - I for a generic symmetric B of the claim's own."""
    G = s.general_params("G", s.n, s.n, ("n", "n"))
    B = G + G.T
    R = (s.scalar_matrix(s.lam, s.n, "n") - B).inv()
    return {"BR": B @ R - (s.lam * R - s.In)}


def generic_resolvent_swapped(s):
    """FALSE: (λ − B)⁻¹ = (λ + B)⁻¹ for a generic symmetric B (a careless sign inside the inverted pencil)."""
    G = s.general_params("G", s.n, s.n, ("n", "n"))
    B = G + G.T
    lam = s.scalar_matrix(s.lam, s.n, "n")
    return {"R": (lam - B).inv() - (lam + B).inv()}


def test_symbolic_budget_is_reported_not_guessed():
    # a dense symmetric 7x7 pencil has no core of 3 rows and is larger than 6x6: beyond the budget of a symbolic solve
    res = run_exact(_claim(generic_resolvent_identity), 7, 2, 0)
    assert res.verdict == "inconclusive" and "budget" in res.message
    auto = run_one(_claim(generic_resolvent_identity), Size(7, 2), "auto", 0)
    assert auto.method == "modular" and auto.verdict == "checked" and "budget" in auto.message
    # a 5x5 pencil λI − B (entries of degree <= 1) is within it
    assert run_exact(_claim(generic_resolvent_identity), 5, 2, 0).verdict == "proved"
    # negative controls within the widened budget: a false sign outside, and inside, the inverted 5x5 pencil
    def flipped(s):
        return {k: v + 2 * s.In for k, v in generic_resolvent_identity(s).items()}
    assert run_exact(_claim(flipped), 5, 2, 0).verdict == "fails"
    assert run_exact(_claim(generic_resolvent_swapped), 5, 2, 0).verdict == "fails"
    # the chart's A has its diagonal blocks A11, A22 diagonal: its resolvent is within the budget
    assert run_exact(_claim(resolvent_identity), 5, 2, 0).verdict == "proved"
    assert run_exact(_claim(resolvent_identity_sign), 5, 2, 0).verdict == "fails"


def test_witness_is_reproducible():
    c = _claim(normal_flow_sign)
    a, b = run_points(c, 4, 2, "rational", 5), run_points(c, 4, 2, "rational", 5)
    assert a.witness == b.witness
    assert run_points(c, 4, 2, "rational", 6).witness != a.witness


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_ranks_are_decided_two_sided(n, r):
    why = "the rank of the differential of the O(n)-invariant map X -> X^T X is O(n)-invariant"
    good, bad = _claim(dimension_of_V, "dim", equivariance=why), _claim(dimension_of_V_wrong, "dim", equivariance=why)
    assert run_exact(good, n, r, 0).verdict == "proved"
    # the constraints' differential has full rank: a nonzero maximal minor at a point proves it
    assert run_points(good, n, r, "modular", 0).verdict == "proved"
    assert run_exact(bad, n, r, 0).verdict == "fails"
    assert run_points(bad, n, r, "modular", 0).verdict not in ("proved", "checked")


def test_rerun_command_after_failure():
    res = run_one(_claim(normal_flow_sign), Size(4, 2), "modular", 3)
    assert res.verdict == "fails" and not res.expected
    assert res.rerun == "stiefelsym verify test --size 4,2 --method modular --seed 3"


def cancellation(s):
    """1/((a_1 + q) - a_1) = 1/q for q = 10^-12: float64 loses 4 digits to rounding of a_1 + q."""
    q = s.q(1, 10**12)
    a1 = s.a[0]
    return {"cancellation": 1 / ((a1 + q) - a1) - 1 / q}


def cancellation_wrong(s):
    q = s.q(1, 10**12)
    a1 = s.a[0]
    return {"cancellation": 1 / ((a1 + q) - a1) - 1 / (q * (1 + s.q(1, 10**6)))}


def test_float_escalates_to_balls_when_float64_cannot_resolve():
    res = run_float(_claim(cancellation), 3, 1, 0)
    assert res.verdict == "numeric"
    assert "float64" in res.message and "ball arithmetic" in res.certificate


def test_float_never_widens_its_tolerance_to_pass():
    res = run_float(_claim(cancellation_wrong), 3, 1, 0)
    assert res.verdict == "fails" and (res.witness["field"] == "rational" or res.witness["field"].startswith("arb"))


@pytest.mark.parametrize("hard", ["near-pole", "near-equal-a", "large-momenta"])
def test_hard_cases_reject_a_corrupted_claim(hard):
    for m in ("float", "rational", "modular"):
        assert run_one(_claim(resolvent_identity_sign), Size(3, 2), m, 0, hard=hard).verdict == "fails"
        good = run_one(_claim(resolvent_identity), Size(3, 2), m, 0, hard=hard)
        if hard == "large-momenta":
            # no momenta in the claim: the case changes nothing, and the claim is verified at random points
            assert good.verdict in ("checked", "numeric") and "verified at random points" in good.message
        else:
            assert good.verdict == "undecided" and good.false_pass_bound is None and "chosen, not random" in good.message
        assert "--hard " + hard in good.rerun


def entrywise_constant_matrix(s):
    """tr(X^T E_11 X) = 1 holds at X0 only: entrywise matrices of R^n break the equivariance reduction."""
    E = s.mat([[s.const(1 if (i, j) == (0, 0) else 0) for j in range(s.n)] for i in range(s.n)], tags=("n", "n"))
    return {"value": s.tr(s.X.T @ E @ s.X) - 1}


def test_entrywise_matrices_disable_the_equivariance_reduction():
    res = run_exact(_claim(entrywise_constant_matrix), 3, 1, 0)
    assert res.verdict == "fails" and "rational parametrization" in res.reductions[0]
    # the symbolic Cayley chart with one r x r inverse reaches n = 7; beyond, no symbolic chart
    res = run_exact(_claim(entrywise_constant_matrix), 7, 1, 0)
    assert res.verdict == "fails" and "S = [[S11, -K^T], [K, 0]]" in res.reductions[0]
    # beyond, no symbolic chart: a claim not of the reviewed catalog is refuted at the exact rational point tried
    # first (before stop 73: inconclusive)
    res = run_exact(_claim(entrywise_constant_matrix), 8, 1, 0)
    assert res.verdict == "fails" and res.witness["field"] == "rational" and "limited to n <=" in res.certificate
    assert run_points(_claim(entrywise_constant_matrix), 4, 1, "modular", 0).verdict == "fails"


def test_exact_failure_comes_with_an_exact_witness_point():
    res = run_exact(_claim(normal_flow_sign), 3, 2, 4)
    assert res.verdict == "fails" and res.witness["field"] == "rational" and res.seed == 4
    assert res.witness["point"] and res.witness["value"] != "0"


def buggy(s):
    return {"oops": s.X @ s.X}          # shapes do not match


def float_residual(s):
    return {"oops": 0.5}


@pytest.mark.parametrize("func", [buggy, float_residual])
@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "auto"])
def test_a_broken_claim_is_an_error_verdict_not_a_crash(func, method):
    res = run_one(_claim(func), Size(3, 2), method, 0)
    assert res.verdict == "error" and not res.expected
    assert "Error" in res.message or "TraceRefused" in res.message
    if func is buggy:
        assert "test_methods.py" in res.message       # where in the claim it broke


def two_points(s):
    """Y^T Y = I for a second point; and a false 'Y = X'."""
    return {"Y^T Y": s.Y.T @ s.Y - s.Ir}


def two_points_false(s):
    return {"Y = X": s.Y - s.X}


def test_a_second_point_is_never_reduced_to_X0():
    assert run_exact(_claim(two_points), 3, 2, 0).verdict == "proved"
    res = run_exact(_claim(two_points_false), 3, 2, 0)
    # the first point reduced to X0, the second generic on V (never X0)
    assert res.verdict == "fails" and "second point (Y, Q)" in res.reductions[0]
    assert run_points(_claim(two_points_false), 4, 2, "modular", 0).verdict == "fails"


def stuck_in_native_code(s):
    """Blocks the alarm signal and sleeps: only a hard kill can stop it."""
    import signal
    import time
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    time.sleep(60)
    return {"never": s.X}


def test_exact_method_never_hangs():
    import time
    from stiefelsym.methods.fixed_size import run_exact_isolated
    t0 = time.perf_counter()
    res = run_exact_isolated(_claim(stuck_in_native_code), 4, 2, 0, time_budget=1)
    assert res.verdict == "inconclusive" and "budget" in res.message
    assert time.perf_counter() - t0 < 10


def test_errors_in_the_isolated_child_come_back_as_error_verdicts():
    res = run_one(_claim(buggy), Size(4, 2), "exact", 0)
    assert res.verdict == "error" and "test_methods.py" in res.message


def only_on_the_identity_component(s):
    """det X = 1 only on one component of O(3): a claim true there and false on the other."""
    X = s.X
    det = (X[0, 0] * (X[1, 1] * X[2, 2] - X[1, 2] * X[2, 1]) - X[0, 1] * (X[1, 0] * X[2, 2] - X[1, 2] * X[2, 0])
           + X[0, 2] * (X[1, 0] * X[2, 1] - X[1, 1] * X[2, 0]))
    return {"det X - 1": det - 1}


def test_both_components_are_sampled_when_r_equals_n():
    for kind in ("rational", "modular"):
        res = run_points(_claim(only_on_the_identity_component), 3, 3, kind, 0)
        assert res.verdict == "fails" and res.witness["component"] == 1


def always_at_a_pole(s):
    u = s.scalar("u")
    return {"pole": 1 / (u - u) * s.X}


def test_a_point_at_a_pole_is_redrawn_and_reported_never_a_crash():
    for kind in ("rational", "modular"):
        res = run_points(_claim(always_at_a_pole), 3, 1, kind, 0)
        assert res.verdict == "inconclusive" and "degenerate" in res.message


def _neumann_flow(s):
    """The printed Neumann flow (No), as the catalog writes it."""
    from stiefelsym.proofs.sec5_neumann import flow_No
    return flow_No(s, s.kappa)


def _lax_L(t):
    return t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A


def big_lax(s):
    """dL/dt = [M, L] along the printed Neumann flow (LA1)."""
    return {"LA1": s.d(_lax_L, _neumann_flow(s)) - comm(s.Phi - s.lam * s.A, _lax_L(s))}


def big_lax_swapped(s):
    """Corrupted: the commutator in the wrong order."""
    return {"LA1": s.d(_lax_L, _neumann_flow(s)) - comm(_lax_L(s), s.Phi - s.lam * s.A)}


def test_float_lax_check_at_a_size_with_parameter_blocks():
    """At (16, 8) the float64 backend's shortcuts all act (parameter blocks, products met again
    or transposed, the diagonal A, the selection [D; 0], float32 term scales, one BLAS thread):
    the true Lax equation is numeric, the corrupted one fails with an exact rational witness."""
    good = run_float(_claim(big_lax), 16, 8, 0)
    assert good.verdict == "numeric", good.message
    bad = run_float(_claim(big_lax_swapped), 16, 8, 0)
    assert bad.verdict == "fails" and bad.witness["field"] == "rational"


def test_an_exact_residual_reads_the_same_in_every_run(catalog):
    """The residual of a failing exact run is printed in flint's canonical term order: symengine
    orders the terms of a sum by hashes of the chart's symbols, which depend on how many symbols the
    process made before (the reports once printed a residual with its terms in another order after
    a regeneration, where another worker had run it)."""
    import symengine as se
    claim = catalog.get("manakov-dual-lax")
    texts = set()
    for k in range(12):
        [se.Dummy("spacer") for _ in range(37 * k)]     # symbols made in between, as by other runs
        res = run_exact(claim, 2, 1, 0)
        assert res.verdict == "fails"
        texts.add(res.residual)
    assert len(texts) == 1, texts
