from stiefelsym import admissible, claim  # noqa: F401  (re-exported)

ALL = admissible(n_max=3)
