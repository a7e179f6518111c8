# ruff: noqa
"""A test module by python_files = checks/*.py (a pattern with a folder); it declares no claims."""
def test_must_run():
    assert False, "this test ran (it should, and it fails on purpose)"
