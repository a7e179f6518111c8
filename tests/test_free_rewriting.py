"""Rewriting: decreasing rules, confluence of the rule sets in use, unique and sound normal forms."""
from __future__ import annotations

import random
from fractions import Fraction

import numpy as np
import pytest
import symengine as se

from stiefelsym.backends.fields import RationalField
from stiefelsym.free.algebra import DIMENSIONS, NCPoly, evaluate, symmetric_letter, trace
from stiefelsym.free.rewriting import (Order, RewritingError, RewritingSystem, SharedMemos, complete, critical_pairs,
                                       is_confluent)
from stiefelsym.free.scene import A, FreeScene, P, Pt, X, Xt, resolvent_letter, standard_system
from stiefelsym.scene import Scene
from free_words import random_word

lam, mu = se.Symbol("lambda"), se.Symbol("mu")


def w(*letters):
    return NCPoly.word(letters)


def rule_set(name: str) -> RewritingSystem:
    """The rule sets the free scene builds: constraints, resolvents at symbolic points, A^{-1},
    the resolvent at 0 with A^{-1} (added in either order), a second point."""
    s = FreeScene()
    if name in ("resolvent", "two resolvents", "everything"):
        s.resolvent(s.lam)
    if name in ("two resolvents", "everything"):
        s.resolvent(mu)
        s.resolvent(s.lam + 1)
    if name == "ainv":
        s.Ainv
        s.resolvent(s.lam)
        s.resolvent(mu)
    if name == "ainv, then the resolvent at 0":
        s.Ainv
        s.resolvent(s.lam)
        s.resolvent(0)
    if name == "the resolvent at 0, then ainv":
        s.resolvent(0)
        s.resolvent(s.lam)
        s.Ainv
        s.resolvent(mu)
    if name == "second point":
        s.Y
        s.resolvent(s.lam)
    if name == "complex point":
        s.Zc
        s.Zc_dot
    if name == "complex point, second point, resolvent":
        s.Zc
        s.Y
        s.resolvent(s.lam)
    if name == "everything":
        s.Ainv
        s.resolvent(0)
        s.Y
    return s.system


RULE_SETS = ["constraints", "resolvent", "two resolvents", "ainv", "ainv, then the resolvent at 0",
             "the resolvent at 0, then ainv", "second point", "complex point",
             "complex point, second point, resolvent", "everything"]

#: how many critical pairs each rule set has (all resolve); before the rule R_0 -> -A^{-1}, 4, 6
#: and 8 pairs of the sets with A^{-1} and the resolvent at 0 did not (e.g. Ainv*A*R[0]: Ainv + R[0])
PAIR_COUNTS = {"constraints": 0, "resolvent": 4, "two resolvents": 48, "ainv": 48,
               "ainv, then the resolvent at 0": 40, "the resolvent at 0, then ainv": 90,
               "second point": 4, "complex point": 0, "complex point, second point, resolvent": 4,
               "everything": 168}


@pytest.mark.parametrize("name", RULE_SETS)
def test_every_rule_decreases_and_has_a_reason(name):
    system = rule_set(name)
    assert system.rules
    for rule in system.rules:
        assert system.decreasing(rule), rule
        assert rule.reason
        assert rule.rhs.shape == (rule.lhs[0].row, rule.lhs[-1].col)


@pytest.mark.parametrize("name", RULE_SETS)
def test_critical_pairs_of_the_rule_sets_in_use_all_resolve(name):
    """Confluence proof (diamond lemma): every overlap, inclusion and cyclic critical pair resolves."""
    system = rule_set(name)
    pairs = critical_pairs(system)
    unresolved = [str(p) for p in pairs if not p.joinable]
    assert not unresolved, unresolved
    assert len(pairs) == PAIR_COUNTS[name]
    if name not in ("constraints", "complex point"):
        kinds = {p.kind for p in pairs}
        assert {"overlap", "cyclic"} <= kinds
    if "at 0" in name or name == "everything":
        assert "inclusion" in kinds   # R_0 -> -A^{-1} inside A R_0, R_0 A, R_0 R_mu, R_mu R_0


@pytest.mark.parametrize("ainv_first", [True, False])
def test_the_resolvent_at_0_is_minus_the_inverse_in_either_order(ainv_first):
    """R_0 = (0 I - A)^{-1} -> -A^{-1}, with R_0 + A^{-1} = -A^{-1}·res_left:R_0 - AinvA·R_0."""
    s = FreeScene()
    if ainv_first:
        Ai = s.Ainv._a[0, 0]
        R0 = s.resolvent(0)._a[0, 0]
    else:
        R0 = s.resolvent(0)._a[0, 0]
        Ai = s.Ainv._a[0, 0]
    R0_letter = resolvent_letter(0)
    rule = s.system.rule(f"{R0_letter}=-Ainv")
    assert rule.lhs == (R0_letter,) and rule.rhs == -Ai
    assert sorted(cf.hyp.name for cf in rule.cofactors) == ["AinvA", f"res_left:{R0_letter}"]
    assert s.system.normal_form(Ai + R0) == NCPoly.zero("n", "n")
    assert s.system.normal_form(Ai * R0 - R0 * Ai) == NCPoly.zero("n", "n")
    assert is_confluent(s.system)


def test_the_constraint_rules_have_no_critical_pairs():
    assert critical_pairs(standard_system()) == []
    assert is_confluent(standard_system())


def test_rules_that_do_not_decrease_or_are_ill_typed_are_rejected():
    system = standard_system()
    with pytest.raises(RewritingError, match="does not decrease"):
        system.add_rule((Xt, P), -w(Pt, X), "wrong orientation")
    with pytest.raises(RewritingError):
        system.add_rule((X, Pt), NCPoly.identity("r"), "wrong type")
    with pytest.raises(TypeError):
        system.add_rule((X, X), w(X), "ill-typed")
    with pytest.raises(RewritingError, match="exists"):
        system.add_rule((Xt, X), NCPoly.identity("r"), "duplicate")


# ---------------------------------------------------------------------------
def _letters() -> list:
    return [X, Xt, P, Pt, A, resolvent_letter(lam)]


def random_poly(rng, letters, row, col, terms=5, length=7):
    p = NCPoly.zero(row, col)
    for _ in range(terms):
        c = rng.choice([1, -1, 2]) * rng.choice([se.Integer(1), lam, se.Symbol("kappa")])
        p = p + NCPoly.word(random_word(rng, letters, row, col, rng.randint(0, length)), row, c)
    return p


def reduce_randomly(system: RewritingSystem, p: NCPoly, rng: random.Random) -> NCPoly:
    """Reduce at randomly chosen occurrences (another strategy than the leftmost one)."""
    terms = dict(p.expand().terms)
    while True:
        reducible = []
        for key, c in terms.items():
            word = key[1]
            for i in range(len(word)):
                for rule in system.rules:
                    if word[i:i + len(rule.lhs)] == rule.lhs:
                        reducible.append((key, i, rule))
        if not reducible:
            return NCPoly(terms, p.row, p.col).expand()
        key, i, rule = rng.choice(reducible)
        c = terms.pop(key)
        word = key[1]
        for (_, rw), rc in rule.rhs.terms.items():
            k = ((), word[:i] + rw + word[i + len(rule.lhs):])
            terms[k] = se.expand(terms.get(k, 0) + c * rc)
        terms = {k: v for k, v in terms.items() if v != 0}


@pytest.mark.parametrize("seed", range(6))
def test_normal_forms_do_not_depend_on_the_reduction_strategy(seed):
    rng = random.Random(seed)
    system = rule_set("resolvent")
    letters = _letters()
    for row, col in [("n", "r"), ("r", "r"), ("n", "n"), ("r", "n")]:
        p = random_poly(rng, letters, row, col)
        nf = system.normal_form(p)
        assert reduce_randomly(system, p, rng) == nf
        assert system.normal_form(nf) == nf


@pytest.mark.parametrize("seed", range(6))
def test_trace_normal_forms_are_cyclic_and_adjoint_invariant(seed):
    rng = random.Random(100 + seed)
    system = rule_set("resolvent")
    letters = _letters()
    for _ in range(5):
        p, q = random_poly(rng, letters, "n", "r", 3, 5), random_poly(rng, letters, "r", "n", 3, 5)
        t1 = system.normal_form(trace(system.normal_form(p * q)))
        t2 = system.normal_form(trace(system.normal_form(q * p)))
        t3 = system.normal_form(trace(system.normal_form((p * q).star())))
        assert t1 == t2 == t3
    assert not system.trace_fallbacks
    assert system.trace_normal_form((Xt, P)) == 0  # XᵀP is skew on T*V
    assert system.trace_normal_form((X, Xt)) == NCPoly.scalar(DIMENSIONS["r"])


def fraction_inverse(M: np.ndarray) -> np.ndarray:
    """Gauss-Jordan inverse over the rationals."""
    m = M.shape[0]
    rows = [[Fraction(x) for x in M[i]] + [Fraction(int(i == j)) for j in range(m)] for i in range(m)]
    for col in range(m):
        piv = next(i for i in range(col, m) if rows[i][col] != 0)
        rows[col], rows[piv] = rows[piv], rows[col]
        rows[col] = [x / rows[col][col] for x in rows[col]]
        for i in range(m):
            if i != col and rows[i][col] != 0:
                f = rows[i][col]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[col])]
    return np.array([row[m:] for row in rows], dtype=object)


def exact_point(n: int, r: int, seed: int):
    """A rational point of T*V_{n,r} (the Cayley chart of the coordinate scene), a symmetric A and R_λ."""
    sc = Scene(n, r, RationalField(), chart="cayley", rng=random.Random(seed))
    frac = lambda M: np.array([[Fraction(int(x.p), int(x.q)) for x in row] for row in M._a], dtype=object)
    rng = random.Random(seed)
    B = np.array([[Fraction(rng.randint(-4, 4)) for _ in range(n)] for _ in range(n)], dtype=object)
    Am = B + B.T
    lam_value = Fraction(7, 3)
    Rm = fraction_inverse(lam_value * np.identity(n, dtype=object) - Am)
    values = {"X": frac(sc.X), "P": frac(sc.P), "A": Am, str(resolvent_letter(lam)): Rm}
    return values, {lam: lam_value, se.Symbol("kappa"): Fraction(-5, 11)}


@pytest.mark.parametrize("seed", range(3))
def test_normal_forms_are_sound_at_an_exact_point(seed):
    """Every rule holds on T*V: p and nf(p) agree at a rational point (n=5, r=2)."""
    values, scalars = exact_point(5, 2, seed)
    Rm = values[str(resolvent_letter(lam))]
    assert ((scalars[lam] * np.identity(5, dtype=object) - values["A"]).dot(Rm) == np.identity(5)).all()
    rng = random.Random(seed)
    system = rule_set("resolvent")
    letters = _letters()
    for row, col in [("n", "r"), ("r", "r"), ("n", "n")]:
        p = random_poly(rng, letters, row, col)
        assert (evaluate(p, values, scalars) == evaluate(system.normal_form(p), values, scalars)).all()
        t = trace(p * p.star())
        assert evaluate(t, values, scalars) == evaluate(system.normal_form(t), values, scalars)


def test_reductions_record_their_rules_and_print_a_derivation():
    s = FreeScene()
    R = s.resolvent(s.lam)._a[0, 0]
    p = w(Pt, X) + w(Xt, A) * R * w(X)
    red = s.system.reduce(p)
    assert {r.name for r in red.rules} == {"PtX", "XtX", f"A{resolvent_letter(lam)}"}
    assert red.normal_form == -w(Xt, P) - NCPoly.identity("r") + (w(Xt) * R * w(X)) * lam
    tex = red.latex()
    assert r"\operatorname{nf}(R)" in tex and "cond" in tex and r"\to" in tex
    assert s.system.reduce(w(X)).rules == []


# ---------------------------------------------------------------------------
def test_completion_adds_the_missing_rules_and_finishes():
    a, b = symmetric_letter("a", "r"), symmetric_letter("b", "r")
    system = RewritingSystem(Order([a, b]))
    system.add_rule((a, b), w(b), "toy", "r1")
    system.add_rule((b, a), w(a), "toy", "r2")
    assert not is_confluent(system, cyclic=False)
    result = complete(system)
    assert result.finished
    assert {r.lhs for r in result.added} == {(a, a), (b, b)}
    assert all(r.reason.startswith("completion of r") for r in result.added)
    assert is_confluent(result.system, cyclic=False)
    assert len(system.rules) == 2  # the input is not modified


def test_completion_reports_when_it_does_not_finish():
    a, b = symmetric_letter("a", "r"), symmetric_letter("b", "r")
    system = RewritingSystem(Order([a, b]))
    system.add_rule((b, a, b), w(a, b, a), "braid relation", "braid")
    result = complete(system, max_rules=8)
    assert not result.finished
    assert "more than 8 rules" in result.message


@pytest.mark.parametrize("name", RULE_SETS)
def test_completion_of_the_rule_sets_in_use_adds_nothing(name):
    result = complete(rule_set(name))
    assert result.finished and not result.added


def test_coefficients_simplify_to_a_canonical_zero_memoized():
    from stiefelsym.free.rewriting import ZERO_TYPE, nonzero_terms, simplify_coef
    k, m = se.Symbol("kappa"), se.Symbol("mu")
    hidden = (k + 1) ** 2 - k ** 2 - 2 * k - 1          # zero only once expanded
    rational = hidden / (k - m) + (k - m) / (k - m) - 1  # a rational function with zero numerator
    for c in (hidden, rational, se.Integer(0), k - k):
        for _ in range(2):                                # computed, then memoized
            assert type(simplify_coef(c)) is ZERO_TYPE
    nonzero = (k + 1) ** 2 - k ** 2
    for _ in range(2):
        assert simplify_coef(nonzero) == 2 * k + 1
    assert simplify_coef(se.Rational(1, 2)) == se.Rational(1, 2)
    assert nonzero_terms({"a": hidden, "b": nonzero, "c": se.Integer(3)}) == {"b": 2 * k + 1, "c": 3}


# --------------------------------------------------------------------------- shared memos
def test_standard_systems_share_memos_but_not_what_they_used():
    """Normal forms are functions of the rules: standard systems share their memos; the rules a
    system's own reductions used (rules_applied) and its trace fallbacks stay its own."""
    a, b = standard_system(), standard_system()
    assert a._word_memo is b._word_memo
    w = NCPoly.word((Xt, X, Pt, X))
    assert a.reduce(w).rules and {r.name for r in a.rules_applied()} == {"XtX", "PtX"}
    assert b.rules_applied() == []                       # b reduced nothing yet
    assert b.reduce(NCPoly.word((X, Pt))).rules == [] and b.rules_applied() == []
    assert {r.name for r in b.reduce(w).rules} == {"XtX", "PtX"}   # a memo hit, still b's own record
    assert {r.name for r in b.rules_applied()} == {"XtX", "PtX"}
    # a rule of its own: its own memos from then on
    c = standard_system()
    R = resolvent_letter(se.Symbol("lambda"))
    c.order.add(R)
    c.add_rule((A, R), NCPoly.word((R,)) * se.Symbol("lambda") - NCPoly.identity("n"), "resolvent")
    assert c._word_memo is not a._word_memo and c._word_memo == {}
    assert standard_system()._word_memo is a._word_memo


def test_a_trace_fallback_is_recorded_by_every_system_that_meets_it(monkeypatch):
    real = RewritingSystem._adjoint_rep

    def falls_back(self, c):
        self.trace_fallbacks.add(c)
        self._fallback_events += 1
        return real(self, c)
    monkeypatch.setattr(RewritingSystem, "_adjoint_rep", falls_back)
    tr = trace(NCPoly.word((Xt, P, Xt, P, Xt, A, X)))
    std, shared = standard_system(), SharedMemos()   # memos of their own: nothing reduced before
    a, b = (RewritingSystem(std.order.copy(), std.rules, shared=shared) for _ in range(2))
    a.reduce(tr)
    assert a.trace_fallbacks
    b.reduce(tr)
    assert b.trace_fallbacks == a.trace_fallbacks


def test_a_long_residual_is_set_over_rows_and_the_letters_of_an_inverse_statement_read_y_x():
    """The runs appendix: a residual wider than a line over rows of about ROW_CHARS of LaTeX (every term kept, in
    order), and an inverse statement's elements (InverseY1) as y_1 (stop 59)."""
    from stiefelsym.free.rewriting import ROW_CHARS, _rows
    from stiefelsym.free.scene import _generic_tex
    terms = [rf"+ \frac{{1}}{{2}} X^{{T}} X y_{{{k}}}" for k in range(40)]
    terms[0] = terms[0][2:]
    text = _rows(terms)
    rows = text.split(" \\\\\n  &\\quad ")
    assert len(rows) > 1 and all(len(r) <= ROW_CHARS for r in rows)
    assert " ".join(rows) == " ".join(terms)
    assert _rows(["a", "+ b"]) == "a + b"
    assert [_generic_tex(x) for x in ("InverseY1", "InverseX2", "W1", "U", "Xi")] == \
        ["y_{1}", "x_{2}", "W_{1}", "U", r"\mathit{Xi}"]


def test_a_generic_letter_named_with_underscores_is_a_free_letter_as_on_every_other_scene(tmp_path):
    """Names of a claim's generic matrices are letters, digits and underscores on every scene; the free scene
    refused an underscore (eta_n), so a claim true for all n, r was undecided there while the fixed-size
    methods took it (found by trying statements of the paper as a user, stop 60).  Under the free method the
    true claim is proved, the false one keeps its letter in the residual; the derivation sets eta_n as
    eta_{n}."""
    from stiefelsym.claims import load_claims_file
    from stiefelsym.free.scene import _generic_tex
    from stiefelsym.run.runner import run_one
    path = tmp_path / "names.py"
    path.write_text('''
from stiefelsym import admissible, claim, comm

@claim("names-true", paper="user", kind="id", sizes=admissible(n_max=4))
def names_true(s):
    eta, v = s.generic("eta_n", "n", "n", "sym"), s.X @ s.X.T
    Q = s.In - v
    return {"[eta, v]": comm(eta, v) - (Q @ eta @ v - v @ eta @ Q)}

@claim("names-false", paper="user", kind="id", sizes=admissible(n_max=4))
def names_false(s):
    eta, v = s.generic("eta_n", "n", "n", "sym"), s.X @ s.X.T
    return {"[eta, v]": comm(eta, v) - eta @ v}
''')
    reg = load_claims_file(str(path))
    assert run_one(reg.get("names-true"), None, "free", 0).verdict == "proved"
    res = run_one(reg.get("names-false"), None, "free", 0)
    assert res.verdict == "undecided" and "eta_n" in (res.message or ""), res.message
    assert [_generic_tex(x) for x in ("eta_n", "W1_b", "x_")] == [r"\mathit{eta}_{n}", "W_{1,b}", r"x\_"]
