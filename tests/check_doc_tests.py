#!/usr/bin/python3
"""Every CTest test of the build is listed in doc/testing.md.

Usage: check_doc_tests.py CTEST BUILD_DIR doc/testing.md

Runs `CTEST -N` in BUILD_DIR, reads the test names from its "Test #n: NAME" lines and fails for
each name that doc/testing.md does not mention as a word (`name`, in a table or in text).
"""
import re
import subprocess
import sys


def listed_tests(ctest, build_dir):
    out = subprocess.run([ctest, "-N"], cwd=build_dir, capture_output=True, text=True, check=True).stdout
    return re.findall(r"^\s*Test\s+#\d+:\s+(\S+)\s*$", out, re.M)


def missing(names, doc_text):
    return [n for n in names if not re.search(r"(?<![\w-])" + re.escape(n) + r"(?![\w-])", doc_text)]


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: check_doc_tests.py CTEST BUILD_DIR doc/testing.md")
    ctest, build_dir, doc = sys.argv[1:]
    # Self-test of the matching: a name inside a longer name does not count.
    if missing(["test_a"], "`test_a`") or not missing(["test_a"], "test_ab and my-test_a"):
        sys.exit("check_doc_tests.py self-test failed")
    names = listed_tests(ctest, build_dir)
    if not names:
        sys.exit(f"check_doc_tests.py: `{ctest} -N` in {build_dir} listed no tests")
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    gone = missing(names, text)
    for n in gone:
        print(f"{doc}: CTest test {n} is not listed")
    print(f"{len(names)} CTest tests, {len(gone)} missing from {doc}")
    return 1 if gone else 0


if __name__ == "__main__":
    sys.exit(main())
