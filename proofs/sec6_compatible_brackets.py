"""§6 Compatible Poisson brackets and integrability: the pencil Λ1, Λ2 on gl(n), the map Θ = Φ + XXᵀ, the Casimirs and the integrable families of the section."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm  # noqa: F401

SECTION = "6"
