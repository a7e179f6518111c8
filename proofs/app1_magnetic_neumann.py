"""Appendix 1. Magnetic Neumann systems: the twisted symplectic form, the momentum map Φ_ε, the magnetic flows and their Lax pairs, Proposition YM."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm  # noqa: F401

SECTION = "A1"
