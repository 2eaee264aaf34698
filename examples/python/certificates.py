#!/usr/bin/python3
"""Certificates: every full answer carries evidence that the independent verifier checks."""

import relpos

p = relpos.Paraboloid.standard((0, 0, 0), 1, 1)
pairs = {
    "I": relpos.Ellipsoid.sphere((0, 0, 1), "1/4"),
    "TI": relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4"),
    "C": relpos.Ellipsoid.sphere(("1/2", 0, "1/4"), "3/10"),
    "TE": relpos.Ellipsoid.sphere((0, 0, -1), 1),
    "E": relpos.Ellipsoid.sphere((0, 0, "-3/2"), "1/2"),
}
for expected, e in pairs.items():
    c = relpos.classify(e, p)
    relpos.verify(e, p, c)  # raises relpos.CertificateError if the evidence does not prove it
    print(c.position, c.certificate.kind, c.certificate.to_json())

# A forged answer is refused.
c = relpos.classify(pairs["TI"], p)
forged = relpos.Classification(dict(c.as_dict(), position="I"))
try:
    relpos.verify(pairs["TI"], p, forged)
except relpos.CertificateError as err:
    print("refused:", err)

# Contact only: do the surfaces meet? Also certified for bodies that are not small.
print("contact:", relpos.contact(relpos.Ellipsoid.sphere((0, 0, -5), 4), p).contact)
