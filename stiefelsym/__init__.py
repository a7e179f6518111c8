"""stiefelsym: mechanical verification of the identities of Fedorov & Jovanovic,
"Geodesic Flows and Neumann Systems on Stiefel Varieties".

The public API for writing claims:

    from stiefelsym import claim, admissible, comm, block, Rank, Count

A claim is a function of a scene ``s`` returning a dict of named checks:
residual matrices or scalars that must vanish on T*V(n, r), ``Rank`` or
``Count`` statements.
"""
import os as _os

# The engine's parallelism is one process per run (--jobs); BLAS threads inside each process only
# compete with the other workers (on 2 cores a 200 x 200 float64 product was 30x slower with
# OpenBLAS's default threads under load).  Set before numpy is first imported; an explicit
# setting in the environment wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    _os.environ.setdefault(_var, "1")

from .claims import Checks, Claim, Count, Rank, Registry, Size, admissible, claim, load_catalog, load_claims_file
from .ir import block
from .matrix import Mat, comm
from .scene import Flow, Scene

__all__ = ["claim", "admissible", "comm", "block", "Rank", "Count", "Checks", "Claim", "Registry", "Size",
           "Mat", "Scene", "Flow", "load_catalog", "load_claims_file"]
__version__ = "0.1.0"
