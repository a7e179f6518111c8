"""Number systems: each evaluates the IR's primitive operations over whole matrices."""
