"""The engineering formulas: one module per topic, one function per formula, each with its
formula, units, validity and source in the docstring. Arithmetic only, so every function
serves one screw (floats) or the whole catalog (NumPy columns)."""
