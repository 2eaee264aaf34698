#!/usr/bin/python3
"""A scene: many bodies against one paraboloid with the library's early-outs on every core."""

import numpy

import relpos

rng = numpy.random.default_rng(7)
p = relpos.Paraboloid.standard((0, 0, 0), 1, 2)
bodies = [relpos.Ellipsoid.from_axes((x, y, z), (a, a / 2, a / 3), (1, 0, 0, 1))
          for x, y, z, a in zip(*rng.uniform(-2, 2, (3, 2000)), rng.uniform(0.05, 0.5, 2000))]
bodies.append(relpos.Ellipsoid.sphere((0, 0, "1/4"), "1/4"))  # touches the vertex from inside

result = relpos.scene(p, bodies)
print("bodies:", len(result.positions), " threads:", result.threads)
print("positions:", result.counts())
print("settled by:", {k: v for k, v in result.stage_counts().items() if v})
print("last body:", result.names()[-1])
