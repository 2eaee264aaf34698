#!/usr/bin/env python3
"""Input, output and limits of the relpos CLI (doc/cli.md): ids echoed byte for byte,
duplicate keys, BOM/CRLF/NUL/trailing separators alike in JSON Lines and CSV, bounded memory per line,
allocation failure on one line, write failures and closed pipes, the same message and exit code from
every command, scene and batch agreeing line by line, motion limits, batch options.

    check_io.py RELPOS_BINARY
"""
import json
import os
import resource
import subprocess
import sys
import tempfile

relpos = sys.argv[1]
failures = []
tmp = tempfile.mkdtemp(prefix="relpos-io-")

E = '"ellipsoid":{"sphere":{"center":[0,0,1],"radius":"1/4"}}'
P = '"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}'


def check(name, ok, detail=""):
    print(("ok:   " if ok else "FAIL: ") + name + ("" if ok else "  " + str(detail)[:600]))
    if not ok:
        failures.append(name)


def run(args, stdin=None, limit_as=None, shell=None):
    def pre():
        if limit_as:
            resource.setrlimit(resource.RLIMIT_AS, (limit_as, limit_as))
    if shell:
        return subprocess.run(shell, shell=True, capture_output=True, timeout=300, executable="/bin/bash")
    return subprocess.run([relpos] + args, input=stdin, capture_output=True, timeout=300,
                          preexec_fn=pre if limit_as else None)


def write(name, data):
    path = os.path.join(tmp, name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def lines(p):
    return p.stdout.decode("utf-8").splitlines()


# --- ids byte for byte -------------------------------------------------------------------------
ids = ["100000000000000000000000000000001", "1.00000000000000000001", "-0.5e-3", '[1, 2.50]', '"\\u00e9"']
data = "".join('{"id": %s ,%s,%s}\n' % (i, E, P) for i in ids).encode()
p = run(["batch", "--evidence", "minimal", write("ids.jsonl", data)])
out = lines(p)
check("batch exits 0 on ids", p.returncode == 0, p.stderr)
for i, line in zip(ids, out):
    check("id %s echoed byte for byte" % i, line.startswith('{"id":%s,' % i), line)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", "--format", "jsonl"],
        stdin="".join('{"id": %s ,%s}\n' % (i, E) for i in ids).encode())
for i, line in zip(ids, lines(p)):
    check("scene id %s echoed byte for byte" % i, line.startswith('{"id":%s,' % i), line)

# --- duplicate keys ----------------------------------------------------------------------------
data = ('{"id":1,%s,%s,%s}\n{"id":1,"id":2,%s,%s}\n{"id":3,"ellipsoid":{"sphere":{"center":[0,0,1],"center":[0,0,2],'
        '"radius":1}},%s}\n' % (E, E, P, E, P, P)).encode()
out = lines(run(["batch", write("dup.jsonl", data)]))
check("two ellipsoids: error", "duplicate key \\\"ellipsoid\\\"" in out[0], out[0])
check("two ids: error", "duplicate key \\\"id\\\"" in out[1], out[1])
check("duplicate nested key: error", "duplicate key" in out[2] and "ellipsoid" in out[2], out[2])

# --- BOM, CRLF, NUL, trailing separators: JSONL and CSV alike ----------------------------------
p = run(["batch"], stdin=('\ufeff{"id":"bom",%s,%s}\r\n' % (E, P)).encode())
check("JSONL with BOM and CRLF answered", '"position":"I"' in p.stdout.decode(), p.stdout)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", write("bom.csv", "\ufeffa,0,0,1,1/4\r\nb,0,0,1,1/4\r\n".encode())])
out = lines(p)
check("CSV with BOM reads its first row", len(out) == 2 and all('"position":"I"' in o for o in out), out)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", write("trail.csv", b"0,0,1,1/4,\n")])
check("CSV trailing separator: an empty-field error", "field 5 of 5 is empty" in p.stdout.decode() and
      '"id":1' in p.stdout.decode(), p.stdout)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", write("nul.csv", b"0,0,1\x00,1/4\n")])
check("CSV NUL byte named with its column", "NUL byte at column 6" in p.stdout.decode(), p.stdout)
p = run(["batch", write("nul.jsonl", ('{"id":1,%s,\x00%s}\n' % (E, P)).encode())])
check("JSONL NUL byte named with its column", "NUL byte at column" in p.stdout.decode(), p.stdout)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", "--format", "jsonl"],
        stdin=('{"id":1,%s,\x00"comment":1}\n' % E).encode())
check("scene JSONL NUL byte: the same message", "NUL byte at column" in p.stdout.decode(), p.stdout)
p = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", write("latin.csv", b"\xe9t\xe9,0,0,1,1/4\n")])
check("invalid UTF-8 in a CSV id replaced by U+FFFD", '"id":"\ufffdt\ufffd"' in p.stdout.decode("utf-8"), p.stdout)

# --- scene and batch agree line by line --------------------------------------------------------
bodies = ['{"id":"far","ellipsoid":{"sphere":{"center":[0,0,"1e4000"],"radius":"1e-4000"}}}',
          '{"id":"ok",%s}' % E, '{"id":"bad","ellipsoid":[1]}', '', '{"id":"x","ellipsoid":1,"ellipsoid":2}',
          '{"id":7,"ellipsoid":{"sphere":{"center":[0,0,1],"radius":0}}}', 'nonsense']
scene = lines(run(["scene", "--standard-paraboloid", "1,1", "--no-progress", "--format", "jsonl"],
                  stdin="\n".join(bodies).encode() + b"\n"))
batch_in = "\n".join(b[:-1] + "," + P + "}" if b.startswith("{") else b for b in bodies) + "\n"
batch = lines(run(["batch", "--evidence", "minimal"], stdin=batch_in.encode()))
for s, b in zip(scene, batch):
    js, jb = json.loads(s), json.loads(b)
    same = js["id"] == jb["id"] and js.get("error") == jb.get("error") and js.get("position") == jb.get("position")
    check("scene and batch agree on %s" % json.dumps(js["id"]), same, (s, b))

# --- memory: bounded per line, allocation failure is that line's error --------------------------
big = write("big.jsonl", ('{"id":"big",%s,%s,"comment":[' % (E, P)).encode() + b"7," * 25000000 + b"7]}\n" +
            ('{"id":"next",%s,%s}\n' % (E, P)).encode())
# Address-space limits cannot be combined with AddressSanitizer (its shadow memory needs terabytes
# of address space): the sanitizer build skips these two probes and keeps the others.
huge = write("huge.jsonl", b'{"id":"huge","comment":"' + b"x" * 300000000 + b'"}\n' + ('{"id":"next",%s,%s}\n' % (E, P)).encode())
if not os.environ.get("RELPOS_SANITIZED"):
    p = run(["batch", "--evidence", "minimal", big], limit_as=1000000 * 1024)
    out = lines(p)
    check("50 MB comment line under 1 GB: exit 0, two answers", p.returncode == 0 and len(out) == 2 and
          '"id":"next","position"' in out[1], (p.returncode, out, p.stderr[-300:]))
    # Peak resident memory of the largest child so far: every earlier child handled small inputs.
    rss_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    check("50 MB line peaks below 500 MB (%d MB)" % (rss_kb // 1024), rss_kb < 500 * 1024, rss_kb)
    p = run(["batch", "--max-line-bytes", "1000000000", huge], limit_as=700 * 1024 * 1024)
    out = lines(p)
    check("out of memory on one line: that line's error, the run goes on", p.returncode == 0 and len(out) == 2 and
          "out of memory" in out[0] and '"id":"next","position"' in out[1], (p.returncode, out, p.stderr[-300:]))
p = run(["batch", huge])
out = lines(p)
check("a line beyond --max-line-bytes: an error line, then the next answer",
      p.returncode == 0 and len(out) == 2 and "line too long" in out[0] and '"id":"next","position"' in out[1], out)
os.unlink(huge)
os.unlink(big)
p = run(["batch", "--evidence", "minimal"], stdin=('{"id":1,%s,%s,"comment":%s}\n' % (E, P, "[" * 100000 + "]" * 100000)).encode())
check("deep comment refused without a crash", p.returncode == 0 and "nested deeper" in p.stdout.decode(), p.stdout[:300])

# --- write failures and closed pipes: message and exit 3 from every command ---------------------
many = write("many.jsonl", "".join('{"id":%d,%s,%s}\n' % (i, E, P) for i in range(3000)).encode())
for name, cmd in [("classify", "classify --sphere 0,0,1,1/4 --standard-paraboloid 1,1"),
                  ("batch", "batch --evidence minimal " + many),
                  ("scene", "scene --standard-paraboloid 1,1 --no-progress --format jsonl " + many),
                  ("motion", "motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation "
                             "'[[], [], [\"-9/4\", 0, 1]]' --t0 0 --t1 2")]:
    p = run([], shell="%s %s > /dev/full" % (relpos, cmd))
    check("%s > /dev/full: exit 3 with a message" % name, p.returncode == 3 and b"cannot write the output" in p.stderr,
          (p.returncode, p.stderr))
for name, cmd in [("batch", "batch --evidence minimal " + many),
                  ("scene", "scene --standard-paraboloid 1,1 --no-progress --format jsonl " + many)]:
    p = run([], shell="%s %s | head -1 > /dev/null; echo ${PIPESTATUS[0]}" % (relpos, cmd))
    check("%s | head -1: exit 3, not SIGPIPE" % name, p.stdout.decode().strip() == "3" and
          b"cannot write the output" in p.stderr, (p.stdout, p.stderr))

# --- the same bad input, the same exit code and message ------------------------------------------
S = ["--standard-paraboloid", "1,2"]
p1 = run(["classify", "--sphere", "0,0,\xff,1"] + S)
p2 = run(["motion", "--sphere", "0,0,\xff,1", "--t0", "0", "--t1", "1"] + S)
check("bad byte: classify and motion alike", p1.returncode == p2.returncode == 1 and p1.stderr == p2.stderr,
      (p1.returncode, p2.returncode, p1.stderr, p2.stderr))
p = run(["motion", "--sphere", "0,0,0,1/4", "--t0", "\xff", "--t1", "1", "--json"] + S)
check("motion --t0 <bad byte> --json exits 1 like classify", p.returncode == 1 and b"--t0" in p.stderr, p)
p = run(["motion", "--sphere", "0,0,0,1/4", "--t0", "NaN", "--t1", "1"] + S)
check("--t0 NaN named as --t0", p.returncode == 1 and b"relpos: --t0:" in p.stderr, p.stderr)
p = run(["motion", "--sphere", "0,0,0,1/4", "--t0", "0", "--t1", "1", "--pivot", "foo"] + S)
check("--pivot foo lists origin|center", p.returncode == 1 and b"origin|center" in p.stderr, p.stderr)
for cmd in (["classify", "--sphere", "0,0,1,1/4"] + S, ["motion", "--sphere", "0,0,1,1/4", "--t0", "0", "--t1", "1"] + S,
            ["batch", "-"], ["scene"] + S):
    a = run(cmd + ["--json" if cmd[0] in ("classify", "motion") else "--threads=1"] * 2)
    b = run(cmd + ["--standard-paraboloid", "1,2"] if cmd[0] != "batch" else cmd + ["--digits", "3", "--digits", "3"])
    check("%s: an option given twice is a usage error" % cmd[0], a.returncode == 2 and b.returncode == 2 and
          b"given twice" in a.stderr and b"given twice" in b.stderr, (a.stderr, b.stderr))
for cmd in (["batch", tmp], ["scene"] + S + [tmp]):
    p = run(cmd)
    check("%s on a directory says so" % cmd[0], p.returncode == 3 and b"is a directory" in p.stderr, p.stderr)

# --- rounding breaks a paraboloid's shape: the message says so ----------------------------------
rot = ('{"matrix":[[0.9330127019,0.1160254038,-0.25,0],[0.1160254038,0.5669872981,0.4330127019,0],'
       '[-0.25,0.4330127019,0.5,-0.5],[0,0,-0.5,0]]}')
p = run(["classify", "--sphere", "0,0,3,1/4", "--paraboloid", rot])
check("rounded paraboloid: the message names rounding and the geometric form",
      p.returncode == 1 and b"rounding" in p.stderr and b"vertex" in p.stderr, p.stderr)

# --- batch options ------------------------------------------------------------------------------
data = "".join('{"id":%d,"ellipsoid":{"sphere":{"center":[0,0,%s],"radius":"1/4"}},%s}\n' % (i, 0.5 + i / 100.0, P)
               for i in range(300)).encode()
path = write("order.jsonl", data)
one = run(["batch", "--threads", "1", path]).stdout
two = run(["batch", "--threads", "2", path]).stdout
check("--threads 2 answers as --threads 1, in input order", one == two and len(one.splitlines()) == 300)
m = [json.loads(l) for l in run(["batch", "--evidence", "minimal", path]).stdout.splitlines()]
check("--evidence minimal: id, position, small, contact, rule, stage",
      all(list(x) == ["id", "position", "small", "contact", "rule", "stage"] for x in m), m[0])
d = run(["batch", "--numbers", "double"], stdin=('{"id":1,"ellipsoid":{"sphere":{"center":[0,0,0.1],"radius":0.1}},'
                                                 '"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}}\n').encode())
x = run(["batch"], stdin=('{"id":1,"ellipsoid":{"sphere":{"center":[0,0,0.1],"radius":0.1}},'
                          '"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}}\n').encode())
check("--numbers double reads 0.1 as the double (a different exact pair)",
      json.loads(d.stdout)["f"] != json.loads(x.stdout)["f"], (d.stdout[:200], x.stdout[:200]))
proc = subprocess.Popen([relpos, "batch", "--evidence", "minimal"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
proc.stdin.write(('{"id":"live",%s,%s}\n' % (E, P)).encode())
proc.stdin.flush()
first = proc.stdout.readline()  # answered before the input ends
proc.stdin.close()
proc.wait(timeout=60)
check("interactive batch answers each line at once", b'"id":"live"' in first, first)

# --- motion limits ------------------------------------------------------------------------------
cheb = [0] * 31
cheb[30] = 2 ** 30  # 2 T_30 leading term is enough to exceed the degree limit
p = run(["motion", "--sphere", "0,0,0,1/4", "--standard-paraboloid", "1,2", "--translation", json.dumps([cheb, [], []]),
         "--t0", "-1", "--t1", "1"])
check("degree-30 motion refused with a message", p.returncode == 1 and b"degree 30" in p.stderr, p.stderr)
p = run(["motion", "--sphere", "0,0,0,1/4", "--standard-paraboloid", "1,2", "--t0", "0", "--t1", "1", "--digits", "600"])
check("motion --digits 600 refused", p.returncode == 2 and b"--digits" in p.stderr, p.stderr)
p = run(["motion", "--sphere", "0,0,0,1/4", "--standard-paraboloid", "1,2", "--translation",
         json.dumps([[0], [0], ["1/%d" % (3 ** 400)]]), "--t0", "0", "--t1", "1"])
check("motion coefficient beyond the bit limit refused", p.returncode == 1 and b"bits" in p.stderr, p.stderr)

p = run(["motion", "--ellipsoid", '{"center":[0,0,-1],"axes":["1/2",1,"1/4"]}', "--standard-paraboloid", "1,2",
         "--translation", "[[0,0,-32,0,160,0,-256,0,128,0,0,0,1],[0,1,0,3,0,0,0,0,0,0,0,0,1],[0,0,0,0,0,0,0,0,0,0,0,7,3]]",
         "--rotation", "[[1,0,0,5,0,0,0,0,0,0,0,0,1],[0,1,0,0,0,0,0,0,0,0,0,2],[],[0,0,3]]",
         "--t0", "-1", "--t1", "1", "--max-seconds", "1"])
check("motion beyond --max-seconds: a message and exit 5", p.returncode == 5 and b"time budget" in p.stderr,
      (p.returncode, p.stderr))

# --- help lists every command and option ---------------------------------------------------------
h = run(["--help"]).stdout.decode()
for word in ["classify", "batch", "scene", "motion", "verify", "--evidence", "--threads", "--numbers",
             "--max-line-bytes", "--max-seconds", "--pivot", "--generate", "--contact-only", "--quiet"]:
    check("relpos --help mentions %s" % word, word in h)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
