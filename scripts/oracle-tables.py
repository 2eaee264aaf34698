#!/usr/bin/env python3
"""The tables and the chart of doc/oracle.md's walkthrough, regenerated: `relpos cases`, the adapter
of examples/oracle around the paper's rule in doubles, `relpos judge`.

  scripts/oracle-tables.py RELPOS_CLI                 # print the tables
  scripts/oracle-tables.py RELPOS_CLI --write         # put them into doc/oracle.md, the chart into
                                                      # doc/figures/oracle-chart.png (relpos writes
                                                      # stored deflate blocks; the repository's copy
                                                      # is the same image recompressed by zlib)
  scripts/oracle-tables.py RELPOS_CLI --check         # fail unless doc/oracle.md holds these tables
                                                      # and doc/figures/oracle-chart.png this chart's
                                                      # pixels (CTest doc_oracle)

The commands are the walkthrough's (CASES below), seed 1: the same build gives the same bytes.
"""
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "doc", "oracle.md")
CHART = os.path.join(ROOT, "doc", "figures", "oracle-chart.png")
CASES = ["cases", "offaxis", "rotated", "special", "circular", "tiny", "huge", "far", "exact", "--n", "40",
         "--eps", "1e-2,1e-6,1e-10,0"]
BEGIN, END = "<!-- oracle-tables:begin -->", "<!-- oracle-tables:end -->"


def tables(cli, chart=None):
    with tempfile.TemporaryDirectory() as tmp:
        cases = os.path.join(tmp, "cases.jsonl")
        answers = os.path.join(tmp, "answers.jsonl")
        with open(cases, "w") as f:
            subprocess.run([cli] + CASES, stdout=f, check=True)
        with open(cases) as i, open(answers, "w") as o:
            subprocess.run([sys.executable, os.path.join(ROOT, "examples", "oracle", "adapter.py")], stdin=i,
                           stdout=o, check=True)
        out = []
        for truth in ("exact", "double"):
            args = [cli, "judge", cases, answers, "--truth", truth, "--misses", "2"]
            if truth == "exact" and chart:
                args += ["--plot", chart]
            out.append("$ relpos judge cases.jsonl answers.jsonl --truth %s --misses 2\n" % truth)
            out.append(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
        return "```\n" + "\n".join(out).rstrip("\n") + "\n```\n"


def chunks_of(png):
    """The chunks other than IDAT, and the inflated image data."""
    chunks, at, data = [], 8, b""
    while at < len(png):
        (n,) = struct.unpack(">I", png[at:at + 4])
        kind, body = png[at + 4:at + 8], png[at + 8:at + 8 + n]
        if kind == b"IDAT":
            data += body
        else:
            chunks.append((kind, body))
        at += 12 + n
    return chunks, zlib.decompress(data)


def recompressed(png):
    """The same PNG with its image data deflated by zlib (chunks re-checksummed)."""
    chunks, data = chunks_of(png)
    chunks.insert(2, (b"IDAT", zlib.compress(data, 9)))  # after IHDR and PLTE
    out = png[:8]
    for kind, body in chunks:
        out += struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli, mode = sys.argv[1], (sys.argv[2] if len(sys.argv) > 2 else "")
    fresh = tempfile.NamedTemporaryFile(suffix=".png", delete=False).name
    text = tables(cli, CHART if mode == "--write" else fresh)
    if not mode:
        sys.stdout.write(text)
        return 0
    doc = open(DOC, encoding="utf-8").read()
    begin, end = doc.index(BEGIN) + len(BEGIN) + 1, doc.index(END)
    if mode == "--write":
        open(DOC, "w", encoding="utf-8").write(doc[:begin] + text + doc[end:])
        with open(CHART, "rb") as f:
            png = recompressed(f.read())
        with open(CHART, "wb") as f:
            f.write(png)
        return 0
    if doc[begin:end] != text:
        print("doc/oracle.md: the walkthrough's tables differ from scripts/oracle-tables.py's output:")
        print(text)
        return 1
    with open(fresh, "rb") as f, open(CHART, "rb") as g:
        same = chunks_of(f.read()) == chunks_of(g.read())
    os.unlink(fresh)
    if not same:
        print("doc/figures/oracle-chart.png: not the chart of this run (scripts/oracle-tables.py --write)")
        return 1
    print("doc/oracle.md: the walkthrough's tables and chart are the script's output")
    return 0


if __name__ == "__main__":
    sys.exit(main())
