#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Every C++ snippet of README.md and doc/*.md is one of the example programs, verbatim: each
```cpp block must equal the whole text of a file in examples/cpp/, which CTest builds and runs
(tests/examples/check_cpp_example.sh). So no snippet in the documentation goes uncompiled.

    check_doc_snippets.py SOURCE_DIR
"""
import glob
import os
import re
import sys

root = sys.argv[1]
examples = {}
for path in sorted(glob.glob(os.path.join(root, "examples", "cpp", "*.cpp"))):
    with open(path) as f:
        examples[f.read()] = os.path.relpath(path, root)
docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "doc", "*.md")))
fence = re.compile(r"^```(\S*)[^\n]*\n(.*?)^```[ \t]*$", re.M | re.S)
checked, bad = 0, []
for doc in docs:
    with open(doc) as f:
        text = f.read()
    for m in fence.finditer(text):
        if m.group(1).lower() not in ("cpp", "c++", "cxx"):
            continue
        checked += 1
        line = text.count("\n", 0, m.start()) + 1
        if m.group(2) not in examples:
            bad.append("%s:%d: a ```cpp block that is not the text of a file in examples/cpp/"
                       % (os.path.relpath(doc, root), line))
for b in bad:
    print(b)
print("%d C++ snippets checked against %d examples" % (checked, len(examples)))
sys.exit(1 if bad or checked == 0 else 0)
