#!/usr/bin/env python3
"""General pairs through the CLI (doc/testing.md, `cli_general`): `relpos batch` (full and minimal
evidence) on the lines of tests/general_cases_jsonl.cpp gives every pair the position of its
construction or of the independent oracle, `relpos verify` checks every certificate (and refuses
tampered ones), `relpos classify --quadric` answers a geometric form as the batch does, and `relpos
scene --quadric` gives the constructed pairs that share a quadric their positions.

Usage: check_general.py RELPOS GENERATOR [RANDOM [SEED [MAPS]]]
(the self-check at scale, doc/testing.md: RANDOM 10000 and MAPS 8 under a few seeds)
"""
import json
from fractions import Fraction
import subprocess
import sys
import tempfile
from pathlib import Path


def main() -> int:
    relpos, generator = sys.argv[1], sys.argv[2]
    random = sys.argv[3] if len(sys.argv) > 3 else "300"
    more = sys.argv[4:6]  # the generator's SEED and MAPS
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        cases = Path(tmp) / "general.jsonl"
        cases.write_text(subprocess.run([generator, random] + more, check=True, capture_output=True, text=True).stdout)
        lines = cases.read_text().splitlines()
        for evidence in ("full", "minimal"):
            out = subprocess.run([relpos, "batch", str(cases), "--evidence", evidence], check=True,
                                 capture_output=True, text=True).stdout.splitlines()
            if len(out) != len(lines):
                failures.append(f"{evidence}: {len(out)} answers for {len(lines)} lines")
                continue
            for given, answer in zip(lines, out):
                expect = json.loads(given)["comment"]["expect"]
                got = json.loads(answer)
                if got.get("position") != expect:
                    failures.append(f"{evidence}, line {got.get('id')}: {got.get('position', got.get('error'))}, "
                                    f"expected {expect} ({json.loads(given)['comment']['source']})")
            if evidence == "full":
                answers = Path(tmp) / "answers.jsonl"
                answers.write_text("\n".join(out) + "\n")
                v = subprocess.run([relpos, "verify", str(cases), str(answers)], capture_output=True, text=True)
                if v.returncode != 0 or not v.stdout.startswith(f"verified {len(lines)}, failed 0"):
                    failures.append("verify: " + v.stdout.strip()[-400:])
                # Tampered: every multiplier negated, every ratio doubled, crossing points swapped, a
                # contact set's radius changed -> every line fails.
                tampered = []
                for a in out:
                    j = json.loads(a)
                    c = j.get("certificate")
                    if isinstance(c, dict) and isinstance(c.get("t"), str):
                        c["t"] = c["t"][1:] if c["t"].startswith("-") else "-" + c["t"]
                    elif isinstance(c, dict) and "ratio" in c:
                        c["ratio"] = str(2 * Fraction(c["ratio"]))
                    elif isinstance(c, dict) and "inside" in c:
                        c["inside"], c["outside"] = c["outside"], c["inside"]
                    elif isinstance(c, dict) and "contact_set" in c:
                        c["contact_set"]["radius2"]["a"] = "-1"
                    tampered.append(json.dumps(j))
                bad = Path(tmp) / "tampered.jsonl"
                bad.write_text("\n".join(tampered) + "\n")
                v = subprocess.run([relpos, "verify", str(cases), str(bad), "--quiet"], capture_output=True, text=True)
                if v.returncode != 1 or not v.stdout.startswith(f"verified 0, failed {len(lines)}"):
                    failures.append("tampered certificates: " + v.stdout.strip())
        # classify --quadric with a geometric form, against the batch answer of the same pair.
        form = '{"type": "hyperboloid of one sheet", "center": [0,0,0], "axes": [1,1,1]}'
        c = subprocess.run([relpos, "classify", "--sphere", "0,0,0,1", "--quadric", form, "--json"], check=True,
                           capture_output=True, text=True).stdout
        if json.loads(c)["position"] != "TI":
            failures.append("classify --quadric: " + c[:200])
        # "paraboloid" and "quadric" on one line, in either order, whether the paraboloid is read by
        # the fast reader (a matrix), by the general reader (an object) or is null: refused; a
        # duplicate key keeps its own error. Under both number modes (the fast reader's two paths).
        both = "a line takes \"paraboloid\" or \"quadric\", not both"
        e = json.loads(lines[0])["ellipsoid"]
        q = json.loads(lines[0])["quadric"]
        p = [["1", "0", "0", "0"], ["0", "1", "0", "0"], ["0", "0", "0", "-1/2"], ["0", "0", "-1/2", "5"]]
        mixed = [
            ([("paraboloid", p), ("quadric", q)], both),
            ([("quadric", q), ("paraboloid", p)], both),
            ([("paraboloid", {"matrix": p}), ("quadric", q)], both),
            ([("quadric", q), ("paraboloid", {"matrix": p})], both),
            ([("paraboloid", None), ("quadric", q)], both),
            ([("quadric", q), ("paraboloid", None)], both),
            ([("quadric", q), ("quadric", q)], "duplicate key \"quadric\""),
            ([("paraboloid", p), ("quadric", q), ("paraboloid", p)], "duplicate key \"paraboloid\""),
        ]
        text = ""
        for n, (members, _) in enumerate(mixed, 1):
            body = ",".join(f'"{k}":{json.dumps(v)}' for k, v in members)
            text += f'{{"id":{n},"ellipsoid":{json.dumps(e)},{body}}}\n'
        bad = Path(tmp) / "mixed.jsonl"
        bad.write_text(text)
        for numbers in ("exact", "double"):
            out = subprocess.run([relpos, "batch", str(bad), "--numbers", numbers], capture_output=True,
                                 text=True).stdout.splitlines()
            got = [json.loads(a).get("error") for a in out]
            want = [m for _, m in mixed]
            if got != want:
                failures.append(f"paraboloid and quadric (--numbers {numbers}): {got}, expected {want}")
        # An unknown key's message names the keys a line takes; a line with every one of them (the
        # "quadric" in place of the "paraboloid") is answered, so the list is the reader's own.
        typo = f'{{"id":1,"ellipsoid":{json.dumps(e)},"quadric":{json.dumps(q)},"colour":1}}\n'
        every = f'{{"id":2,"ellipsoid":{json.dumps(e)},"quadric":{json.dumps(q)},"meta":{{"k":1}},"comment":"c"}}\n'
        out = subprocess.run([relpos, "batch"], input=typo + every, capture_output=True, text=True).stdout.splitlines()
        named = 'unknown key "colour" (a line takes "id", "ellipsoid", "paraboloid" or "quadric", "meta" and "comment")'
        if len(out) != 2 or json.loads(out[0]).get("error") != named or "position" not in json.loads(out[1]):
            failures.append(f"the keys a line takes: {out}")
        # relpos scene --quadric: the lines that share a quadric (constructed ones, nudged tangencies)
        # form a scene; every body gets the position of its construction (on 2 threads: one run per
        # scene keeps the sanitizer build's time down; test_general_scene varies the threads), and the
        # summary counts them.
        groups = {}
        for given in lines:
            j = json.loads(given)
            groups.setdefault(json.dumps(j["quadric"]), []).append(j)
        scenes = 0
        for quadric, members in groups.items():
            if len(members) < 2:
                continue
            scenes += 1
            body = "".join(json.dumps({"id": m["id"], "ellipsoid": m["ellipsoid"]}) + "\n" for m in members)
            for threads in ("2",):
                run = subprocess.run([relpos, "scene", "--quadric", quadric, "--threads", threads, "--no-progress"],
                                     input=body, capture_output=True, text=True)
                got = [json.loads(a) for a in run.stdout.splitlines()]
                want = [m["comment"]["expect"] for m in members]
                if run.returncode != 0 or [g.get("position") for g in got] != want:
                    failures.append(f"scene --quadric {quadric[:60]}: {[g.get('position', g.get('error')) for g in got]}, "
                                    f"expected {want}")
                    continue
                summary = json.loads(run.stderr.splitlines()[-1])["summary"]
                if summary["bodies"] != len(members) or sum(summary["positions"].values()) != len(members):
                    failures.append(f"scene --quadric summary: {summary}")
        if scenes < 5:
            failures.append(f"only {scenes} scenes of constructed pairs")
        # A scene's quadric that cannot be read: exit 1 and the batch line's message.
        run = subprocess.run([relpos, "scene", "--quadric", "[[1,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,0]]"],
                             input="", capture_output=True, text=True)
        if run.returncode != 1 or not run.stderr.startswith("relpos: quadric: not a quadric solid"):
            failures.append(f"scene --quadric with a degenerate quadric: {run.returncode} {run.stderr[:200]}")
    for f in failures[:40]:
        print(f)
    print(f"{len(lines)} general lines, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
