"""§2 Hamiltonian flows on Stiefel varieties."""
SECTION = "2"
