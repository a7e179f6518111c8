"""stiefelsym: mechanical verification of the identities of Fedorov & Jovanovic,
"Geodesic Flows and Neumann Systems on Stiefel Varieties".

The public API for writing claims:

    from stiefelsym import claim, admissible, comm, block, Rank, Count

A claim is a function of a scene ``s`` returning a dict of named checks:
residual matrices or scalars that must vanish on T*V(n, r), ``Rank`` or
``Count`` statements.
"""
from .claims import Checks, Claim, Count, Rank, Registry, Size, admissible, claim, load_catalog, load_claims_file
from .matrix import Mat, block, comm
from .scene import Flow, Scene

__all__ = ["claim", "admissible", "comm", "block", "Rank", "Count", "Checks", "Claim", "Registry", "Size",
           "Mat", "Scene", "Flow", "load_catalog", "load_claims_file"]
__version__ = "0.1.0"
