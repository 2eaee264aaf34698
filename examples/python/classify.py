#!/usr/bin/python3
"""Classify one pair exactly and print the answer with its evidence (doc/python.md)."""

from fractions import Fraction

import relpos

# z = x^2/1.2^2 + y^2/1.5^2, and the README's sphere: decimals and fractions are exact rationals.
p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
e = relpos.Ellipsoid.sphere((0, "0.5", "92281/129600"), Fraction(1, 4))
c = relpos.classify(e, p)
print("position:", c.position, "-", relpos.POSITION_MEANINGS[c.position])
print("small:", c.small, " rho:", c.rho, " stage:", c.stage)
print("rule:", c.rule)
print("f coefficients (low degree first):", c.as_dict()["f"])

# The same pair in the CLI's JSON forms: dicts are read by the CLI's reader.
same = relpos.classify(relpos.Ellipsoid({"sphere": {"center": [0, "1/2", "92281/129600"], "radius": "0.25"}}),
                       relpos.Paraboloid({"vertex": [0, 0, 0], "a": "6/5", "b": 1.5}))
print("same answer from the JSON forms:", same == c)

# Bad input: the CLI's message.
try:
    relpos.Ellipsoid([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]])
except ValueError as err:
    print("error:", err)
