#!/usr/bin/env python3
"""Fit the polynomial colour map of src/render/colormap.c to matplotlib's viridis.

Least squares, one polynomial in t per channel (degree 8) over 256 samples of viridis (a
development-time check only: orikin does not depend on matplotlib). Prints the coefficients
(constant term first) and the largest error per channel in 1/255 steps.

usage: /usr/bin/python3 scripts/fit_viridis.py
"""
import numpy as np
from matplotlib import colormaps

DEGREE = 8
t = np.linspace(0.0, 1.0, 256)
rgb = colormaps["viridis"](t)[:, :3]
A = np.vander(t, DEGREE + 1, increasing=True)
for ch, name in enumerate("rgb"):
    c, *_ = np.linalg.lstsq(A, rgb[:, ch], rcond=None)
    err = np.max(np.abs(A @ c - rgb[:, ch])) * 255.0
    print(f"{name}: {{" + ", ".join(f"{x:.9g}" for x in c) + f"}}  max error {err:.2f}/255")
