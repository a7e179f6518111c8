"""Claims for the pytest plugin (copy beside corrections_r.py into a scratch folder and run
`python -m pytest -p no:cacheprovider --stiefelsym plugin_claims.py corrections_r.py -q`): an erratum whose code
raises (no verdict: must not pass as the expected failure) and an erratum that is true (must fail as unexpected)."""
from stiefelsym import admissible, claim


@claim("s73-erratum-error", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="declared false")
def erratum_error(s):
    """An erratum whose code raises at every size: no verdict at all (must not count as the expected failure)."""
    raise RuntimeError("boom")


@claim("s73-erratum-true", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="declared false")
def erratum_true(s):
    """Declared an erratum but TRUE: X^T X = I_r."""
    return {"id": s.X.T @ s.X - s.Ir}
