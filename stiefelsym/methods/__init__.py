"""Verification methods: a method is a chart, its points, a backend and a decision rule.

The fixed-size methods (exact, rational, modular, float, ball, auto) are in :mod:`.fixed_size`, the
dimension-free method in :mod:`.dimension_free`."""
