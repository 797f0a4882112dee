"""Layer L1: Constrained Stochastic Scene Generation (and the uniform-random baseline)."""
