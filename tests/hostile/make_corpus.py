#!/usr/bin/env python3
"""Writes tests/hostile/hostile.jsonl and hostile.expect (checked in; rerun after editing CASES).

hostile.expect has one line per input line: <expected id as JSON> TAB <"error" or "position"> TAB
<keyword>. An error line must carry an error message containing the keyword; a position line must be
classified with that position. Lines that cannot be read as a JSON object get their line number as id.
"""
import json
import os

SPHERE = '{"sphere": {"center": [0, 0, 1], "radius": "1/4"}}'
PARA = '{"vertex": [0, 0, 0], "a": 1, "b": 2}'
OK = '"ellipsoid": ' + SPHERE + ', "paraboloid": ' + PARA


def pair(e=SPHERE, p=PARA):
    return '"ellipsoid": ' + e + ', "paraboloid": ' + p


def line(id_, body):
    return '{"id": ' + json.dumps(id_) + ', ' + body + '}'


def matrix(rows):
    return json.dumps({"matrix": rows})


def coeffs(c):
    return json.dumps({"coefficients": c})


# Every quadric type that is not an ellipsoid / elliptic paraboloid, as 10 coefficients
# A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J, with the name the error must give.
WRONG = [
    ("hyperboloid of one sheet", [1, 1, -1, 0, 0, 0, 0, 0, 0, -1]),
    ("hyperboloid of two sheets", [1, 1, -1, 0, 0, 0, 0, 0, 0, 1]),
    ("cone", [1, 1, -1, 0, 0, 0, 0, 0, 0, 0]),
    ("elliptic cylinder", [1, 2, 0, 0, 0, 0, 0, 0, 0, -1]),
    ("hyperbolic cylinder", [1, -1, 0, 0, 0, 0, 0, 0, 0, -1]),
    ("parabolic cylinder", [1, 0, 0, 0, 0, 0, 0, 0, -1, 0]),
    ("imaginary ellipsoid", [1, 1, 1, 0, 0, 0, 0, 0, 0, 1]),
    ("point", [1, 1, 1, 0, 0, 0, 0, 0, 0, 0]),
    ("hyperbolic paraboloid", [1, -1, 0, 0, 0, 0, 0, 0, -1, 0]),
    ("imaginary elliptic cylinder", [1, 1, 0, 0, 0, 0, 0, 0, 0, 1]),
    ("line", [1, 1, 0, 0, 0, 0, 0, 0, 0, 0]),
    ("intersecting planes", [1, -1, 0, 0, 0, 0, 0, 0, 0, 0]),
    ("parallel planes", [1, 0, 0, 0, 0, 0, 0, 0, 0, -1]),
    ("imaginary parallel planes", [1, 0, 0, 0, 0, 0, 0, 0, 0, 1]),
    ("double plane", [1, 0, 0, 0, 0, 0, 0, 0, 0, 0]),
    ("plane", [0, 0, 0, 0, 0, 0, 0, 0, 1, 0]),
    ("without quadratic terms", [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]),
]

# (bytes of the line without its end, expected id (None: the line number), kind, keyword)
CASES = []


def add(raw, id_, kind, keyword, end=b"\n"):
    CASES.append((raw.encode("utf-8", "surrogateescape") if isinstance(raw, str) else raw, id_, kind, keyword, end))


# --- truncated and malformed JSON
add(line("t1", OK)[:-30], None, "error", "invalid JSON")
add('{"id": "t2",', None, "error", "invalid JSON")
add("{", None, "error", "invalid JSON")
add("}", None, "error", "invalid JSON")
add('{"id": "t3", ' + OK + '} trailing', None, "error", "invalid JSON")
add(line("t4", OK) + line("t5", OK), None, "error", "invalid JSON")
add('{"id": "t6" "ellipsoid": 1}', None, "error", "invalid JSON")
add("{'id': 'single-quotes'}", None, "error", "invalid JSON")
add('{"id": "t7", ' + OK + ',}', None, "error", "invalid JSON")
add('"just a string"', None, "error", "expected a JSON object")
add("42", None, "error", "expected a JSON object")
add("null", None, "error", "expected a JSON object")
add("[]", None, "error", "expected a JSON object")
add("[" * 300 + "]" * 300, None, "error", "nested deeper than 256")
add("{}", None, "error", "ellipsoid: missing")
add('{"id": "only-id"}', "only-id", "error", "ellipsoid: missing")
add(line("no-paraboloid", '"ellipsoid": ' + SPHERE), "no-paraboloid", "error", "paraboloid: missing")
add(line("typo-key", OK + ', "paraboloidd": 1'), "typo-key", "error", 'unknown key "paraboloidd"')
# --- binary garbage, encodings
add(b"\x00\x01\x02\xff\xfe\xfd\x80\x81garbage\x00", None, "error", "NUL byte at column 1")
add(b"\xde\xad\xbe\xef" * 16, None, "error", "invalid JSON")
add(b'{"id": "\xff\xfe", ' + OK.encode() + b"}", None, "error", "invalid JSON")
add(b'{"id": "nul\x00inside", ' + OK.encode() + b"}", None, "error", "NUL byte at column 12")
add('{"id": "\\ud800", ' + OK + '}', None, "error", "invalid JSON")
add(b"\xef\xbb\xbf" + line("bom", OK).encode(), None, "error", "byte order mark is accepted only at the start")  # not line 1
add(line("escaped-newline\nin-id", OK), "escaped-newline\nin-id", "position", "I")
add(line("unicode-\u00e9\u4e2d", OK), "unicode-\u00e9\u4e2d", "position", "I")
# --- NaN / Inf as bare tokens and as strings
for tok in ["NaN", "Infinity", "-Infinity", "nan", "inf"]:
    add(line("bare-" + tok, pair('{"sphere": {"center": [0, 0, 1], "radius": ' + tok + '}}')), None, "error",
        "invalid JSON")
for s in ["NaN", "nan", "Infinity", "-Infinity", "+inf", "-inf", "INF", "inf"]:
    add(line("string-" + s, pair('{"sphere": {"center": [0, 0, 1], "radius": "' + s + '"}}')), "string-" + s, "error",
        "not finite")
# --- other bad numbers
bad = [("true", "expected a number, got true"), ("null", "expected a number, got null"),
       ('"1/0"', "zero denominator"), ('"1.2.3"', "unexpected character"), ('""', "empty"),
       ('"0x10"', "unexpected character"), ('"1,5"', "unexpected character"), ('"1e"', "missing exponent digits"),
       ('"1e4001"', "beyond the supported range"), ('"1e-99999999"', "exponent out of range"),
       ('"--1"', "unexpected character"), ('"1/2/3"', "a fraction needs integers"), ('[1]', "expected a number"),
       ('{"x": 1}', "expected a number")]
for i, (tok, kw) in enumerate(bad):
    add(line("bad-number-%d" % i, pair('{"sphere": {"center": [0, ' + tok + ', 1], "radius": "1/4"}}')),
        "bad-number-%d" % i, "error", kw)
add(line("radius-zero", pair('{"sphere": {"center": [0, 0, 1], "radius": 0}}')), "radius-zero", "error",
    "radius must be positive")
add(line("a-zero", pair(SPHERE, '{"vertex": [0, 0, 0], "a": "-0", "b": 2}')), "a-zero", "error", "must be positive")
# --- extreme but valid numbers
add(line("e300", pair('{"sphere": {"center": [0, 0, 1e300], "radius": 1e-300}}')), "e300", "position", "I")
add(line("e-300-pair", pair('{"sphere": {"center": [0, 0, 1e-300], "radius": 2.5e-301}}',
                            '{"vertex": [0, 0, 0], "a": 1e-150, "b": 2e-150}')), "e-300-pair", "position", "I")
add(line("e400-json-number", pair('{"sphere": {"center": [0, 0, 1e400], "radius": "1/4"}}')), "e400-json-number",
    "position", "I")
add(line("e2000-json-number", pair('{"sphere": {"center": [0, 0, 1e2000], "radius": "1/4"}}')), "e2000-json-number",
    "error", "numbers too large")
add(line("double-extremes", pair('{"sphere": {"center": [0, 0, 1e300], "radius": 4.9406564584124654e-324}}')),
    "double-extremes", "error", "numbers too large")
add(line("subnormal", pair('{"sphere": {"center": [0, 0, 1], "radius": 4.9406564584124654e-324}}')), "subnormal",
    "position", "I")
add(line("subnormal-string", pair('{"sphere": {"center": [0, 0, "1"], "radius": "5e-324"}}')), "subnormal-string",
    "position", "I")
add(line("max-double", pair('{"sphere": {"center": [0, 0, 1.7976931348623157e308], "radius": "1/4"}}')),
    "max-double", "position", "I")
add(line("max-double-alone", pair('{"sphere": {"center": [0, 0, 1.7976931348623157e308], "radius": 8.98846567431158e307}}')),
    "max-double-alone", "position", "C")
# --- wrong shapes
add(line("matrix-3x3", pair(matrix([[1, 0, 0], [0, 1, 0], [0, 0, 1]]))), "matrix-3x3", "error", "4x4")
add(line("matrix-4x5", pair(matrix([[1, 0, 0, 0, 0], [0, 1, 0, 0, 0], [0, 0, 1, 0, 0], [0, 0, 0, -1, 0]]))),
    "matrix-4x5", "error", "a row of 4 numbers")
add(line("matrix-ragged", pair(matrix([[1, 0, 0, 0], [0, 1, 0], [0, 0, 1, 0], [0, 0, 0, -1]]))), "matrix-ragged",
    "error", "ellipsoid.matrix[1]: expected a row of 4 numbers")
add(line("matrix-5x4", pair(matrix([[1, 0, 0, 0]] * 5))), "matrix-5x4", "error", "4x4")
add(line("matrix-empty", pair(matrix([]))), "matrix-empty", "error", "4x4")
add(line("matrix-object", pair('{"matrix": {"a": 1}}')), "matrix-object", "error", "4x4")
add(line("coefficients-9", pair(coeffs([1] * 9))), "coefficients-9", "error", "10 coefficients")
add(line("coefficients-11", pair(coeffs([1] * 11))), "coefficients-11", "error", "10 coefficients")
add(line("center-2", pair('{"sphere": {"center": [0, 1], "radius": 1}}')), "center-2", "error", "3 numbers")
add(line("axes-4", pair('{"center": [0, 0, 1], "axes": [1, 1, 1, 1]}')), "axes-4", "error", "3 numbers")
add(line("quaternion-3", pair('{"center": [0, 0, 1], "axes": [1, 1, 1], "rotation": [1, 0, 0]}')), "quaternion-3",
    "error", "quaternion")
add(line("rotation-matrix-3x2", pair('{"center": [0, 0, 1], "axes": [1, 1, 1], "rotation_matrix": [[1, 0], [0, 1], [0, 0]]}')),
    "rotation-matrix-3x2", "error", "a row of 3 numbers")
add(line("map-2x3", pair(SPHERE, '{"map": [[1, 0, 0], [0, 1, 0]], "translation": [0, 0, 0]}')), "map-2x3", "error",
    "3x3")
add(line("quadric-string", pair('"sphere"')), "quadric-string", "error", "expected a 4x4 array or an object")
add(line("quadric-number", pair(SPHERE, "7")), "quadric-number", "error", "expected a 4x4 array or an object")
add(line("no-form", pair('{"radius": 1}')), "no-form", "error", "no recognized ellipsoid form")
add(line("both-rotations", pair('{"center": [0, 0, 1], "axes": [1, 1, 1], "rotation": [1, 0, 0, 0], "rotation_matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}')),
    "both-rotations", "error", "not both")
add(line("not-symmetric", pair(matrix([[1, 2, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]))),
    "not-symmetric", "error", "not symmetric")
add(line("singular-map", pair('{"center": [0, 0, 1], "map": [[1, 0, 0], [0, 1, 0], [0, 0, 0]]}')), "singular-map",
    "error", "singular")
add(line("zero-quaternion", pair('{"center": [0, 0, 1], "axes": [1, 1, 1], "rotation": [0, 0, 0, 0]}')),
    "zero-quaternion", "error", "quaternion is zero")
add(line("not-orthogonal", pair('{"center": [0, 0, 1], "axes": [1, 1, 1], "rotation_matrix": [[1, 1, 0], [0, 1, 0], [0, 0, 1]]}')),
    "not-orthogonal", "error", "orthogonal")
# --- every wrong quadric type, as ellipsoid and as paraboloid; and the two roles swapped
for name, c in WRONG:
    add(line("ellipsoid-" + name, pair(coeffs(c))), "ellipsoid-" + name, "error", "ellipsoid: not an ellipsoid: the matrix describes")
    add(line("paraboloid-" + name, pair(SPHERE, coeffs(c))), "paraboloid-" + name, "error",
        "paraboloid: not an elliptic paraboloid: the matrix describes")
    CASES[-2] = CASES[-2][:3] + (name,) + CASES[-2][4:]
    CASES[-1] = CASES[-1][:3] + (name,) + CASES[-1][4:]
add(line("ellipsoid-is-paraboloid", pair(coeffs([1, 1, 0, 0, 0, 0, 0, 0, -1, 0]))), "ellipsoid-is-paraboloid", "error",
    "elliptic paraboloid")
add(line("paraboloid-is-ellipsoid", pair(SPHERE, SPHERE)), "paraboloid-is-ellipsoid", "error",
    "no recognized paraboloid form")
add(line("paraboloid-is-ellipsoid-coefficients", pair(SPHERE, coeffs([1, 1, 1, 0, 0, 0, 0, 0, 0, -1]))),
    "paraboloid-is-ellipsoid-coefficients", "error", "describes an ellipsoid")
# --- empty lines, CRLF, ids
add("", None, "error", "empty line")
add("   \t  ", None, "error", "empty line")
add(line("crlf", OK), "crlf", "position", "I", end=b"\r\n")
add("", None, "error", "empty line", end=b"\r\n")
add(line("id-null", OK).replace('"id": "id-null"', '"id": null'), None, "position", "I")
add(line("x", OK).replace('"id": "x"', '"id": [1, {"a": [2]}]'), [1, {"a": [2]}], "position", "I")
add(line("x", OK).replace('"id": "x"', '"id": 0.1'), 0.1, "position", "I")
add(line("x", OK).replace('"id": "x"', '"id": -7'), -7, "position", "I")
add(line("dup", OK + ', "comment": 1, "comment": 2'), "dup", "error", "duplicate key")
add(line("after-all-that", OK), "after-all-that", "position", "I")

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "hostile.jsonl"), "wb") as out, open(os.path.join(here, "hostile.expect"), "w") as exp:
    for n, (raw, id_, kind, kw, end) in enumerate(CASES, start=1):
        out.write(raw + end)
        exp.write(json.dumps(n if id_ is None and kind == "error" else id_) + "\t" + kind + "\t" + kw + "\n")
