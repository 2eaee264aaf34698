#!/usr/bin/python3
"""Render doc/figures/{I,TI,C,TE,E}.png and doc/figures/paper-example.png with the built Python
package relpos (matplotlib, Agg backend). Each pair is classified by the library; the script stops
if a pair does not get the position its file is named after.

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
        ax.view_init(elev=elev, azim=-60)
        ax.title.set_fontsize(10)
        fig.tight_layout()
        path = os.path.join(args.out, name + ".png")
        fig.savefig(path, dpi=args.dpi)
        plt.close(fig)
        print("%s: %s (%s; %d bytes)" % (path, c.position, c.stage, os.path.getsize(path)))


if __name__ == "__main__":
    main()
