"""Engine crank-slider dynamics: the force table (Table 2)."""
