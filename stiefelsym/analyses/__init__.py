"""Analyses built on runs: the mutation analysis, the discovery of conserved quantities and corrections,
the numerical integration of the flows, speed against error and the cost model's measurements."""
