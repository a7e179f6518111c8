"""stiefelsym: mechanical verification of the identities of Fedorov & Jovanovic,
"Geodesic Flows and Neumann Systems on Stiefel Varieties".

The public API for writing claims:

    from stiefelsym import claim, admissible, comm, block, Rank, Count, Inverse

A claim is a function of a scene ``s`` returning a dict of named checks:
residual matrices or scalars that must vanish on T*V(n, r), ``Rank``,
``Count``, ``Inverse`` or ``RightInverse`` statements.

Running claims from Python (the results ``stiefelsym verify`` prints, as records):

    from stiefelsym import verify
    results = verify(["euclidean-flow"], sizes=[(4, 2)], methods=["modular"])
    results.ok, results[0].verdict
"""
import sys as _sys

# Exact constants have no size limit: a claim may multiply by 2^15000, and the engine writes such
# integers in decimal (the graph's digest, the records, JSON between its processes).  Python refuses
# the decimal text of an integer above 4300 digits unless told otherwise (a guard for parsing
# untrusted text; a claims file is code, and the engine's own texts are its own).
if hasattr(_sys, "set_int_max_str_digits") and _sys.get_int_max_str_digits() != 0:
    _sys.set_int_max_str_digits(0)

from stiefelsym._version import __version__  # noqa: E402
from stiefelsym.api import load, verify
from stiefelsym.claims import (CatalogError, Checks, Claim, Registry, Size, SizeSpec, admissible, claim, load_catalog,
                               load_claims_file)
from stiefelsym.ir import block
from stiefelsym.ir.statements import Count, Inverse, Rank, RightInverse
from stiefelsym.backends.matrix import Mat, comm, det, elementary
from stiefelsym.results import Result, ResultList
from stiefelsym.reports import notebook as _notebook  # noqa: F401,E402 (installs the displays of results and claims)
from stiefelsym.scene import Flow, Scene

__all__ = ["CatalogError", "claim", "admissible", "comm", "block", "det", "elementary", "Rank", "Count", "Inverse", "RightInverse", "Checks", "Claim", "Registry", "Size",
           "SizeSpec", "Mat", "Scene", "Flow", "load", "load_catalog", "load_claims_file", "verify", "Result",
           "ResultList", "__version__"]
