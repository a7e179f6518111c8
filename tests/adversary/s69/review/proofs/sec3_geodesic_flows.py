# ruff: noqa
def boom(s):
    raise ValueError("helper raised")
