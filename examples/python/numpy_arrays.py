#!/usr/bin/python3
"""Many pairs from numpy arrays: decide_positions reads every entry exactly, on every core."""

import numpy

import relpos

rng = numpy.random.default_rng(1)
n = 10000
# Spheres near the cup z = x^2 + y^2, as float64 matrices (n, 4, 4).
x, y = rng.uniform(-1, 1, (2, n))
z = x * x + y * y + rng.uniform(-0.3, 0.3, n)
r = rng.uniform(0.01, 0.3, n)
E = numpy.zeros((n, 4, 4))
E[:, 0, 0] = E[:, 1, 1] = E[:, 2, 2] = 1
for k, c in enumerate((x, y, z)):
    E[:, k, 3] = E[:, 3, k] = -c
E[:, 3, 3] = x * x + y * y + z * z - r * r
# Two exact tangencies at the vertex: radius 1/4 centred at (0, 0, 1/4) (TI) and at (0, 0, -1/4) (TE).
E[0] = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -0.25], [0, 0, -0.25, 0]]
E[1] = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.25], [0, 0, 0.25, 0]]
P = numpy.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, -0.5], [0, 0, -0.5, 0]])  # shared by all pairs

codes = relpos.decide_positions(E, P)
names = numpy.array(relpos.POSITION_NAMES)[codes]
print("first two:", names[:2].tolist())
print("counts:", {name: int((codes == k).sum()) for k, name in enumerate(relpos.POSITION_NAMES)})

# One bad matrix need not abort the call: errors="code" marks it relpos.INVALID (-1).
E[5] = numpy.diag([1.0, -1.0, 1.0, -1.0])
codes = relpos.decide_positions(E, P, errors="code")
print("invalid pairs:", numpy.flatnonzero(codes == relpos.INVALID).tolist())

# numpy.longdouble is read exactly too (its values are dyadic rationals), never rounded to float64.
L = E[:2].astype(numpy.longdouble)
L[0, 3, 3] = -numpy.longdouble(2) ** -1100  # the TI sphere pushed down by 2^-1100: it now crosses
print("longdouble:", numpy.array(relpos.POSITION_NAMES)[relpos.decide_positions(L, P)].tolist())
