"""The exact method's straight-line programs (stiefelsym.ir.straightline): the same checks and
verdicts as the interpreter, recomputed at every run, shared only by graphs with the same digest,
and a corrupted claim still fails through them."""
import dataclasses

import pytest

from stiefelsym import admissible, block, comm
from stiefelsym.claims import Claim
from stiefelsym.ir import compile_claim
from stiefelsym.ir.derivative import derivatives, scene_flows
from stiefelsym.ir.straightline import Leaf, NotCompiled, compile_graph
from stiefelsym.methods import fixed_size as fs
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.backends.native import backend
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.scene import REALIZATIONS, Scene


def neumann_flow(s):
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    return {"X": P - k * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}


def la1(s):
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    M = s.Phi - s.lam * s.A
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


def la1_again(s):
    """LA1 written a second time: another function, the same graph."""
    M = s.Phi - s.lam * s.A
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


def la1_sign_flipped(s):
    """LA1 with the sign of XX^T in L flipped: false."""
    L = lambda t: t.lam * t.Phi - t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    M = s.Phi - s.lam * s.A
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


def _claim(func, cid="la1-straight"):
    return Claim(id=cid, paper=("LA1",), kind="lax", section="5", func=func, sizes=admissible(5),
                 title="The big Lax equation along the printed Neumann flow.")


@pytest.fixture
def fresh(fresh_programs):
    return fresh_programs


def _programs(func, n, r):
    cons = REALIZATIONS["standard"]
    d = compile_claim(func, n, r, (cons.name, cons.build)).digest()
    return {k: v for k, v in fs._STRAIGHT.items() if k[0] == d and k[3:5] == (n, r)}


def _record(res):
    """The record of a run, every field but its seconds."""
    return {k: v for k, v in dataclasses.asdict(res).items() if k != "seconds"}


def _interpreted(monkeypatch, claim, n, r):
    monkeypatch.setattr(fs, "STRAIGHT_AFTER", 10**9)
    try:
        return run_exact(claim, n, r, 0)
    finally:
        monkeypatch.setattr(fs, "STRAIGHT_AFTER", 1)


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_la1_through_the_program_is_proved_and_the_sign_flip_fails(fresh, monkeypatch, n, r):
    good, bad = _claim(la1), _claim(la1_sign_flipped, "la1-sign-flipped")
    want_good, want_bad = _interpreted(monkeypatch, good, n, r), _interpreted(monkeypatch, bad, n, r)
    assert want_good.verdict == "proved" and want_bad.verdict == "fails"
    for _ in range(5):      # counted, compiled, planned (a proof), run by its plan
        assert _record(run_exact(good, n, r, 0)) == _record(want_good)
        got = run_exact(bad, n, r, 0)
        assert got.verdict == "fails" and got.residual and _record(got) == _record(want_bad)
    (p_good,), (p_bad,) = _programs(la1, n, r).values(), _programs(la1_sign_flipped, n, r).values()
    assert type(p_good) is fs._Straight and type(p_bad) is fs._Straight and p_good is not p_bad
    # the corrupted claim's verdict comes from its program's values at this run
    calls = []
    real = p_bad.fn
    p_bad.fn = lambda xs: calls.append(1) or real(xs)
    assert run_exact(bad, n, r, 0).verdict == "fails" and calls == [1]


def test_a_program_is_shared_by_the_graph_digest_only(fresh, monkeypatch):
    run_exact(_claim(la1), 3, 1, 0)
    run_exact(_claim(la1), 3, 1, 0)
    assert len(_programs(la1, 3, 1)) == 1
    # another function with the same graph (another claim id): the same program, not compiled again
    real = fs._compile_straight
    monkeypatch.setattr(fs, "_compile_straight", lambda *a: pytest.fail("compiled again"))
    assert run_exact(_claim(la1_again, "la1-again"), 3, 1, 0).verdict == "proved"
    assert _programs(la1_again, 3, 1) == _programs(la1, 3, 1)
    # a different graph does not find it: it is counted, then compiled on its own
    monkeypatch.setattr(fs, "_compile_straight", real)
    assert _programs(la1_sign_flipped, 3, 1) == {}
    run_exact(_claim(la1_sign_flipped, "flip"), 3, 1, 0)
    assert _programs(la1_sign_flipped, 3, 1) == {}


#: the catalog's claims whose graphs the compiler handles, at small sizes
CATALOG_SAMPLE = ["invariants-so-n", "euclidean-invariance", "manakov-square", "ym-charge",
                  # traces, pairings, s.q, division by constants, fresh parameters, matrices by rows
                  "normal-legendre-inverse", "normal-momentum-of-velocity", "chain-algebra-commutative",
                  "manakov-operator", "coupled-corrected-flow-invariants",
                  # checks that are numbers
                  "quartic", "neumann-hamiltonian", "symmetric-pair"]


@pytest.mark.parametrize("n,r", [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)])
def test_catalog_sample_same_verdicts_as_the_interpreter(fresh, monkeypatch, catalog, n, r):
    compiled = 0
    for cid in CATALOG_SAMPLE:
        c = catalog.get(cid)
        if not c.sizes.admits(n, r):
            continue
        want = _interpreted(monkeypatch, c, n, r)
        for _ in range(5):      # counted, compiled, planned (a proof), run by its plan
            assert _record(run_exact(c, n, r, 0)) == _record(want), cid
        cons = REALIZATIONS[c.realization]
        d = compile_claim(c.func, n, r, (cons.name, cons.build)).digest()
        compiled += sum(type(v) is fs._Straight for k, v in fs._STRAIGHT.items() if k[0] == d)
    assert compiled
    assert not any(isinstance(v, str) and "disagrees" in v for v in fs._STRAIGHT.values())
    # proofs planned, some through programs at the level of coefficients (each planned run above equal to the
    # interpreter's record)
    assert fs._PLANS and any(p.straight.entries is not None for p in fs._PLANS.values())


def _chart_leaves(n, r):
    f = SymbolicField()
    sc = Scene(n, r, f, chart="equivariant", realization="standard", right_reduction=True)
    cons = REALIZATIONS["standard"]
    g = compile_claim(la1, n, r, (cons.name, cons.build))
    checks = fs.call_claim(la1, sc)
    be = backend(f)
    values = {}

    def leaves(pattern):
        def leaf(i, name):
            v = getattr(sc, name)
            if hasattr(v, "_nat"):
                rows, scalar = be._fix(v._nat()).a.tolist(), False
            else:
                rows, scalar = [[be.ring.from_se(v)[0]]], True
            values[i] = rows
            return Leaf([[pattern(x) for x in row] for row in rows], scalar)
        return leaf
    return derivatives(g, scene_flows(sc)), checks, leaves, values, be


def test_constants_folded_and_zeros_skipped_give_the_same_values():
    h, checks, leaves, values, be = _chart_leaves(3, 1)
    folded = compile_graph(h, leaves(fs._constant))
    every = compile_graph(h, leaves(lambda x: None))      # every entry of the chart an input
    assert folded.operations < every.operations
    want = be._fix(checks["LA1"]._nat()).a.tolist()
    for prog in (folded, every):
        got = prog.function(be.ring.zero)([values[i][a][b] for i, a, b in prog.inputs])
        assert [list(row) for row in got[0]] == want


def test_a_program_that_disagrees_with_the_interpreter_is_not_used(fresh, monkeypatch):
    from stiefelsym.ir import straightline

    def wrong(h, leaf, *size):
        p = straightline.compile_graph(h, leaf, *size)
        p.source = p.source.replace("return (((", "return (((x0 + ")    # an input added to one entry
        return p
    f = SymbolicField()
    sc = Scene(3, 1, f, chart="equivariant", realization="standard", right_reduction=True)
    checks = fs.call_claim(la1, sc)
    cons = REALIZATIONS["standard"]
    g = compile_claim(la1, 3, 1, (cons.name, cons.build))
    with pytest.raises(NotCompiled, match="disagrees"):
        fs._straight(g, f, sc, checks, (), wrong)
    assert fs._straight(g, f, sc, checks, (), straightline.compile_graph).operations > 0


def test_ops_outside_the_compiler_are_refused():
    def with_inverse(s):
        return {"inv": s.A @ (s.A + s.lam * s.identity(s.n, "n")).inv() - s.X @ s.X.T}
    cons = REALIZATIONS["standard"]
    g = compile_claim(with_inverse, 3, 1, (cons.name, cons.build))
    with pytest.raises(NotCompiled):
        compile_graph(g, lambda i, name: Leaf([[None] * 3 for _ in range(3)]))


# -- the scene's methods, entries, blocks and division by constants, compiled ---------------------

def _as_matrix(s, x):
    return s.scalar_matrix(x, s.r, "r")


def traces_and_pairings(s):
    """<Φ, Φ> = -tr(Φ²)/2, with the 1/2 written three ways (a division, s.q, a Fraction-valued s.const)."""
    P = s.Phi @ s.Phi
    return {"killing": _as_matrix(s, s.killing(s.Phi, s.Phi) + s.tr(P) / 2),
            "q": _as_matrix(s, s.q(1, 2) * s.tr(P) + s.killing(s.Phi, s.Phi)),
            "lam": _as_matrix(s, s.tr(s.lam * P) / 4 + s.killing(s.Phi, s.Phi) * s.lam / 2)}


def traces_sign_flipped(s):
    P = s.Phi @ s.Phi
    return {"killing": _as_matrix(s, s.killing(s.Phi, s.Phi) - s.tr(P) / 2)}


def traces_term_dropped(s):
    P = s.Phi @ s.Phi
    return {"q": _as_matrix(s, s.q(1, 2) * s.tr(P) + s.killing(s.Phi, s.Phi)),
            "lam": _as_matrix(s, s.tr(s.lam * P) / 4)}


def blocks_and_entries(s):
    """The block diag(XᵀX, I_r) read back by slices and entries: XᵀX = I_r."""
    r = s.r
    M = block([[s.X.T @ s.X, s.zeros(r, r, ("r", "r"))], [s.zeros(r, r, ("r", "r")), s.Ir]])
    return {"top": M[0:r, 0:r] - s.identity(r, "r"), "bottom": M[r:, r:] - M[0:r, 0:r],
            "corner": M[0:r, r:] + M[r:, 0:r],
            "entry": _as_matrix(s, M[0, 0] - 1), "row": M[0, :] - M[0:1, :], "column": M[:, r] - M[:, r:r + 1]}


def blocks_sign_flipped(s):
    r = s.r
    M = block([[s.X.T @ s.X, s.zeros(r, r, ("r", "r"))], [s.zeros(r, r, ("r", "r")), s.Ir]])
    return {"top": M[0:r, 0:r] + s.identity(r, "r")}


def blocks_entry_dropped(s):
    r = s.r
    M = block([[s.X.T @ s.X, s.zeros(r, r, ("r", "r"))], [s.zeros(r, r, ("r", "r")), s.Ir]])
    return {"entry": _as_matrix(s, M[0, 0])}


def parameters_and_rows(s):
    """A generic matrix and a scalar parameter of the claim's own, and a matrix written by its rows."""
    G, mu = s.generic("G", "n", "r"), s.scalar("mu")
    return {"scale": (mu * G).T - mu * G.T,
            "rows": s.mat([[mu, 0], [0, mu]]) - s.scalar_matrix(mu, 2),
            "list": s.mat([[mu * 2, 1]]) - s.mat([[mu + mu, s.q(2, 2)]])}


def parameters_sign_flipped(s):
    mu = s.scalar("mu")
    return {"rows": s.mat([[mu, 0], [0, -mu]]) - s.scalar_matrix(mu, 2)}


def parameters_term_dropped(s):
    G, mu = s.generic("G", "n", "r"), s.scalar("mu")
    return {"scale": (mu * G).T - mu * G.T, "rows": s.mat([[mu, 0], [0, mu]])}


NEW_OPS = [(traces_and_pairings, [traces_sign_flipped, traces_term_dropped]),
           (blocks_and_entries, [blocks_sign_flipped, blocks_entry_dropped]),
           (parameters_and_rows, [parameters_sign_flipped, parameters_term_dropped])]


@pytest.mark.parametrize("good,bads", NEW_OPS, ids=[g.__name__ for g, _ in NEW_OPS])
@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_new_ops_compile_prove_and_a_corruption_fails(fresh, monkeypatch, good, bads, n, r):
    for func, verdict in [(good, "proved")] + [(b, "fails") for b in bads]:
        c = _claim(func, func.__name__.replace("_", "-"))
        want = _interpreted(monkeypatch, c, n, r)
        assert want.verdict == verdict, (func.__name__, want.message)
        for _ in range(5):      # counted, compiled, planned (a proof), run by its plan
            assert _record(run_exact(c, n, r, 0)) == _record(want), func.__name__
        progs = _programs(func, n, r)
        assert progs and all(type(p) is fs._Straight for p in progs.values()), (func.__name__, progs)
        if verdict == "fails":
            # the verdict comes from the program's values at this run
            (p,) = progs.values()
            calls = []
            real = p.fn
            p.fn = lambda xs: calls.append(1) or real(xs)
            assert run_exact(c, n, r, 0).verdict == "fails" and calls == [1]


def test_rational_constants_are_ring_elements_not_floats():
    cons = REALIZATIONS["standard"]
    g = compile_claim(traces_and_pairings, 3, 1, (cons.name, cons.build))
    sc = Scene(3, 1, SymbolicField(), chart="equivariant", realization="standard")
    h = derivatives(g, scene_flows(sc))

    def leaf(i, name):
        v = getattr(sc, name) if type(name) is str else getattr(sc, name[0])(*name[1])
        return Leaf([[None] * v.shape[1] for _ in range(v.shape[0])]) if hasattr(v, "shape") else Leaf([[None]], True)
    prog = compile_graph(h, leaf, lambda d: getattr(sc, d))
    assert prog.constants and "/" not in prog.source and "." not in prog.source
    with pytest.raises(NotCompiled):
        prog.function(0)        # no exact fractions of the ring: refused, never a float


@pytest.mark.parametrize("func", [
    lambda s: {"d": _as_matrix(s, s.tr(s.Phi @ s.Phi) / s.lam)},                  # a division by a polynomial
    lambda s: {"r": s.A @ s.resolvent(s.lam) - s.X @ s.X.T},                       # a scene method not compiled
])
def test_divisions_by_polynomials_and_other_methods_are_refused(func):
    cons = REALIZATIONS["standard"]
    g = compile_claim(func, 3, 1, (cons.name, cons.build))
    sc = Scene(3, 1, SymbolicField(), chart="equivariant", realization="standard")
    with pytest.raises(NotCompiled):
        compile_graph(g, lambda i, name: Leaf([[None]], True) if name == "lam" else
                      Leaf([[None] * 3 for _ in range(3)]), lambda d: getattr(sc, d))


def numbers_as_checks(s):
    """Checks that are numbers: <Φ, Φ> + tr(Φ²)/2 = 0 and tr(XᵀX) - r = 0."""
    return {"pairing": s.killing(s.Phi, s.Phi) + s.tr(s.Phi @ s.Phi) / 2, "trace": s.tr(s.X.T @ s.X) - s.r}


def numbers_sign_flipped(s):
    return {"pairing": s.killing(s.Phi, s.Phi) - s.tr(s.Phi @ s.Phi) / 2}


def numbers_term_dropped(s):
    return {"trace": s.tr(s.X.T @ s.X)}


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_checks_that_are_numbers_compile_and_a_corruption_fails(fresh, monkeypatch, n, r):
    test_new_ops_compile_prove_and_a_corruption_fails(fresh, monkeypatch, numbers_as_checks,
                                                      [numbers_sign_flipped, numbers_term_dropped], n, r)


# -- programs at the level of coefficients, and the plans of proofs ---------------------------------

def _random_program(rng, k, rational=False):
    """A random straight-line program over k inputs in the compiler's forms (sums, differences and
    products of values and integer constants, x - x, coefficients riding along, signed outputs; with
    ``rational``, the ring's rational constants K0 = 1/2 and K1 = -3/4 among the constants)."""
    from fractions import Fraction
    names, lines = [f"x{j}" for j in range(k)], []

    def lit():
        c = rng.choice([-3, -2, -1, 1, 2, 5] + (["K0", "K1"] if rational else []))
        return c if type(c) is str else str(c) if c > 0 else f"({c})"
    for j in range(rng.randint(3, 14)):
        a, b = rng.choice(names), rng.choice(names)
        expr = rng.choice([f"{a} + {b}", f"{a} - {b}", f"{a} * {b}", f"{a} - {a}", f"{a} + {lit()}",
                           f"{lit()} - {a}", f"{lit()} * {a} + {b}", f"{a} + {lit()} * {b}",
                           f"{lit()} * {a} + {lit()} * {b}", f"{a} * {a}"])
        lines.append(f"    v{j} = {expr}")
        names.append(f"v{j}")
    outs = [rng.choice([f"{rng.choice(names)}", f"-{rng.choice(names)}", f"{lit()} * {rng.choice(names)}",
                        "ZERO", f"ZERO + {lit()}"]) for _ in range(4)]
    src = "\n".join(["def program(X):", "    " + ", ".join(f"x{j}" for j in range(k)) + ", = X", *lines,
                     "    return (((" + ", ".join(outs[:2]) + ",), (" + ", ".join(outs[2:]) + ",),),)"]) + "\n"
    from stiefelsym.ir.straightline import Program
    return Program(src, [(0, 0, j) for j in range(k)], {"M": (2, 2)}, len(lines),
                   (Fraction(1, 2), Fraction(-3, 4)) if rational else ())


@pytest.mark.parametrize("rational", [False, True], ids=["Z[x]", "rational constants"])
def test_coefficient_programs_compute_what_the_ring_program_computes(rational):
    import random
    import flint
    from stiefelsym.ir.straightline import coefficient_program
    rng = random.Random(20)
    ctx = (flint.fmpq_mpoly_ctx if rational else flint.fmpz_mpoly_ctx).get(("a", "b", "c", "d"), "degrevlex")
    zero = ctx.from_dict({})
    for _ in range(300):
        k = rng.randint(1, 4)
        prog = _random_program(rng, k, rational)
        xs = [ctx.from_dict({tuple(rng.randint(0, 2) for _ in range(4)): rng.choice([-4, -1, 1, 3, 7])
                             for _ in range(rng.randint(1, 3))}) for _ in range(k)]
        want = [[list(row) for row in m] for m in prog.function(zero, flint.fmpq)(xs)]
        terms = [[(m, int(c.p) if rational else int(c)) for m, c in x.to_dict().items()] for x in xs]
        cp = coefficient_program(prog, terms, 4, 10**6)
        assert "/" not in cp.source and "." not in cp.source      # integers only
        values = cp.function([c for tt in terms for _, c in tt])
        assert all(type(v) is int for v in values)
        q = (lambda c: flint.fmpq(c.numerator, c.denominator)) if rational else int
        got = [[[ctx.from_dict({**{mono: q(c) * values[i] for i, mono, c in slots if values[i]},
                                **{mono: q(c) for mono, c in consts}})
                 for consts, slots in row] for row in m] for m in cp.entries]
        assert got == want, prog.source


def test_a_coefficient_program_computes_x_minus_x_and_decides_on_the_values():
    from stiefelsym.ir.straightline import Program, coefficient_program
    prog = Program("def program(X):\n    x0, = X\n    v0 = x0 - x0\n    return (((v0,),),)\n", [(0, 0, 0)],
                   {"M": (1, 1)}, 1)
    cp = coefficient_program(prog, [[((1, 0), 3), ((0, 2), -1)]], 2, 100)
    assert "i0 - i0" in cp.source and "i1 - i1" in cp.source      # written, not cancelled
    assert len(cp.entries[0][0][0][1]) == 2                        # both coefficients are computed
    assert cp.function([3, -1]) == (0, 0) and cp.function([3, 5]) == (0, 0)
    # beyond its budget of operations a program stays with the ring
    with pytest.raises(NotCompiled):
        coefficient_program(prog, [[((1, 0), 3), ((0, 2), -1)]], 2, 1)


def test_a_coefficient_program_that_disagrees_with_the_interpreter_is_not_used(monkeypatch):
    from stiefelsym.ir import straightline
    real = straightline.coefficient_program

    def wrong(prog, terms, nvars, cap):
        cp = real(prog, terms, nvars, cap)
        return straightline.CoefficientProgram(cp.source.replace("    return (", "    return (1 + "), cp.entries,
                                               cp.operations, cp.constant_terms)      # 1 added to one coefficient
    monkeypatch.setattr(straightline, "coefficient_program", wrong)
    f = SymbolicField()
    sc = Scene(3, 1, f, chart="equivariant", realization="standard", right_reduction=True)
    checks = fs.call_claim(la1, sc)
    cons = REALIZATIONS["standard"]
    g = compile_claim(la1, 3, 1, (cons.name, cons.build))
    with pytest.raises(NotCompiled, match="coefficient program disagrees"):
        fs._straight(g, f, sc, checks, (), straightline.compile_graph)
    monkeypatch.setattr(straightline, "coefficient_program", real)
    st = fs._straight(g, f, sc, checks, (), straightline.compile_graph)
    assert st.entries is not None and st.fn(st.inputs) and not any(st.fn(st.inputs))


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_a_plan_runs_the_program_and_decides_on_its_values(fresh, monkeypatch, n, r):
    good, bad = _claim(la1), _claim(la1_sign_flipped, "la1-sign-flipped")
    want_good, want_bad = _interpreted(monkeypatch, good, n, r), _interpreted(monkeypatch, bad, n, r)
    for _ in range(4):
        assert _record(run_exact(good, n, r, 0)) == _record(want_good)
        assert _record(run_exact(bad, n, r, 0)) == _record(want_bad)
    (plan,) = fs._PLANS.values()            # a proof only: a refutation goes the whole way at every run
    (p_bad,) = _programs(la1_sign_flipped, n, r).values()
    assert p_bad.entries is not None       # the corrupted claim failed through its coefficient program
    assert plan.claim is good and plan.straight.entries is not None
    st = plan.straight
    # the plan's runs: the program at every run, and no chart evaluated otherwise
    calls, real = [], st.fn
    with monkeypatch.context() as m:
        m.setattr(st, "fn", lambda xs: calls.append(1) or real(xs))
        m.setattr(fs, "_chart_checks", lambda *a, **k: pytest.fail("a chart evaluated"))
        for _ in range(3):
            assert _record(run_exact(good, n, r, 0)) == _record(want_good)
    assert calls == [1, 1, 1]
    # a value that is not 0 at a run is never proved through the plan: the whole method runs, through
    # the same program, and the claim fails with that value as its residual
    values = real(st.inputs)
    assert len(values) > 1 and not any(values)
    with monkeypatch.context() as m:
        m.setattr(st, "fn", lambda xs: (1,) + real(xs)[1:])
        got = run_exact(good, n, r, 0)
        assert got.verdict == "fails" and got.residual
    assert _record(run_exact(good, n, r, 0)) == _record(want_good) and fs._PLANS
    # a program dropped from the memo drops its plan
    fs._STRAIGHT.clear()
    assert _record(run_exact(good, n, r, 0)) == _record(want_good)      # compiled again (counted before)
    assert st not in fs._STRAIGHT.values() and fs._PLANS[(id(good), id(good.func), n, r)].straight is None
    assert _record(run_exact(good, n, r, 0)) == _record(want_good)      # the new program, planned again
    assert fs._PLANS[(id(good), id(good.func), n, r)].straight not in (None, st)
