"""Round 14 (tests/adversary/README.md, the "Round 14" table): the exact method's proofs at a size taken from the
dimension-free proof of the same graph (`methods/specialise.py`), beyond a claim's symbolic budget.  Each test
asserts the CORRECT outcome: a proof at (n, r) only where the dimension-free certificate is a proof there."""
import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.methods import specialise
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.run.runner import run_one

SPECIALISED = "the dimension-free proof, specialised"
PASSING = ("proved", "checked", "numeric")


def _claim(func, sizes, cid=None, **kw):
    return Claim(id=cid or func.__name__.replace("_", "-"), paper=("prep",), kind="id", section="t", func=func,
                 sizes=sizes, exact_max_n=1, **kw)


def xxt(s):
    """X Xᵀ = I_n: true at r = n only."""
    return {"XXt - I": s.X @ s.X.T - s.In}


def dual(s):
    """XᵀP + PᵀX = 0: true at every size."""
    return {"XtP + PtX": s.X.T @ s.P + s.P.T @ s.X}


@pytest.fixture(autouse=True)
def _fresh():
    specialise.reset()
    yield
    specialise.reset()


@pytest.mark.parametrize("field,value", [("r_is_n", False), ("r_in", ())])
def test_a_statement_of_sizes_changed_in_place_is_not_given_the_old_proof(field, value):
    """NA: the dimension-free result was kept while the claim's SizeSpec was the same object; changed in place
    (object.__setattr__, as a notebook can) from r = n to every r, the proof of X Xᵀ = I_n that used X Xᵀ = I_n
    (a hypothesis of r = n) was lent to (4,2), and the modular cross-check turned it into `error` where the claim
    fails.  Closed: the cached result is keyed by the families of sizes read now, and the certificate's own
    hypotheses must hold at the size (`specialise.scope_problem`)."""
    sizes = admissible(5, r_is_n=True) if field == "r_is_n" else admissible(5, r_in=("n",))
    c = _claim(xxt, sizes)
    res = run_one(c, Size(4, 4), "exact", 0)
    assert res.verdict == "proved" and res.reductions[0].startswith(SPECIALISED)
    object.__setattr__(c.sizes, field, value)
    for method in ("exact", "auto"):
        res = run_one(c, Size(4, 2), method, 0)
        assert res.verdict == "fails", (method, res.verdict, res.message)


def test_the_certificate_states_its_own_scope():
    """The scope is read from the certificate, whatever the claim says now: a hypothesis of r = n at r < n, a case
    of cases that does not cover the size, a certificate of another realization, a coefficient with a pole at the
    size, a certificate that cannot be read."""
    square = run_free(_claim(xxt, admissible(5, r_is_n=True))).certificate_data
    assert specialise.scope_problem(square, "standard", None, 4, 4) == ""
    assert "XXt" in specialise.scope_problem(square, "standard", None, 4, 2)
    assert "realization" in specialise.scope_problem(square, "metric", None, 4, 4)
    cases = run_free(_claim(dual, admissible(5, r_in=(1, "n")))).certificate_data
    assert cases["format"].endswith("cases-1")
    from stiefelsym.ir import SizeFamily
    assert specialise.scope_problem(cases, "standard", SizeFamily(1, 2), 4, 1) == ""
    assert specialise.scope_problem(cases, "standard", SizeFamily(None, 1), 4, 4) == ""
    assert "no case" in specialise.scope_problem(cases, "standard", SizeFamily(2, 2), 4, 2)
    plain = run_free(_claim(dual, admissible(5))).certificate_data
    poled = {**plain, "entries": [{**e, "terms": [{**t, "coef": "1/(n - r)"} for t in e["terms"]]}
                                  for e in plain["entries"]]}
    assert "pole" in specialise.scope_problem(poled, "standard", None, 4, 4)
    assert specialise.scope_problem(poled, "standard", None, 4, 2) == ""
    assert "cannot be read" in specialise.scope_problem({"format": "forged"}, "standard", None, 4, 2)


def slow_rewriting(s):
    """True: (XᵀP + PᵀX) M⁸ = 0 with M = XᵀAP + PᵀAX + XᵀX: the free algebra expands 3⁸ words (about 3 s), the
    modular method evaluates it at a point in milliseconds."""
    M = s.X.T @ s.A @ s.P + s.P.T @ s.A @ s.X + s.X.T @ s.X
    Y = M
    for _ in range(7):
        Y = Y @ M
    return {"x": (s.X.T @ s.P + s.P.T @ s.X) @ Y}


def test_a_slow_dimension_free_attempt_does_not_take_the_run_budget(monkeypatch):
    """NB: beyond the symbolic budget the dimension-free attempt ran unbounded in the run's own process before the
    methods that decide the claim at the size: a true claim whose rewriting is slow (ten factors: 30 s) and whose
    modular run takes 0.01 s was `inconclusive` (the run's --timeout 15 exceeded) under auto and exact.  Closed: the
    attempt runs in a forked child killed after FREE_SECONDS (a quarter of the run's budget if less); then the run
    goes on as before (auto: modular; exact: its charts)."""
    import time
    monkeypatch.setattr(specialise, "FREE_SECONDS", 0.5, raising=False)
    c = _claim(slow_rewriting, admissible(5))
    t0 = time.perf_counter()
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "checked" and res.method == "modular", (res.verdict, res.message)
    assert time.perf_counter() - t0 < 2.5
    monkeypatch.setattr(specialise, "FREE_SECONDS", 60.0)     # a longer limit: the attempt is made again
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "proved" and res.reductions[0].startswith(SPECIALISED)
