#!/usr/bin/python3
"""Motion: the exact first-contact time and the timeline of a rising sphere."""

import relpos

e = relpos.Ellipsoid.sphere((0, 0, 0), "1/4")
p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
rise = [[], [], ["-9/4", 0, 1]]  # the centre moves to (0, 0, t^2 - 9/4)

fc = relpos.first_contact(e, p, 0, 2, translation=rise)
t = fc.time
print("first contact:", fc.kind, "at t =", t.decimal(20), "position", fc.position)
print("  t is the root of", " + ".join("%d*t^%d" % (c, k) for k, c in enumerate(t.polynomial) if c),
      "in", [str(x) for x in t.interval])

tl = relpos.timeline(e, p, 0, 2, translation=rise)
for c in tl.changes:
    print("at t ~ %s: %s -> %s -> %s" % (c["time"].decimal(12), c["before"], c["at"], c["after"]))
print("position at t = 3/2:", tl.position_at("3/2"))
