"""A resolvent R(μ) = (μI_n − A)⁻¹ at a spectral parameter μ that moves with the point (a trace polynomial,
μ = tr(PᵀP)): the free scene gives it a letter R_m with A R_m = R_m A = m R_m − I for a fresh symbol m standing
for μ (no AttributeError), the derivative passes of the graph differentiate it (R' = −μ'R²), and every derivative
the free scene would take itself (gradients, brackets, flows of a function that holds it) is refused: a false
statement that drops the motion of μ is never proved, the true one is, with a certificate the checker accepts."""
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact

CLAIM = load_catalog().get("neumann-dual-lax-normal")


def _mu(t):
    return t.tr(t.P.T @ t.P)


def _R(t):
    return t.resolvent(_mu(t))


def _H(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2


def resolvent_definition(s):
    """(μI − A)R(μ) = I written with the letter's own rule: A R = R A = μR − I."""
    R = _R(s)
    return {"A R - R A": s.A @ R - R @ s.A}


def derivative_along_a_flow(s):
    """d/dt R(μ) = −μ' R(μ)² along the Neumann-type flow of ½tr(XᵀAX) (μ = tr(PᵀP) moves along it)."""
    flow = s.dirac_flow(_H)
    return {"dR/dt + mu' R^2": s.d(_R, flow) + s.d(_mu, flow) * (_R(s) @ _R(s))}


def derivative_dropping_the_motion(s):
    """False: d/dt R(μ) = 0 (as if μ were constant)."""
    return {"dR/dt": s.d(_R, s.dirac_flow(_H))}


def derivative_with_the_wrong_sign(s):
    """False: d/dt R(μ) = +μ' R(μ)²."""
    flow = s.dirac_flow(_H)
    return {"dR/dt - mu' R^2": s.d(_R, flow) - s.d(_mu, flow) * (_R(s) @ _R(s))}


def bracket_dropping_the_motion(s):
    """False: {tr(XᵀR(μ)X), tr(XᵀAX)} = 0 (a bracket the free scene would take itself: refused)."""
    return {"bracket": s.bracket(lambda t: t.tr(t.X.T @ _R(t) @ t.X), _H)}


def test_a_moving_spectral_parameter_gets_a_letter():
    for func in (resolvent_definition, derivative_along_a_flow):
        res = run_free(CLAIM, func)
        assert res.verdict == "proved", (func.__name__, res.message)
        assert check_certificate(res.certificate_data).accepted


def test_a_derivative_that_drops_the_motion_is_not_proved():
    for func in (derivative_dropping_the_motion, derivative_with_the_wrong_sign, bracket_dropping_the_motion):
        assert run_free(CLAIM, func).verdict == "undecided", func.__name__
        assert run_exact(CLAIM, 3, 2, 0, func=func).verdict == "fails", func.__name__


def test_the_true_derivative_holds_at_a_fixed_size():
    assert run_exact(CLAIM, 3, 2, 0, func=derivative_along_a_flow).verdict == "proved"


def two_moving_parameters(s):
    """R(tr PᵀP) R(tr XᵀAX) = (R(tr PᵀP) − R(tr XᵀAX))/(tr XᵀAX − tr PᵀP): the two parameters may coincide on
    T*V, so the free scene refuses a second moving parameter rather than divide by their difference."""
    R1, R2 = _R(s), s.resolvent(s.tr(s.X.T @ s.A @ s.X))
    return {"x": R1 @ R2 - R2 @ R1}


def test_a_second_moving_spectral_parameter_is_refused():
    res = run_free(CLAIM, two_moving_parameters)
    assert res.verdict == "undecided" and "two spectral parameters" in res.message
