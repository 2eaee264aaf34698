#!/usr/bin/env python3
"""The adapter of doc/oracle.md's walkthrough: `relpos cases` lines on standard input, one answer
{"id": ..., "position": ...} per case on standard output, from the float code in paper_rule.py.

    relpos cases all --n 50 > cases.jsonl
    python3 examples/oracle/adapter.py < cases.jsonl > answers.jsonl
    relpos judge cases.jsonl answers.jsonl --plot errors.png
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_rule import position  # noqa: E402  (the float code under test)

for line in sys.stdin:
    case = json.loads(line)
    d = case["meta"]["double"]  # the doubles a float code holds (JSON numbers: exact round trip)
    e, p = d["ellipsoid"], d["paraboloid"]
    try:
        answer = position(e["center"], e["axes"], e["rotation"], p["vertex"], p["a"], p["b"], p["rotation"])
    except (ArithmeticError, ValueError):
        answer = None  # undecided
    print(json.dumps({"id": case["id"], "position": answer}))
