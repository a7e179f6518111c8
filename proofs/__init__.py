"""The paper's claims, one module per section of the paper."""

#: catalog modules in the order of the paper
MODULES = ("sec1_introduction", "sec2_hamiltonian_flows", "sec3_geodesic_flows", "sec4_integrability",
           "sec5_neumann", "sec6_compatible_brackets", "sec6_dimension_lemmas",
           "sec7_grassmannians", "sec8_dual_lax_pair", "app1_magnetic_neumann",
           "app2_double_coupled_complex")

#: section headings for the reports
SECTION_TITLES = {
    "1": "Introduction",
    "2": "Hamiltonian flows on Stiefel varieties",
    "3": "Geodesic flows",
    "4": "Integrability of geodesic flows",
    "5": "The Neumann systems on Stiefel varieties",
    "6": "Compatible Poisson brackets and integrability",
    "7": "Reduction to Grassmannians",
    "8": "The dual Lax pair and geometric interpretation of integrals",
    "A1": "Appendix 1. Magnetic Neumann systems",
    "A2": "Appendix 2. Double, coupled and complex systems",
}
