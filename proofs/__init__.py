"""The paper's claims, one module per section of the paper."""

#: catalog modules in the order of the paper
MODULES = ("sec2_hamiltonian_flows", "sec3_geodesic_flows")
