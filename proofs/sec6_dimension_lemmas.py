"""§6 The dimension lemmas: LEMA1, LEMA2 and the kernels, the isotropic tori (dim_fol, NEUMANN), each with a two-sided certificate."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm  # noqa: F401

SECTION = "6"
