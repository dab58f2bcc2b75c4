"""Pure calculation core: SI floats in, SI floats out, no web imports.

One module per engineering topic; every formula lives in exactly one function whose
docstring gives the formula, the units and the source. References used throughout (a
module with a numbered reference list of its own numbers its sources in that list):

[1] Seed catalog, "Linear Motion - Leadscrew Assemblies", Design and Engineering Data
    (``shared/seed``).
[2] Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed. (2011), sec. 8-2
    (power screws; Example 8-1, eqs. 8-7 and 8-8) and sec. 4-11 to 4-13 (columns; eq.
    4-45, Johnson's parabola eq. 4-46).
[3] Thomson Industries, "Critical speed" and "Column loading" in the lead screw catalog
    (n_c = 4.76e6 d_r / L^2 for steel, simple-simple, inches).
[4] Timoshenko & Gere, Theory of Elastic Stability (Euler column, end conditions).
[5] Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1 (beam eigenvalues).
"""
