"""State of the caller's own module that a claim function reads (the graph cache's record must follow it)."""
K = 1
