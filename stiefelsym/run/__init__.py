"""Running verifications: the plan, the worker pool, budgets, the confined interpreter, the cost model."""
