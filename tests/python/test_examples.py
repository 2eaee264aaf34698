"""Every example of examples/python/ runs and prints what its pairs are known to be, and every
```python block of doc/python.md runs (the Dask section's need a cluster: test_distributed.py runs
them on a LocalCluster)."""

import os
import re
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.get(
    "RELPOS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
)
EXAMPLES = os.path.join(SOURCE_DIR, "examples", "python")

# For each example, lines its output must contain: positions known by construction.
EXPECTED = {
    "classify.py": ["position: I - interior", "small: True", "same answer from the JSON forms: True",
                    "error: ellipsoid: not an ellipsoid: the matrix describes a hyperboloid of one sheet"],
    "numpy_arrays.py": ["first two: ['TI', 'TE']", "invalid pairs: [5]", "longdouble: ['C', 'TE']"],
    "scene.py": ["bodies: 2001", "last body: TI"],
    "motion.py": ["first contact: contact at t = 1.4142135623730950488 position TE", "E -> TE -> C",
                  "C -> TI -> I", "position at t = 3/2: C"],
    "dask_batch.py": ["answers/mixed.jsonl: one answer per input line"],
    "certificates.py": ["I definite", "TI tangent", "C crossing", "TE tangent", "E definite", "refused: I:",
                        "contact: none"],
}


def test_every_example_is_checked():
    assert sorted(f for f in os.listdir(EXAMPLES) if f.endswith(".py")) == sorted(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_runs(name, tmp_path):
    import relpos

    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(relpos.__file__))))
    run = subprocess.run([sys.executable, os.path.join(EXAMPLES, name)], cwd=tmp_path, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=300)
    assert run.returncode == 0, run.stderr.decode()
    out = run.stdout.decode()
    for line in EXPECTED[name]:
        assert line in out, (name, line, out)
    if name == "scene.py":  # the counts add up to the bodies
        counts = eval(re.search(r"positions: (\{.*\})", out).group(1))
        assert sum(counts.values()) == 2001 and counts["TI"] >= 1


def doc_blocks():
    """(heading, code) of every ```python block of doc/python.md, in order."""
    text = open(os.path.join(SOURCE_DIR, "doc", "python.md"), encoding="utf-8").read()
    heading, blocks = "", []
    for part in re.split(r"(^```python\n.*?^```$)", text, flags=re.S | re.M):
        if part.startswith("```python"):
            blocks.append((heading, part[len("```python\n"):-3]))
        else:
            titles = re.findall(r"^#+ (.*)$", part, flags=re.M)
            heading = titles[-1] if titles else heading
    return blocks


def test_doc_python_blocks_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    blocks = doc_blocks()
    ran = 0
    namespace = {"__name__": "doc_python"}
    for heading, code in blocks:
        if "Dask" in heading:
            continue
        exec(compile(code, "doc/python.md (%s)" % heading, "exec"), namespace)
        ran += 1
    assert ran >= 5, [h for h, _ in blocks]
