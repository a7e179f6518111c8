"""The version of stiefelsym (one place: the package, the dask workers' check)."""
__version__ = "0.1.0"
