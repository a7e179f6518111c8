"""Appendix 2. Double, coupled and complex Neumann systems: the Lagrangian systems, their flows, conserved quantities and Lax pairs."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm  # noqa: F401

SECTION = "A2"
