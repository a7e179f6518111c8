"""Sixth round: the one-sided inverse and the Inverse statement's maps called more than once, the fresh
elements and tensors, the double point's base, the certificates' `about` and scope, the sandbox and the
mutation of graphs (tests/adversary/README.md, the last table).  As before: every run is the CLI in a fresh
process, each test asserts the CORRECT outcome, and a route open today is a strict xfail."""

from adversary_cli import PASSING
from test_adversary_s34b import by_claim, fixed, run_all

STATEFUL = ("adv-s36-ri-stateful-projection", "adv-s36-ri-argument-test", "adv-s36-inv-stateful-pair")


def test_a_map_that_changes_between_its_calls_is_refused():
    """op of a RightInverse is called on inv(y) and then on a generic x (and inv of an Inverse on y and then on
    op(x)): an op that is the identity on its first call (a counter) or on the value its inverse returned (a
    test of its argument) and x ↦ X Xᵀ x otherwise was "onto R^{n×r}": proved (exact), checked (modular,
    rational), numeric (float, ball) at (3,2), and free proved it for every n, r; a pair of maps that are two
    maps each passed as an Inverse.  Closed: the tracer compares the graph of op (and inv) on its two arguments
    (functions numbered by the trace renamed in order) and refuses a map that traces to two graphs: error at
    every fixed size, undecided by free; a map that makes a new function at each call is still proved."""
    got = by_claim(run_all("s36_stateful_maps.py"))
    for c in STATEFUL:
        assert fixed(got[c]) == {"error"} and got[c]["free"] == "error", (c, got[c])
    true = got["adv-s36-ri-fresh-functions"]
    assert fixed(true) <= set(PASSING) and true["free"] == "proved", true


def test_a_tensor_that_is_another_form_on_some_evaluations_is_refused():
    """poisson_checks evaluates the tensor (one engine step per evaluation, its form traced as a function of
    (x, a, b)) for the antisymmetry, the degree and the Jacobi identity; a form that counts its evaluations,
    (1 + tr(xC))⟨x, [a, b]⟩ on the first six and Lie–Poisson afterwards, passed all three at (4,2): proved
    (exact), checked (modular, rational), numeric (float, ball), and free proved it for every n, r, while the
    same tensor with one form fails the Jacobi identity.  Closed: checked_tensor compares the graph of each evaluation's form with the first's
    (trace.same_step_function) and refuses another: error at every fixed size; free is not a pass."""
    got = by_claim(run_all("s36_stateful_tensor.py", size="4,2", methods=("modular", "rational", "float", "ball")))
    form, control = got["adv-s36-poisson-counting-form"], got["adv-s36-poisson-counting-control"]
    assert fixed(form) == {"error"} and form["free"] not in PASSING, form
    assert fixed(control) == {"fails"} and control["free"] not in PASSING, control


def test_the_stateful_tensor_under_exact():
    """The same under exact at (4,2): refused (error); before, proved."""
    got = by_claim(run_all("s36_stateful_tensor.py", ids=("adv-s36-poisson-counting-form",), size="4,2",
                           methods=("exact",), free=False))
    assert fixed(got["adv-s36-poisson-counting-form"]) == {"error"}, got


def test_a_tensor_that_is_another_form_in_its_compatibility_check_is_refused():
    """A tensor object that is Λ (Poisson on so(3), not compatible with Lie–Poisson) in its poisson_checks and
    Lie–Poisson in compatibility(s, T, LP) (a flag the claim sets between the calls; each call is one form)
    was "Poisson and compatible with Lie–Poisson": proved (exact), checked (modular, rational), numeric (float,
    ball) at (3,2), and so were 1·T (T.scaled) in compatibility and a subclass whose own __add__ builds the sum
    with no parts; the control with one form fails.  Closed: the evaluations of one tensor object are one form
    across the claim, and the form of a sum T1 + T2 is held to its parts' (PoissonTensor keeps them): error at
    every fixed size; free is not a pass (undecided: coordinates); one object used consistently is proved."""
    got = by_claim(run_all("s36_tensor_across_checks.py", size="3,2"))
    for c in ("adv-s36-poisson-two-faces", "adv-s36-poisson-two-faces-scaled", "adv-s36-poisson-two-faces-own-sum"):
        assert fixed(got[c]) == {"error"} and got[c]["free"] not in PASSING, (c, got[c])
    control = got["adv-s36-poisson-two-faces-control"]
    assert fixed(control) == {"fails"} and control["free"] not in PASSING, control
    for c in ("adv-s36-poisson-field-alone", "adv-s36-poisson-same-object-true"):
        assert fixed(got[c]) <= set(PASSING), (c, got[c])


def test_a_covector_that_changes_between_the_bracket_and_the_right_side_is_refused():
    """poisson_map_residual(s, dirac, 2Φ, LP, a, b) with a covector a that is G on its first call (inside the
    bracket's function) and 2G on the claim's scene was "2Φ is a Poisson map": proved (exact), checked
    (modular, rational), numeric (float, ball) at (3,2); the control with one covector fails.  Closed: the map
    and the covectors must be one graph of their scene at every call (trace.same_scene_function, the claim's
    scene standing for every scene): error at every fixed size; Φ with generic covectors, also captured from
    the claim's scene, is still passed."""
    got = by_claim(run_all("s36_poisson_map_calls.py"))
    bad = got["adv-s36-pmap-stateful-covector"]
    assert fixed(bad) == {"error"} and bad["free"] not in PASSING, bad
    assert fixed(got["adv-s36-pmap-control"]) == {"fails"}, got["adv-s36-pmap-control"]
    for c in ("adv-s36-pmap-true", "adv-s36-pmap-captured-true"):
        assert fixed(got[c]) <= set(PASSING), (c, got[c])


def test_two_corrections_of_one_description_are_refused(tmp_path):
    """A claim with two corrections described alike (a true one, checked, and a false one, fails): every record
    names a correction by its description, so `check` ran the first for both and rejected the honest record of
    the second (digest), and a results file where the false one's record was replaced by a copy of the true
    one's was accepted by `check` and rendered by `report` ("verified"), the failing correction gone.  Closed:
    a claim refuses a second correction of the same description (the decorator, and the verifying process for
    a list the file appended to): the file is bad input, exit 2."""
    from adversary_cli import HERE, cli
    for name in ("s36_duplicate_corrections.py", "s36_duplicate_corrections_appended.py"):
        res = cli("verify", "--claims", str(HERE / name), "--size", "3,2", "--method", "modular", "--jobs", "1")
        assert res.returncode == 2 and "two corrections described" in res.stderr, (name, res.returncode,
                                                                                   res.stderr[-600:])
