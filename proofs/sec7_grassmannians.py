"""§7 Reduction to Grassmannians: the Neumann flows on Ψ = 0, the reduced equation on e_1∧…∧e_r, the case r = n − 1 and the quartic Hamiltonian."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm  # noqa: F401

SECTION = "7"
