"""The paper's claims, one module per section of the paper."""

#: catalog modules in the order of the paper
MODULES = ("sec2_hamiltonian_flows", "sec3_geodesic_flows", "sec4_integrability",
           "sec5_neumann", "sec8_dual_lax_pair")

#: section headings for the reports
SECTION_TITLES = {
    "2": "Hamiltonian flows on Stiefel varieties",
    "3": "Geodesic flows",
    "4": "Integrability of geodesic flows",
    "5": "The Neumann systems on Stiefel varieties",
    "8": "The dual Lax pair and geometric interpretation of integrals",
}
