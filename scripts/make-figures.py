#!/usr/bin/python3
"""Render doc/figures/{I,TI,C,TE,E}.png, doc/figures/paper-example.png and one
doc/figures/quadric-<type>.png for each type of relpos.Quadric (doc/quadrics.md, "Figures") with the
built Python package relpos (matplotlib, Agg backend). Each pair is classified by the library; the
script stops if a pair does not get the position it was built to have.

    /usr/bin/python3 scripts/make-figures.py [--build BUILD_DIR] [--out DIR] [--dpi N]
"""

import argparse
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))

# (file name, expected position, ellipsoid, paraboloid, view elevation)
PAIRS = [
    ("I", "I", ("sphere", (0, 0, 1), "1/4"), ((0, 0, 0), 1, 1), 15),
    # radius 1/4 <= 1/2, the radius of curvature of z = x^2 + y^2 at its vertex: touches from inside
    ("TI", "TI", ("sphere", (0, 0, "1/4"), "1/4"), ((0, 0, 0), 1, 1), 10),
    ("C", "C", ("sphere", ("1/2", 0, "1/4"), "3/10"), ((0, 0, 0), 1, 1), 15),
    ("TE", "TE", ("sphere", (0, 0, -1), 1), ((0, 0, 0), 1, 1), 10),
    ("E", "E", ("sphere", (0, 0, "-3/2"), "1/2"), ((0, 0, 0), 1, 1), 10),
    # The paper's example (README): z = x^2/1.2^2 + y^2/1.5^2, a special root of f, position I.
    ("paper-example", "I", ("sphere", (0, "0.5", "92281/129600"), "1/4"), ((0, 0, 0), "1.2", "1.5"), 12),
]

# (quadric type, expected position, ellipsoid (centre, radius), quadric constructor and arguments, view
# elevation), each position known by construction.
QUADRIC_PAIRS = [
    # the quadric's solid, x^2 + 4y^2 + 9z^2 <= 1, inside the ball of radius 2
    ("ellipsoid", "O", ((0, 0, 0), 2), ("ellipsoid", (0, 0, 0), (1, "1/2", "1/3")), 15),
    # x^2 + y^2 - z^2 <= 1: the unit ball touches the waist circle from inside
    ("hyperboloid of one sheet", "TI", ((0, 0, 0), 1), ("hyperboloid_one_sheet", (0, 0, 0), (1, 1, 1)), 10),
    # z^2 - x^2 - y^2 >= 1: the unit ball touches both vertices (0, 0, +-1) from between the sheets
    ("hyperboloid of two sheets", "TE", ((0, 0, 0), 1), ("hyperboloid_two_sheets", (0, 0, 0), (1, 1, 1)), 10),
    # x^2 + y^2 <= z^2: a ball of radius 1/2 < 2/sqrt(2) on the axis at height 2
    ("elliptic cone", "I", ((0, 0, 2), "1/2"), ("cone", (0, 0, 0), 1, 1), 15),
    # z >= x^2 + y^2: a ball below the vertex
    ("elliptic paraboloid", "E", ((0, 0, -1), "1/2"), ("elliptic_paraboloid", (0, 0, 0), 1, 1), 10),
    # the saddle through the ball's centre
    ("hyperbolic paraboloid", "C", ((0, 0, 0), "1/2"), ("hyperbolic_paraboloid", (0, 0, 0), 1, 1), 20),
    # the unit tube x^2 + y^2 <= 1 and a ball centred on its wall
    ("elliptic cylinder", "C", ((1, 0, 0), "1/2"), ("elliptic_cylinder", (0, 0, 0), 1, 1), 20),
    # the middle of x^2 - y^2 = 1 holds the ball of radius 1/2 at the centre
    ("hyperbolic cylinder", "I", ((0, 0, 0), "1/2"), ("hyperbolic_cylinder", (0, 0, 0), 1, 1), 20),
    # x^2 <= z: the unit ball below touches the vertex line from outside
    ("parabolic cylinder", "TE", ((0, 0, -1), 1), ("parabolic_cylinder", (0, 0, 0), 1), 10),
    # -1 <= z <= 1: the unit ball touches both planes from inside
    ("slab", "TI", ((0, 0, 0), 1), ("slab", (0, 0, 1), -1, 1), 10),
    # x + y + z <= 1/4: the plane cuts the ball of radius 1/2 at the origin
    ("half-space", "C", ((0, 0, 0), "1/2"), ("half_space", (1, 1, 1), "1/4"), 15),
]


def save(fig, ax, elev, path, plt):
    ax.view_init(elev=elev, azim=-60)
    ax.title.set_fontsize(10)
    fig.tight_layout()
    fig.savefig(path[0], dpi=path[1])
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (default: build)")
    ap.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    ap.add_argument("--dpi", type=int, default=80)
    args = ap.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import relpos

    os.makedirs(args.out, exist_ok=True)
    for name, expected, (_, centre, radius), (vertex, a, b), elev in PAIRS:
        e = relpos.Ellipsoid.sphere(centre, radius)
        p = relpos.Paraboloid.standard(vertex, a, b)
        c = relpos.classify(e, p)
        if c.position != expected:
            sys.exit("make-figures: %s classified %s, expected %s" % (name, c.position, expected))
        fig = plt.figure(figsize=(4.5, 4.5))
        ax = fig.add_subplot(projection="3d")
        title = "%s: %s" % (c.position, relpos.POSITION_MEANINGS[c.position])
        if name == "paper-example":
            title = "the paper's example: %s (%s)" % (c.position, relpos.POSITION_MEANINGS[c.position].split(":")[0])
        relpos.plot(e, p, ax=ax, classification=c, title=title)
        path = os.path.join(args.out, name + ".png")
        save(fig, ax, elev, (path, args.dpi), plt)
        print("%s: %s (%s; %d bytes)" % (path, c.position, c.stage, os.path.getsize(path)))
    for kind, expected, (centre, radius), (constructor, *arguments), elev in QUADRIC_PAIRS:
        e = relpos.Ellipsoid.sphere(centre, radius)
        q = getattr(relpos.Quadric, constructor)(*arguments)
        c = relpos.classify(e, q)
        if q.type != kind or c.position != expected:
            sys.exit("make-figures: %s classified %s (%s), expected %s" % (kind, c.position, q.type, expected))
        fig = plt.figure(figsize=(4.5, 4.5))
        ax = fig.add_subplot(projection="3d")
        relpos.plot(e, q, ax=ax, classification=c)
        path = os.path.join(args.out, "quadric-%s.png" % kind.replace(" ", "-"))
        save(fig, ax, elev, (path, args.dpi), plt)
        print("%s: %s (%s; %d bytes)" % (path, c.position, c.stage, os.path.getsize(path)))


if __name__ == "__main__":
    main()
