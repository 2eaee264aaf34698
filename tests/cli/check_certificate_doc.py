#!/usr/bin/env python3
"""The worked examples of doc/certificates.md: every ```sh block `relpos classify ... --json` followed by
a ```json block is run and its position and certificate compared with that block; every ```python
block (the checks by hand) is run and must pass.

Usage: check_certificate_doc.py PATH/TO/relpos PATH/TO/doc/certificates.md
"""
import json
import re
import shlex
import subprocess
import sys

relpos, doc = sys.argv[1], sys.argv[2]
text = open(doc, encoding="utf-8").read()
blocks = re.findall(r"```(\w+)\n(.*?)```", text, flags=re.S)
failures, commands, scripts = [], 0, 0
for (lang, body), nxt in zip(blocks, blocks[1:] + [("", "")]):
    if lang == "sh" and body.startswith("relpos classify") and nxt[0] == "json":
        commands += 1
        argv = shlex.split(body.strip())
        run = subprocess.run([relpos] + argv[1:], capture_output=True, text=True, check=False)
        if run.returncode != 0:
            failures.append(f"{body.strip()}: exit {run.returncode}: {run.stderr.strip()}")
            continue
        got = json.loads(run.stdout)
        want = json.loads(nxt[1])
        for key, value in want.items():
            if got.get(key) != value:
                failures.append(f"{body.strip()}: {key} is {json.dumps(got.get(key))}, the doc says {json.dumps(value)}")
    elif lang == "python":
        scripts += 1
        run = subprocess.run([sys.executable, "-c", body], capture_output=True, text=True, check=False)
        if run.returncode != 0:
            failures.append(f"python block {scripts} failed:\n{run.stderr.strip()}")
for f in failures:
    print("FAIL " + f)
print(f"certificates.md: {commands} commands, {scripts} python blocks, {len(failures)} failures")
sys.exit(1 if failures or commands == 0 or scripts == 0 else 0)
