# SPDX-License-Identifier: MIT
"""Interrogates a spline through points (thesis 6.3): curvature, torsion and the
curvature fins ("comb"), written as CSV for any plotting tool.

    PYTHONPATH=build/ci/python /usr/bin/python3 examples/python/curvature_comb.py
"""
import numpy as np

import hulahoops as hh

points = np.array([[0, 0, 0], [30, 20, 5], [60, 10, 15], [90, 35, 10], [120, 30, 0]], dtype=float)
curve = hh.interpolate(points, start="bessel", end="bessel")
a = hh.analyse(curve, 400, fins=["curvature"], fin_scale=200.0)
print(f"length {curve.arc_length():.3f} mm, max curvature {np.nanmax(a['curvature']):.5f} 1/mm, "
      f"torsion in [{np.nanmin(a['torsion']):.5f}, {np.nanmax(a['torsion']):.5f}] 1/mm")
table = np.column_stack([a["t"], a["points"], a["curvature"], a["torsion"], a["fins"][0]["tip"]])
np.savetxt("curvature_comb.csv", table, delimiter=",", header="t,x,y,z,kappa,tau,fin_x,fin_y,fin_z", comments="")
