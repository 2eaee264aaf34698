#!/usr/bin/env python3
"""Hostile input for the relpos CLI (doc/testing.md): `relpos batch` must exit 0 and answer every input
line, in order, with the id preserved, an error message naming the problem or the expected position,
and no run may hang.

    check_hostile.py RELPOS_BINARY TESTS_HOSTILE_DIR

Runs the checked-in corpus (hostile.jsonl with hostile.expect, written by make_corpus.py) and inputs
generated here because they are large: 10^4-digit rationals, numbers beyond the 10000-character
limit, a 5 MB line, a million-element matrix, 100000 nested brackets, an empty file, a file without
a final newline, CR-only line ends, standard input. Then a few `relpos classify` error paths and
their exit codes.
"""
import json
import os
import random
import re
import subprocess
import sys
import tempfile

TIMEOUT = 120  # seconds per run; a hang fails the test
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run(args, stdin=None):
    # `timeout` kills a hung relpos; the Python timeout is a second line of defence.
    try:
        p = subprocess.run(["timeout", str(TIMEOUT)] + args, input=stdin, capture_output=True, timeout=TIMEOUT + 30)
    except subprocess.TimeoutExpired:
        return None
    return p


def input_lines(data):
    """The lines relpos sees: split at '\\n'; a last line without '\\n' counts."""
    if not data:
        return []
    parts = data.split(b"\n")
    if parts[-1] == b"":
        parts.pop()
    return parts


def check_batch(relpos, name, data, expect, use_stdin=False):
    """expect: one (id, kind, keyword) per input line."""
    lines = input_lines(data)
    if len(lines) != len(expect):
        raise SystemExit("test bug: %s has %d lines but %d expectations" % (name, len(lines), len(expect)))
    with tempfile.NamedTemporaryFile(suffix=".jsonl", delete=False) as f:
        f.write(data)
        path = f.name
    try:
        p = run([relpos, "batch", "-"], stdin=data) if use_stdin else run([relpos, "batch", path])
    finally:
        os.unlink(path)
    if p is None or p.returncode == 124:
        fail("%s: relpos batch did not finish within %d s" % (name, TIMEOUT))
        return
    if p.returncode != 0:
        fail("%s: exit code %d (stderr: %s)" % (name, p.returncode, p.stderr[:300]))
    out = p.stdout.decode("utf-8").split("\n")
    if out and out[-1] == "":
        out.pop()
    if len(out) != len(lines):
        fail("%s: %d input lines but %d output lines" % (name, len(lines), len(out)))
        return
    for n, (text, (want_id, kind, keyword)) in enumerate(zip(out, expect), start=1):
        where = "%s line %d" % (name, n)
        try:
            obj = json.loads(text)
        except ValueError as e:
            fail("%s: output is not JSON (%s): %s" % (where, e, text[:200]))
            continue
        if not isinstance(obj, dict) or "id" not in obj:
            fail("%s: output without id: %s" % (where, text[:200]))
            continue
        if obj["id"] != want_id:
            fail("%s: id %r, expected %r" % (where, obj["id"], want_id))
        if kind == "error":
            msg = obj.get("error")
            if not isinstance(msg, str) or keyword not in msg:
                fail("%s: expected an error containing %r, got %s" % (where, keyword, text[:300]))
        else:
            if obj.get("position") != keyword:
                fail("%s: expected position %r, got %s" % (where, keyword, text[:300]))


def digits(rng, n):
    return str(rng.randrange(1, 10)) + "".join(rng.choice("0123456789") for _ in range(n - 1))


def main():
    relpos, here = sys.argv[1], sys.argv[2]
    rng = random.Random(20240611)

    # 1. The checked-in corpus.
    with open(os.path.join(here, "hostile.jsonl"), "rb") as f:
        data = f.read()
    expect = []
    with open(os.path.join(here, "hostile.expect"), encoding="utf-8") as f:
        for row in f.read().split("\n"):
            if row:
                id_text, kind, keyword = row.split("\t")
                expect.append((json.loads(id_text), kind, keyword))
    check_batch(relpos, "hostile.jsonl", data, expect)
    check_batch(relpos, "hostile.jsonl on stdin", data, expect, use_stdin=True)

    # 2. Generated inputs.
    sphere = lambda r: '{"sphere": {"center": [0, 0, 1], "radius": %s}}' % r
    para = '{"vertex": [0, 0, 0], "a": 1, "b": 2}'
    pair = lambda i, e, p=para: '{"id": "%s", "ellipsoid": %s, "paraboloid": %s}' % (i, e, p)
    ten4 = "1" + "0" * 4998  # "ten4/(4 ten4)" has 9999 characters
    big = digits(rng, 9998)
    gen = [
        # A 10^4-character rational that reduces to 1/4: accepted, classified.
        (pair("rational-1e4-chars", sphere('"%s/%s"' % (ten4, "4" + "0" * 4998))), "rational-1e4-chars", "position", "I"),
        # A 10^4-digit rational that does not reduce: accepted by the parser, refused by the size limit.
        (pair("rational-1e4-digits", sphere('"1/%s"' % big)), "rational-1e4-digits", "error", "numbers too large"),
        (pair("integer-1e4-digits-json", '{"sphere": {"center": [0, 0, %s], "radius": 1}}' % digits(rng, 9999)),
         "integer-1e4-digits-json", "error", "numbers too large"),
        # One character over the limit, as a string and as a JSON number.
        (pair("over-limit-string", sphere('"0.%s"' % ("0" * 9998 + "1"))), "over-limit-string", "error",
         "longer than the 10000-character limit"),
        (pair("over-limit-json", sphere("0.%s" % ("0" * 9998 + "1"))), "over-limit-json", "error",
         "longer than the 10000-character limit"),
        (pair("over-limit-fraction", sphere('"%s/%s"' % (digits(rng, 5000), digits(rng, 5001)))), "over-limit-fraction",
         "error", "longer than the 10000-character limit"),
        # 10^4 decimal places that reduce to something small: fine.
        (pair("decimal-1e4-places", sphere('"0.25%s"' % ("0" * 9990))), "decimal-1e4-places", "position", "I"),
        # Exponents at and beyond the parser's limits (e - digits after the point within [-14000, 4000]):
        # accepted numbers this large or small then exceed the pair limit.
        (pair("exponent-4000", sphere('"25e-4002"')), "exponent-4000", "error", "numbers too large"),
        (pair("exponent-plus-4000", sphere('"1e4000"')), "exponent-plus-4000", "error", "numbers too large"),
        (pair("exponent-plus-4001", sphere('"1e4001"')), "exponent-plus-4001", "error", "beyond the supported range"),
        # Each matrix rescaled on its own by 10^1000 and 10^-1000: its primitive form is small, so the
        # pair is classified (the sphere of "e300" on the axis of z = x^2 + y^2/4: I); a sphere whose
        # own matrix is large is still refused (above).
        ('{"id": "rescaled-1e1000", "ellipsoid": {"matrix": [[1e1000, 0, 0, 0], [0, 1e1000, 0, 0], '
         '[0, 0, 1e1000, -1e1000], [0, 0, -1e1000, 9.375e999]]}, "paraboloid": {"matrix": [[1e-1000, 0, 0, 0], '
         '[0, 2.5e-1001, 0, 0], [0, 0, 0, -5e-1001], [0, 0, -5e-1001, 0]]}}', "rescaled-1e1000", "position", "I"),
        (pair("exponent-minus-14001", sphere('"1e-14001"')), "exponent-minus-14001", "error",
         "beyond the supported range"),
        # Very long lines.
        ('{"id": "long-comment", "comment": "%s", "ellipsoid": %s, "paraboloid": %s}' % ("x" * 5000000, sphere('"1/4"'), para),
         "long-comment", "position", "I"),
        ('{"id": "million-row", "ellipsoid": {"matrix": [[%s]]}, "paraboloid": %s}' % (",".join(["0"] * 1000000), para),
         "million-row", "error", "4x4"),
        ("[" * 100000, None, "error", "nested deeper than 256"),
        ('{"id": "deep-id", "id2": %s}' % ("[" * 100000 + "]" * 100000), None, "error", "nested deeper than 256"),
        ("x" * 3000000, None, "error", "invalid JSON"),
    ]
    data = b""
    expect = []
    for n, (text, id_, kind, kw) in enumerate(gen, start=1):
        data += text.encode() + b"\n"
        expect.append((n if id_ is None else id_, kind, kw))
    check_batch(relpos, "generated", data, expect)

    ok = pair("ok", sphere('"1/4"'))
    check_batch(relpos, "empty file", b"", [])
    check_batch(relpos, "one newline", b"\n", [(1, "error", "empty line")])
    check_batch(relpos, "no final newline", (ok + "\n" + ok).encode(), [("ok", "position", "I")] * 2)
    check_batch(relpos, "CR-only line ends", (ok + "\r" + ok + "\r").encode(), [(1, "error", "invalid JSON")])
    check_batch(relpos, "CRLF file", (ok + "\r\n\r\n" + ok + "\r\n").encode(),
                [("ok", "position", "I"), (2, "error", "empty line"), ("ok", "position", "I")])
    check_batch(relpos, "truncated final line", (ok + "\n" + ok[:-17]).encode(),
                [("ok", "position", "I"), (2, "error", "invalid JSON")])

    # 3. `relpos classify`: exit codes and messages (doc/cli.md, Exit codes).
    def classify(args, code, keyword):
        p = run([relpos] + args)
        if p is None or p.returncode != code or keyword.encode() not in p.stderr:
            fail("relpos %s: expected exit %d and %r on stderr, got %s" %
                 (" ".join(a[:40] for a in args), code, keyword, None if p is None else (p.returncode, p.stderr[:300])))

    classify(["classify", "--ellipsoid", "{", "--paraboloid", para], 1, "invalid JSON")
    classify(["classify", "--sphere", "0,0,1,NaN", "--standard-paraboloid", "1,2"], 1, "not finite")
    classify(["classify", "--sphere", "0,0,1", "--standard-paraboloid", "1,2"], 1, "expected 4 comma-separated")
    classify(["classify", "--sphere", "0,0,1,1/%s" % big[:3000], "--standard-paraboloid", "1,2"], 1, "numbers too large")
    classify(["classify", "--ellipsoid", '{"coefficients": [1,1,-1,0,0,0,0,0,0,-1]}', "--standard-paraboloid", "1,2"],
             1, "hyperboloid of one sheet")
    classify(["classify", "--sphere", "0,0,1,1"], 2, "missing the paraboloid")
    classify(["classify", "--sphere", "0,0,1,1", "--standard-paraboloid", "1,2", "--digits", "0"], 2, "--digits")
    classify(["batch", "/nonexistent/relpos-hostile.jsonl"], 3, "cannot open")
    # The pair size limit raised with --max-bits (never lowered): a 4661-bit sphere is refused by
    # default and answered with the limit raised, by classify (contact only too), batch and scene.
    wide = "0,1/%s,1,1/4" % ("7" * 700 + "1")
    classify(["classify", "--sphere", wide, "--standard-paraboloid", "1,1"], 1, "beyond the limit of 4096 bits")
    classify(["classify", "--sphere", wide, "--standard-paraboloid", "1,1", "--contact-only"], 1, "numbers too large")
    classify(["classify", "--sphere", wide, "--standard-paraboloid", "1,1", "--max-bits", "4095"], 2, "--max-bits")
    for extra in ([], ["--contact-only"]):
        p = run([relpos, "classify", "--sphere", wide, "--standard-paraboloid", "1,1", "--max-bits", "5000", "--json"]
                + extra)
        if p is None or p.returncode != 0 or json.loads(p.stdout.decode()).get("position") != "I":
            fail("relpos classify --max-bits 5000 %s: expected position I, got %s" % (extra, p and p.stdout[:200]))
    line = ('{"id": 1, "ellipsoid": {"sphere": {"center": [0, "1/%s", 1], "radius": "1/4"}}}' % ("7" * 700 + "1"))
    for cmd, data in ((["batch"], line[:-1] + ', "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}'),
                      (["scene", "--standard-paraboloid", "1,1", "--no-progress"], line)):
        for limit, want in (([], b"numbers too large"), (["--max-bits", "5000"], b'"position":"I"')):
            p = run([relpos] + cmd + ["-"] + limit, stdin=(data + "\n").encode())
            if p is None or p.returncode != 0 or want not in p.stdout:
                fail("relpos %s %s: expected %r, got %s" % (cmd[0], limit, want, p and p.stdout[:200]))
    # The same limit for a general pair (classify --quadric, a batch line with "quadric", scene
    # --quadric), at the limit: the pair's N bits, from the error, are answered with --max-bits N and
    # refused with N - 1, the error naming N - 1.
    ring = '{"type": "hyperboloid of one sheet", "center": [0, 0, 0], "axes": [10, 10, 10]}'
    p = run([relpos, "classify", "--sphere", wide, "--quadric", ring])
    message = p.stderr.decode() if p is not None else ""
    m = re.search(r"has (\d+)-bit entries, beyond the limit of 4096 bits", message)
    if p is None or p.returncode != 1 or not m:
        fail("relpos classify --quadric with a 4661-bit sphere: expected the size error, got %r" % message[:200])
    else:
        bits = int(m.group(1))
        # (answered with the verdict alone: the full evidence of so large a general pair takes seconds)
        p = run([relpos, "classify", "--sphere", wide, "--quadric", ring, "--max-bits", str(bits), "--json",
                 "--contact-only"])
        if p is None or p.returncode != 0 or json.loads(p.stdout.decode()).get("position") != "I":
            fail("relpos classify --quadric --max-bits %d: expected position I, got %s" % (bits, p and p.stdout[:200]))
        for extra in ([], ["--contact-only"]):
            p = run([relpos, "classify", "--sphere", wide, "--quadric", ring, "--max-bits", str(bits - 1)] + extra)
            if p is None or p.returncode != 1 or ("beyond the limit of %d bits" % (bits - 1)) not in p.stderr.decode():
                fail("relpos classify --quadric --max-bits %d %s: expected the size error naming the limit, got %s"
                     % (bits - 1, extra, p and p.stderr[:200]))
        for cmd, data in ((["batch"], line[:-1] + ', "quadric": %s}' % ring),
                          (["scene", "--quadric", ring, "--no-progress"], line)):
            for limit, want in (([], b"beyond the limit of 4096 bits"), (["--max-bits", str(bits)], b'"position":"I"'),
                                (["--max-bits", str(bits - 1)], b"beyond the limit of %d bits" % (bits - 1))):
                minimal = ["--evidence", "minimal"] if cmd[0] == "batch" else []
                p = run([relpos] + cmd + ["-"] + minimal + limit, stdin=(data + "\n").encode())
                if p is None or p.returncode != 0 or want not in p.stdout:
                    fail("relpos %s (quadric) %s: expected %r, got %s" % (cmd[0], limit, want, p and p.stdout[:200]))
    p = run([relpos, "classify", "--sphere", "0,0,1,x", "--standard-paraboloid", "1,2", "--json"])
    if p is None or p.returncode != 1 or "error" not in json.loads(p.stdout.decode() or "{}"):
        fail("relpos classify --json with a bad number: expected exit 1 and {\"error\": ...} on stdout")

    if failures:
        print("hostile input: %d failures" % len(failures))
        return 1
    print("hostile input: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
