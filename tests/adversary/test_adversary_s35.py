"""Fifth round: the double Neumann system's point next to the scene's own point, the Inverse statement's
divisors (constants that vanish at some size), and what else was tried (tests/adversary/README.md, the last
table).  As before: every run is the CLI in a fresh process, each test asserts the CORRECT outcome, and a route
open today is a strict xfail."""


from adversary_cli import PASSING
from test_adversary_s34b import by_claim, fixed, run_all

DOUBLE_FALSE = ("adv-s35-dx-in-the-span-of-x", "adv-s35-dx-dy-against-x", "adv-s35-dx-against-p",
                "adv-s35-dx-in-the-span-of-y")
DOUBLE_TRUE = "adv-s35-dx-not-moved-by-x"


def test_the_double_point_is_independent_of_the_scenes_point():
    """DX = X₀DU was built on the scene's own X: X Xᵀ DX = DX, (XᵀDX)(DYᵀX) = I_r, tr(Pᵀ(I − XXᵀ)DX) = 0 were
    proved / checked / numeric at (3,2) by every fixed-size method (free: undecided, DX is a letter of its
    own), and dDX/dt = 0 along a flow of (X, P), true, failed under every fixed-size method (free: proved).
    Closed: the double point is built on a point of V(n, r) of its own (Scene._double_base)."""
    got = by_claim(run_all("s35_double_point.py", ids=(*DOUBLE_FALSE, DOUBLE_TRUE)))
    for c in DOUBLE_FALSE:
        assert fixed(got[c]) == {"fails"} and got[c]["free"] == "undecided", (c, got[c])
    true = got[DOUBLE_TRUE]
    assert fixed(true) <= set(PASSING) and true["free"] == "proved", true


def test_the_double_points_parameters_are_not_the_claims_own():
    """The double point's D, U, Z, V, W were drawn by s.scalar("double_d1") ... and s.general_params("double_V",
    ...), the claim's own names: a claim's s.scalar("double_d1") was D's entry, so tr(DXᵀDX) = ν² at r = 1 and
    DẊ = G (G = s.general_params("double_V", n, r)) were proved / checked / numeric by every fixed-size method.
    Closed: the double point's parameters are the engine's (names a claim cannot spell)."""
    got = by_claim(run_all("s35_double_point.py", ids=("adv-s35-scalar-named-like-d", "adv-s35-params-named-like-v"),
                           size="3,1"))
    for c in ("adv-s35-scalar-named-like-d", "adv-s35-params-named-like-v"):
        assert fixed(got[c]) == {"fails"} and got[c]["free"] == "undecided", (c, got[c])


def test_a_tensor_built_on_the_test_point_is_not_passed():
    """Λ_x(a, b) = ⟨x, [a, b]⟩ + |x − x₀|²⟨a, b⟩ on so(n) is not antisymmetric where x ≠ x₀; with x₀ the test
    point of poisson_checks (s.generic("Bkx", "n", "n") projected, or spied from a first call) every fixed-size
    method said proved / checked / numeric at (3,2).  Closed: the test elements are fresh (s.fresh: numbered by
    the engine, new at every call, no claim's name), and the tensor is traced as a function of (x, a, b) at
    each evaluation, so a point a tensor keeps is a parameter of that function: the named point and the
    control fail under every fixed-size method, the spied one is refused by the tracer (error: a function's
    parameter used outside the function); free is undecided for all three."""
    got = by_claim(run_all("s35_poisson_test_point.py"))
    for c in ("adv-s35-poisson-control", "adv-s35-poisson-named-test-point"):
        assert fixed(got[c]) == {"fails"}, (c, got[c])
    spied = got["adv-s35-poisson-spied-test-point"]
    assert fixed(spied) == {"error"}, spied
    for c, v in got.items():
        assert v["free"] not in PASSING, (c, v)


FRESH_KEPT = ("adv-s35-poisson-point-of-compatibility", "adv-s35-poisson-call-spy", "adv-s35-poisson-two-calls",
              "adv-s35-poisson-in-call-keeper")


def test_a_point_kept_from_the_poisson_checks_is_never_the_test_point():
    """Points kept by a tensor from a first compatibility, by a PoissonTensor subclass's __call__, from one of two
    poisson_checks of one claim, or within one poisson_checks (a form that keeps the first point it is evaluated
    at: it passed antisymmetry, degree and Jacobi with fresh points alone) are parameters of the form's function:
    error under every fixed-size method, undecided by free; a tensor built on an element the claim drew with
    s.fresh fails; Lie–Poisson checked twice and compatible with its negative is proved (free too)."""
    got = by_claim(run_all("s35_poisson_fresh_variations.py"))
    for c in FRESH_KEPT:
        assert fixed(got[c]) == {"error"}, (c, got[c])
        assert got[c]["free"] not in PASSING, (c, got[c])
    own = got["adv-s35-poisson-own-fresh"]
    assert fixed(own) == {"fails"} and own["free"] not in PASSING, own
    true = got["adv-s35-poisson-fresh-true"]
    assert fixed(true) <= set(PASSING) and true["free"] == "proved", true


def test_the_scope_of_a_free_proof_cannot_be_widened_by_its_text(tmp_path):
    """magnetic-psi12-conserved is proved for every n at r = 2 (its certificate uses E₁E₁ᵀ + E₂E₂ᵀ = I_r); its
    record's certificate text edited from "(for every n at r = 2, the only r the claim is stated for: it uses
    ...)" to "(for every n and r)" was rendered by `report` as "proved" in the table and counted in the headline
    among "proved for every n and r at once", and `check` accepted it (it compared the certificate's data only).
    Closed: `report` and `check` compare the certificate's text with the one derived again."""
    import json

    from adversary_cli import cli
    out = tmp_path / "run"
    cli("verify", "magnetic-psi12-conserved", "--method", "free", "--jobs", "1", "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    record = payload["results"][0]
    assert record["verdict"] == "proved" and "(for every n at r = 2" in record["certificate"], record["certificate"]
    assert cli("check", str(out / "results.json")).returncode == 0
    start = record["certificate"].index("(for every n at r = 2")
    end = record["certificate"].index(")", start) + 1
    record["certificate"] = record["certificate"][:start] + "(for every n and r)" + record["certificate"][end:]
    forged = tmp_path / "forged.json"
    forged.write_text(json.dumps(payload))
    res = cli("check", str(forged))
    assert res.returncode == 1 and "REJECTED magnetic-psi12-conserved" in res.stdout, (res.returncode, res.stdout[-1500:])
    rep = cli("report", "--results", str(forged), "--report-dir", str(tmp_path / "rep"))
    assert rep.returncode == 2 and not (tmp_path / "rep" / "verification.md").exists(), (rep.returncode, rep.stderr[-800:])


def test_a_generic_matrix_named_w_is_not_the_kernel_frame():
    """K G = 0 with K = twisted.kernel_annihilator(s) and G = s.generic("W", "n", "r") (a generic matrix of the
    claim's own) was proved / checked / numeric at (3,1) by every fixed-size method: kernel_frame drew W by
    s.generic("W", "n", "r"); free: undecided (two letters).  Closed: the frame's parameters are the engine's."""
    got = by_claim(run_all("s35_kernel_frame_named.py", size="3,1"))
    for c in ("adv-s35-kernel-frame-named-w", "adv-s35-kernel-frame-named-v"):
        assert fixed(got[c]) == {"fails"} and got[c]["free"] == "undecided", (c, got[c])


def test_a_right_inverse_that_holds_at_some_sizes_only_is_not_passed_there():
    """RightInverse with a factor (tr I_r − 1), a constant at each size but 0 at r = 1: refused under every
    method (a divisor that is not a constant of the algebra), free undecided.  X Xᵀ declared onto R^{n×r}
    (the identity as its right inverse): fails at (3,2) under every fixed-size method (onto only at r = n),
    free undecided (a nonzero normal form)."""
    got = by_claim(run_all("s35_right_inverse_tricks.py"))
    scaled, proj = got["adv-s35-ri-vanishing-factor"], got["adv-s35-ri-projection"]
    assert fixed(scaled) == {"error"} and scaled["free"] == "error", scaled
    assert fixed(proj) == {"fails"} and proj["free"] == "undecided", proj
