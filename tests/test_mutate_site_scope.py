"""The sites a mutation analysis on graphs changes (stiefelsym.analyses.mutate.site_rings, ``--sites``): by
default those of the claim's own function, as the source mode edits the claim's own source; where the claim's
function offers no mutant (its formulas live in helpers), those of the functions it calls, one level of calls
at a time; with ``sites="all"`` every site of its graphs."""
from __future__ import annotations

from stiefelsym.analyses.mutate import SITE_SCOPES, graph_mutants, run_mutation, site_rings
from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.ir import _clean
from stiefelsym.ir.mutants import MutantCensus, site_groups, site_mutants
from stiefelsym.ir.trace import trace
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
SIZES = [Size(3, 2)]
FIXED = ("exact", "rational", "modular", "float")


def product_xp(s):
    """XᵀP (two calls deep from only_in_helpers)."""
    return s.X.T @ s.P


def symmetrized(s):
    """XᵀP + (XᵀP)ᵀ = XᵀP + PᵀX (one call deep from only_in_helpers)."""
    return product_xp(s) + product_xp(s).T


def in_a_helper(s):
    """XᵀP + PᵀX = 0, its first term built by a helper."""
    return {"sym": product_xp(s) + s.P.T @ s.X}


def only_in_helpers(s):
    """XᵀP + PᵀX = 0, every node of it built by helpers."""
    return {"sym": symmetrized(s)}


def toy(func, cid: str) -> Claim:
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=3))


def where(m) -> str:
    """The function a mutant's site is in (its description ends with ``file:line in f(): ...``)."""
    return m.description.split(" in ")[-1].split("(")[0]


def test_the_claim_scope_changes_the_claims_own_function_only():
    c = toy(in_a_helper, "toy-in-a-helper")
    own, why = graph_mutants(c, SIZES, sites="claim")
    every, why_every = graph_mutants(c, SIZES, sites="all")
    assert not why and not why_every and own
    assert {where(m) for m in own} == {"in_a_helper"}
    assert {where(m) for m in every} == {"in_a_helper", "product_xp"}
    assert {m.description for m in own} < {m.description for m in every}
    # the source mode's scope: the helper's product is not changed, the claim's own is
    assert any(m.operator == "drop" and where(m) == "in_a_helper" for m in own)


def test_a_claim_whose_formulas_live_in_helpers_gets_the_mutants_of_its_nearest_helpers():
    """only_in_helpers builds no node itself: its mutants are those of symmetrized() (one call deep), not
    those of product_xp() (two calls deep); each is refuted by every fixed-size method, and the report
    says which sites were changed."""
    c = toy(only_in_helpers, "toy-only-in-helpers")
    rings = site_rings(only_in_helpers)
    assert [text.split(":")[0] for text, _ in rings] == [
        "the claim's function", "the functions it calls", "the functions those call (2 calls deep)", "every site"]
    muts, why = graph_mutants(c, SIZES, sites="claim")
    assert not why and muts and {where(m) for m in muts} == {"symmetrized"}
    every, _ = graph_mutants(c, SIZES, sites="all")
    assert {where(m) for m in every} == {"symmetrized", "product_xp"}
    rep = run_mutation([c], sizes=SIZES, on="graphs", sites="claim")
    cm = rep.claims[0]
    assert rep.ok() and not cm.skipped and cm.sites == "the claim's function; the functions it calls: symmetrized"
    assert cm.mutant_count == len(muts)
    flip = next(o for o in cm.mutants if o.operator == "sign" and "flipped" in o.description)
    assert flip.classification == "killed" and all(flip.killed_by[m] == "fails" for m in FIXED)
    assert all(o.classification in ("killed", "equivalent") for o in cm.mutants)
    assert sum(o.classification == "killed" for o in cm.mutants) >= 3


def test_the_rings_are_disjoint_and_cover_every_site():
    """On a catalog claim whose formulas are in the claim and in helpers (neumann-lax: its Lax matrix and
    the Neumann Hamiltonian), every site of its graph is in exactly one ring, and the claim's ring holds
    the sites of its own function only."""
    c = load_catalog().get("neumann-lax")
    cons = (REALIZATIONS[c.realization].name, REALIZATIONS[c.realization].build)
    g = _clean(trace, c.func, None, None, cons, None, True)
    rings = site_rings(c.func)
    sited = {s for s in g.sites if s is not None}
    assert len(sited) > 20
    for s in sited:
        assert sum(keep(s) for _, keep in rings) == 1, s
    q = c.func.__code__.co_qualname
    own = {s for s in sited if rings[0][1](s)}
    assert own and all(s.function == q or s.function.startswith(q + ".") for s in own)
    assert any(s.function == "neumann_hamiltonian" for s in sited - own)
    # the groups a ring keeps are those of its sites; a ring that keeps nothing makes no mutant (control)
    census = MutantCensus()
    assert site_mutants({None: g}, cons, census, keep=lambda s: False) == [] and census.sites == 0
    assert set(site_groups({None: g}, rings[0][1])) < set(site_groups({None: g}))
    own_muts, _ = graph_mutants(c, None, sites="claim")
    every, _ = graph_mutants(c, None, sites="all")
    assert 0 < len(own_muts) < len(every)


def test_an_unknown_scope_is_refused():
    assert SITE_SCOPES == ("claim", "all")
    for call in (lambda: graph_mutants(toy(in_a_helper, "t"), SIZES, sites="helpers"),
                 lambda: run_mutation([toy(in_a_helper, "t")], sizes=SIZES, on="graphs", sites="helpers")):
        try:
            call()
        except ValueError as exc:
            assert "helpers" in str(exc)
        else:
            raise AssertionError("an unknown scope of sites was accepted")


def test_a_rank_and_a_count_are_changed_at_the_statement_that_made_them():
    """A Rank or Count node is made when the claim has returned (no claim frame), so it takes the site of the
    Rank(...) or Count(...) expression: its expected value k -> k + 1 (and a rank's k -> k - 1) is a mutant at
    that site (as the source mode changes the claim's expression of it), refuted by the exact, rational and
    modular methods.  A
    statement made outside a trace with sites keeps no site."""
    from test_methods import dimension_of_V
    c = Claim(id="toy-dim", paper=("toy",), kind="dim", section="", func=dimension_of_V, sizes=admissible(n_max=3))
    muts, why = graph_mutants(c, SIZES, sites="claim")
    assert not why
    rank = [m for m in muts if "expected rank" in m.description]
    count = [m for m in muts if "expected count" in m.description]
    assert len(rank) == 2 and len(count) == 1 and all("`Rank(s.mat(rows)" in m.description for m in rank)
    assert any("lowered to" in m.description for m in rank)     # k - 1: a point where the rank is higher refutes it
    assert "`Count(" in count[0].description
    rep = run_mutation([c], sizes=SIZES, on="graphs", methods=("exact", "rational", "modular"))
    cm = rep.claims[0]
    assert rep.ok() and not cm.skipped
    for m in rank + count:
        o = next(o for o in cm.mutants if o.description == m.description)
        assert o.classification == "killed" and all(o.killed_by[k] == "fails" for k in ("exact", "rational", "modular"))
    from stiefelsym import Rank
    assert not hasattr(Rank(None, 1), "_site")


def gram(s):
    """XᵀX (= I on V)."""
    return s.X.T @ s.X


def rank_of_a_helpers_matrix(s):
    """rank XᵀX = r: the formula in a helper, the statement in the claim."""
    from stiefelsym import Rank
    return {"rank": Rank(gram(s), s.r)}


def test_a_statement_alone_does_not_stop_the_widening():
    """The claim's function makes only the Rank statement (its expected value k -> k + 1 is its one mutant):
    the helper that builds the matrix is changed too, as if the claim's function offered no mutant."""
    c = Claim(id="toy-rank", paper=("toy",), kind="dim", section="", func=rank_of_a_helpers_matrix,
              sizes=admissible(n_max=3))
    muts, why = graph_mutants(c, SIZES, sites="claim")
    assert not why
    assert {where(m) for m in muts} == {"rank_of_a_helpers_matrix", "gram"}
    assert sum("expected rank" in m.description for m in muts) == 2
    census = MutantCensus()
    from stiefelsym.analyses.mutate import _graph_mutants
    _, _, _, scope = _graph_mutants(c, SIZES, census, sites="claim")
    assert scope == "the claim's function; the functions it calls: gram"
    assert census.sites == len(muts) + census.ill_typed + census.same_as_claim + census.duplicates


def test_the_report_names_the_claims_mutated_at_their_helpers_sites():
    from stiefelsym.reports.report import render_mutation_markdown
    rep = run_mutation([toy(only_in_helpers, "toy-only-in-helpers"), toy(in_a_helper, "toy-in-a-helper")],
                       sizes=SIZES, on="graphs", methods=("rational",))
    md = render_mutation_markdown(rep.to_json())
    assert "- `toy-only-in-helpers`: the claim's function; the functions it calls: symmetrized" in md
    assert "`toy-in-a-helper`:" not in md        # its own function's sites sufficed
