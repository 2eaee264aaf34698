#!/usr/bin/env python3
"""The floors of relpos hold: every #include in src/, include/, cli/ and python/src points down.

The floors are read from the table of doc/architecture.md ("Floors"), so that the document and this
check cannot drift. Each row names a floor: its number, its name, the folders and public headers it
holds, and the floors it may include. The check fails when

  - a source or header file belongs to no floor (a new folder must be placed in the table first),
  - a quoted #include cannot be resolved to a file of the repository,
  - a file includes a file of another floor that its row does not list (an include running up, or
    across to a sibling on the same floor),
  - a row lists a floor that is not below it,
  - the folders, linked by their actual includes, form a cycle,
  - a friend declaration names a function declared only in headers of a higher floor (a climb the
    include check cannot see: the friend needs no include),
  - a file declares, at namespace scope, a function defined only in files of a higher floor (a call
    upward through a hand-written declaration instead of an include),
  - a file under src/ opens a namespace other than relpos (the definitions of public names), a public
    namespace of include/relpos (relpos::io), relpos::detail or one under it, or an anonymous one
    (doc/architecture.md, "Namespaces"),
  - a file of SIZE_RULE (all of src/) has more than MAX_FILE_LINES lines or a function of more
    than MAX_FUNCTION_LINES lines (one job per file; the scan is described in doc/architecture.md,
    "Sizes").

Usage: check_architecture.py REPO_ROOT
"""
import re
import sys
from pathlib import Path

SCANNED = ("src", "include", "cli", "python/src")
EXTENSIONS = {".hpp", ".cpp", ".h", ".cc"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)

# The public API only the API (doc/architecture.md, "The public API").
PUBLIC_HEADERS = "include/relpos/"
MAX_PUBLIC_DECLARATIONS = 100
# One job per file (doc/architecture.md, "Sizes").
MAX_FILE_LINES = 500
MAX_FUNCTION_LINES = 60
# The files and folders (a trailing /) the size rule holds for: all of src/, new files included.
SIZE_RULE = ["src/"]


# ---- The C++ scan behind the size and declaration rules (doc/architecture.md, "Sizes") ----------

RAW_STRING = re.compile(r'R"([^(\s]*)\(')


def strip_code(text: str) -> str:
    """The code with comments, string and character literals and preprocessor lines blanked; every
    newline is kept, so offsets still give line numbers."""
    out, i, n, line_start = [], 0, len(text), True
    while i < n:
        c = text[i]
        if line_start:
            j = i
            while j < n and text[j] in " \t":
                j += 1
            if j < n and text[j] == "#":  # a preprocessor line and its continuations
                while j < n and text[j] != "\n":
                    if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                        out.append("\n")
                        j += 2
                        continue
                    j += 1
                i = j
                continue
            line_start = False
        if c == "\n":
            out.append(c)
            i += 1
            line_start = True
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif (m := RAW_STRING.match(text, i)) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            j = text.find(")" + m.group(1) + '"', m.end())
            j = n if j < 0 else j + len(m.group(1)) + 2
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):  # not a digit separator
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


TEMPLATE_HEAD = re.compile(r"\btemplate\s*<")


def drop_template_heads(head: str) -> str:
    while m := TEMPLATE_HEAD.search(head):
        depth, j = 1, m.end()
        while j < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[j], 0)
            j += 1
        head = head[:m.start()] + " " + head[j:]
    return head


def block_kind(head: str) -> str:
    """What a `{` at namespace or class scope opens, from the text before it: namespace, class, data
    (an initializer, an enum) or function."""
    h = drop_template_heads(head)
    paren = h.find("(")
    before = h if paren < 0 else h[:paren]
    if re.search(r"\bnamespace\b", before) or re.fullmatch(r'\s*extern\s*""\s*', h):
        return "namespace"
    if re.search(r"\benum\b", before):
        return "data"
    if re.search(r"\b(class|struct|union)\b", before):
        return "class"
    if paren < 0 or ("=" in before and not re.search(r"\boperator\b", before)):
        return "data"
    return "function"


def matching_brace(code: str, i: int) -> int:
    """The index after the `}` that closes the `{` at i."""
    depth, j = 1, i + 1
    while j < len(code) and depth:
        depth += {"{": 1, "}": -1}.get(code[j], 0)
        j += 1
    return j


CTOR_INIT = re.compile(r"\)\s*(?:const\s*)?(?:noexcept\s*)?:(?!:)")


def scan_code(code: str):
    """Functions defined and functions declared at namespace or class scope of stripped code:
    ([(name, first line, last line)], [(name, line)] of namespace-scope declarations)."""
    functions, declarations, stack = [], [], []
    i, n, start, paren = 0, len(code), 0, 0
    while i < n:
        c = code[i]
        if c in "([":
            paren += 1
        elif c in ")]":
            paren -= 1
        elif c == ";" and paren == 0:
            if not stack or stack[-1] == "namespace":
                head = drop_template_heads(code[start:i])
                m = re.search(r"([A-Za-z_]\w*)\s*\(", head)
                statement = re.match(r"\s*(friend|typedef|using|static_assert|return)\b", head)
                if m and not statement and "=" not in head[:m.start()]:
                    declarations.append((m.group(1), code.count("\n", 0, i) + 1))
            start = i + 1
        elif c == "}":
            if stack:
                stack.pop()
            start = i + 1
        elif c == "{":
            head = code[start:i]
            if paren > 0 or (stack and stack[-1] not in ("namespace", "class")):
                i = matching_brace(code, i)  # a brace inside an expression or a function body
                continue
            kind = block_kind(head)
            if kind == "function" and CTOR_INIT.search(head) and re.search(r"[\w>]\s*$", head):
                i = matching_brace(code, i)  # a member initializer written with braces: still the head
                continue
            if kind == "function":
                j = matching_brace(code, i)
                names = re.findall(r"(operator\s*[^\s(]+|[~\w:]+)\s*\(", drop_template_heads(head))
                first, last = code.count("\n", 0, i) + 1, code.count("\n", 0, j - 1) + 1
                functions.append((names[0] if names else "?", first, last))
                i = start = j
                continue
            stack.append(kind)
            start = i + 1
        i += 1
    return functions, declarations


FORWARD = re.compile(r"(?:class|struct|union|enum(?:\s+class|\s+struct)?)\s+\w+(?:\s*:\s*[\w:\s]+)?")


def namespace_scope(code: str):
    """Walk stripped code at namespace scope, yielding (event, head, position, heads of the open
    namespace blocks): "statement" for each ';' there, "namespace" for a namespace (or `extern "C"`)
    block opened, "block" for any other block there, which the walk then skips (a class, enum or
    initializer to its ';'); a braced initializer inside parentheses is skipped."""
    heads = []
    i, n, start, paren = 0, len(code), 0, 0
    while i < n:
        c = code[i]
        if c in "([":
            paren += 1
        elif c in ")]":
            paren -= 1
        elif c == ";" and paren == 0:
            yield "statement", code[start:i], i, tuple(heads)
            start = i + 1
        elif c == "}":
            if heads:
                heads.pop()
            start = i + 1
        elif c == "{" and paren > 0:  # a braced initializer in a declaration (a default argument)
            i = matching_brace(code, i)
            continue
        elif c == "{":
            head = code[start:i]
            kind = block_kind(head)
            if kind == "namespace":
                yield "namespace", head, i, tuple(heads)
                heads.append(head)
                start = i + 1
            else:
                yield "block", head, i, tuple(heads)
                i = matching_brace(code, i)
                if kind != "function":  # a class, enum or initializer ends at its ';'
                    i = code.find(";", i)
                    i = n if i < 0 else i
                start = i + 1
                continue
        i += 1


def public_declarations(code: str):
    """The names declared at namespace scope in stripped code outside any namespace named detail, as
    (qualified name, line): every class, struct, union, enum, alias, variable and function (a
    function's overloads share its name, so a caller counts each name once); forward declarations,
    friends and static_asserts declare nothing new."""
    out = []

    def record(head: str, at: int, definition: bool, stack):  # stack: the names of each open namespace
        text = " ".join(drop_template_heads(head).split())
        if not text or any("detail" in names for names in stack) or re.match(r"(friend|static_assert)\b", text):
            return
        if not definition and FORWARD.fullmatch(text):
            return
        eq, paren_at = text.find("="), text.find("(")
        if paren_at >= 0 and (eq < 0 or paren_at < eq):  # a function: the name before its parameters
            name = re.findall(r"(operator\s*\S+?|[A-Za-z_]\w*)\s*$", text[:paren_at])
        else:  # a type, an alias, a variable: the last name before any value or base
            name = re.findall(r"[A-Za-z_]\w*", re.split(r"\s[=:]\s|\s[=:]$|=", text)[0])
        text = ".".join([*(n for names in stack for n in names), name[-1] if name else text])
        out.append((text, code.count("\n", 0, at) + 1))

    for event, head, at, heads in namespace_scope(code):
        if event != "namespace":
            stack = [re.findall(r"\w+", re.sub(r"\b(inline|namespace)\b", " ", h)) for h in heads]
            record(head, at, event == "block", stack)
    return out


def namespace_names(head: str):
    """The names a namespace block's head opens, from the outermost in; an anonymous namespace ""
    and an `extern "C"` block none."""
    names = tuple(re.findall(r"\w+", re.sub(r'\b(inline|namespace|extern)\b|""', " ", head)))
    return names or (("",) if re.search(r"\bnamespace\b", head) else ())


def opened_namespaces(code: str):
    """Every namespace opened in stripped code, as (its full name, line): a tuple of its names from the
    outermost in, an anonymous namespace written "" (`extern "C"` blocks are transparent)."""
    return [(tuple(x for h in heads for x in namespace_names(h)) + namespace_names(head), code.count("\n", 0, at) + 1)
            for event, head, at, heads in namespace_scope(code)
            if event == "namespace" and re.search(r"\bnamespace\b", head)]


def private_namespace(full, public) -> bool:
    """Whether a namespace opened under src/ breaks the rule: relpos, a public namespace,
    relpos::detail and anything under it, and anonymous namespaces anywhere in them are allowed."""
    named = tuple(x for x in full if x)
    if not named:
        return False
    if named[0] != "relpos" or len(named) == 1:
        return named[0] != "relpos"
    return named[1] != "detail" and named not in public


FRIEND = re.compile(r"\bfriend\b([^;{]*?)\b(?:[A-Za-z_]\w*::)*([A-Za-z_]\w*)\s*\(([^;{]*)\)\s*[^;{]*;")


# The scan on a fixture whose answers are known (run before every check, so that a change to the scan
# that miscounts fails here): braces in comments, strings, raw strings and character literals are
# ignored; a constructor's braced member initializers belong to its head; a lambda counts toward the
# function around it; a class's member functions are functions; a namespace-scope lambda, an enum and
# a braced initializer are not.
SELF_TEST = r"""namespace a {
// } { a comment's braces
int f(int x) {          // line 3
  auto g = [](int y) {  // a lambda: part of f
    return y;
  };
  return g(x) + '}';
}                       // line 8
struct S {
  S(int v) : v_{v}, w_{1} {  // line 10
    const char* s = "{{";
  }                          // line 12
  int v_, w_;
  bool operator==(const S& o) const { return v_ == o.v_; }  // line 14
};
enum class E { A, B };
const int table[] = {1, 2, 3};
auto h = [](int z) { return z; };
template <class T, class = typename T::type>
T k(T t) { return t; }  // line 20
const char* raw = R"x(})x";
int declared(double d);
}  // namespace a
"""


# The public count on a fixture: overloads share a name, a namespace qualifies it, a forward
# declaration, a friend and everything in a detail namespace are not counted, members and default
# arguments with braces are not names of their own.
PUBLIC_TEST = r"""namespace relpos {
class Ellipsoid;
struct Verdict { int a; void f(); };
enum class Stage : unsigned char { A, B };
inline constexpr int kLimit = 4;
using Number = double;
Verdict decide(const Ellipsoid& e, const Limit& l = {});
Verdict decide(const double* e);
std::string to_string(Stage s);
inline std::string to_string(int s) { return "}"; }
namespace detail {
struct Access { static int f(); };
int helper(int x);
}  // namespace detail
}  // namespace relpos
namespace relpos::io {
std::string to_string(Verdict v);
}  // namespace relpos::io
"""


# The namespace rule on a fixture: relpos, relpos::io (public), relpos::detail and what is under it
# and anonymous namespaces pass; relpos::forms, relpos::io::detail and a namespace outside relpos fail.
NAMESPACE_TEST = r"""namespace relpos {
namespace {
int f() { namespace x = std; return 0; }
}  // namespace
namespace detail::forms {
struct S { int g() { return 1; } };
}  // namespace detail::forms
}  // namespace relpos
namespace relpos::io {
namespace detail {
}  // namespace detail
}  // namespace relpos::io
namespace relpos::forms {
extern "C" {
int h();
}
}  // namespace relpos::forms
namespace other {
}  // namespace other
"""


def self_test() -> None:
    functions, declarations = scan_code(strip_code(SELF_TEST))
    want = [("f", 3, 8), ("S", 10, 12), ("operator==", 14, 14), ("k", 20, 20)]
    if functions != want or [d[0] for d in declarations] != ["declared"]:
        sys.exit(f"check_architecture.py: the C++ scan miscounts its fixture: {functions}, {declarations}")
    names = sorted({name for name, _ in public_declarations(strip_code(PUBLIC_TEST))})
    want_names = ["relpos.Number", "relpos.Stage", "relpos.Verdict", "relpos.decide", "relpos.io.to_string",
                  "relpos.kLimit", "relpos.to_string"]
    if names != want_names:
        sys.exit(f"check_architecture.py: the public count miscounts its fixture: {names}")
    public = {("relpos",), ("relpos", "io")}
    bad = [(full, line) for full, line in opened_namespaces(strip_code(NAMESPACE_TEST))
           if private_namespace(full, public)]
    if bad != [(("relpos", "io", "detail"), 10), (("relpos", "forms"), 13), (("other",), 18)]:
        sys.exit(f"check_architecture.py: the namespace scan misreads its fixture: {bad}")


def read_floors(doc: Path):
    """Rows of the "Floors" table: (number, name, [paths], [may include])."""
    text = doc.read_text(encoding="utf-8")
    section = re.search(r"^## Floors\n(.*?)(?=^## )", text, re.M | re.S)
    if not section:
        sys.exit(f"{doc}: no '## Floors' section")
    rows = []
    for line in section.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 5 or not cells[0].isdigit():
            continue
        number, name, paths, _holds, may = cells
        paths = re.findall(r"`([^`]+)`", paths)
        may = [] if may in ("", "—", "-") else [m.strip().strip("`") for m in may.split(",")]
        rows.append((int(number), name.strip("`* "), paths, may))
    if not rows:
        sys.exit(f"{doc}: the Floors table has no rows")
    return rows


def main() -> int:
    self_test()
    root = Path(sys.argv[1]).resolve()
    rows = read_floors(root / "doc" / "architecture.md")
    floor_of = {name: number for number, name, _, _ in rows}
    allowed = {name: set(may) for _, name, _, may in rows}
    owner = []  # (path prefix, row name), longest prefix first
    for _, name, paths, _ in rows:
        for p in paths:
            owner.append((p, name))
    owner.sort(key=lambda x: -len(x[0]))
    errors = []

    for number, name, paths, may in rows:
        for m in may:
            if m not in floor_of:
                errors.append(f"doc/architecture.md: floor {name} may include '{m}', which is no floor")
            elif floor_of[m] >= number:
                errors.append(f"doc/architecture.md: floor {name} (#{number}) lists {m} (#{floor_of[m]}), not below it")
        for p in paths:
            if not (root / p).exists():
                errors.append(f"doc/architecture.md: floor {name} names {p}, which does not exist")

    def row_of(rel: str):
        for prefix, name in owner:
            if rel == prefix or (prefix.endswith("/") and rel.startswith(prefix)):
                return name
        return None

    def resolve(including: Path, target: str):
        for base in (including.parent, root / "include", root / "src"):
            candidate = (base / target).resolve()
            if candidate.is_file():
                return candidate
        # A public header CMake generates (relpos/version.hpp) is its template cmake/NAME.in.
        template = root / "cmake" / (Path(target).name + ".in")
        if target.startswith("relpos/") and template.is_file():
            return template
        return None

    edges = {}
    files = sorted(f for d in SCANNED for f in (root / d).rglob("*") if f.suffix in EXTENSIONS and f.is_file())
    for f in files:
        rel = f.relative_to(root).as_posix()
        here = row_of(rel)
        if here is None:
            errors.append(f"{rel}: belongs to no floor of doc/architecture.md")
            continue
        for kind, target in INCLUDE.findall(f.read_text(encoding="utf-8", errors="replace")):
            if kind == "<" and not target.startswith("relpos/"):
                continue  # the standard library and third-party headers
            found = resolve(f, target)
            if found is None:
                errors.append(f'{rel}: #include "{target}" resolves to no file of the repository')
                continue
            there = row_of(found.relative_to(root).as_posix())
            if there is None:
                errors.append(f"{rel}: includes {target}, which belongs to no floor")
                continue
            if there == here:
                continue
            edges.setdefault(here, set()).add(there)
            if there not in allowed[here]:
                direction = "up" if floor_of[there] > floor_of[here] else (
                    "across" if floor_of[there] == floor_of[here] else "down to an unlisted floor")
                errors.append(f"{rel} ({here}, floor {floor_of[here]}) includes {target} "
                              f"({there}, floor {floor_of[there]}): {direction}")

    # Folder-level cycles in the actual include graph (depth-first search, three colours).
    state = {}

    def visit(node, path):
        state[node] = 1
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                errors.append("cycle: " + " -> ".join(path[path.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = 2

    for node in sorted(edges):
        if node not in state:
            visit(node, [node])

    notes = check_declarations_and_sizes(root, files, row_of, floor_of, errors)

    for e in errors:
        print(e)
    for note in notes:
        print(note)
    print(f"{len(files)} files, {sum(len(v) for v in edges.values())} floor-to-floor links, {len(errors)} errors")
    return 1 if errors else 0


def check_declarations_and_sizes(root: Path, files, row_of, floor_of, errors):
    """The declaration rules (friends, hand-written declarations upward) and the size rule; returns
    notes on size violations outside SIZE_RULE."""
    floor = {}  # repository path -> floor number
    defined = {}  # function name -> floors defining it
    declared_in_headers = {}  # function name -> {header: floor} of the headers declaring it (friends aside)
    scans = {}
    for f in files:
        rel = f.relative_to(root).as_posix()
        row = row_of(rel)
        if row is None:
            continue
        floor[rel] = floor_of[row]
        code = strip_code(f.read_text(encoding="utf-8", errors="replace"))
        functions, declarations = scan_code(code)
        scans[rel] = (code, functions, declarations)
        for name, _, _ in functions:
            defined.setdefault(name.split("::")[-1], set()).add(floor[rel])
        if f.suffix in (".hpp", ".h"):
            for name, _ in declarations:
                declared_in_headers.setdefault(name, {})[rel] = floor[rel]

    for rel, (code, functions, declarations) in sorted(scans.items()):
        here = floor[rel]
        for m in FRIEND.finditer(code):
            name = m.group(2)
            if name.startswith("operator"):
                continue
            # Where the function lives: the floors defining it, else those of the other headers
            # declaring it (a declaration beside the friend, as quadric.hpp has, does not count).
            homes = defined.get(name) or {
                fl for header, fl in declared_in_headers.get(name, {}).items() if header != rel}
            if homes and min(homes) > here:
                line = code.count("\n", 0, m.start()) + 1
                errors.append(f"{rel}:{line} (floor {here}) befriends {name}, which lives on floor {min(homes)}: "
                              "a climb the include check cannot see")
        for name, line in declarations:
            homes = defined.get(name, set())
            if homes and min(homes) > here:
                errors.append(f"{rel}:{line} (floor {here}) declares {name}, defined only on floor {min(homes)}: "
                              "a call upward without an include")

    def enforced(rel: str) -> bool:
        return any(rel == p or (p.endswith("/") and rel.startswith(p)) for p in SIZE_RULE)

    for rel, (code, functions, _) in sorted(scans.items()):
        if not enforced(rel):
            continue
        lines = code.count("\n")
        if lines > MAX_FILE_LINES:
            errors.append(f"{rel}: {lines} lines, beyond the limit of {MAX_FILE_LINES}")
        for name, first, last in functions:
            if last - first + 1 > MAX_FUNCTION_LINES:
                errors.append(f"{rel}:{first}: {name} has {last - first + 1} lines, beyond the limit of "
                              f"{MAX_FUNCTION_LINES}")

    # Everything private in relpos::detail (doc/architecture.md, "Namespaces"): the namespaces of src/
    # are those of the public headers, relpos::detail and those under it, and anonymous ones.
    public_namespaces = {full for rel, (code, _, _) in scans.items() if rel.startswith(PUBLIC_HEADERS)
                         for full, _ in opened_namespaces(code) if "detail" not in full and "" not in full}
    for rel, (code, _, _) in sorted(scans.items()):
        if rel.startswith("src/"):
            for full, line in opened_namespaces(code):
                # A namespace inside one already reported is not reported again.
                if private_namespace(full, public_namespaces) and not any(
                        private_namespace(full[:k], public_namespaces) for k in range(1, len(full))):
                    errors.append(f"{rel}:{line}: opens namespace {'::'.join(x or '(anonymous)' for x in full)}, "
                                  "neither public (include/relpos) nor under relpos::detail")

    public = {}  # a public name -> where it is first declared
    for rel, (code, _, _) in sorted(scans.items()):
        if rel.startswith(PUBLIC_HEADERS):
            for text, line in public_declarations(code):
                public.setdefault(text, f"{rel}:{line}")
    if len(public) > MAX_PUBLIC_DECLARATIONS:
        errors.append(f"{PUBLIC_HEADERS}: {len(public)} public names at namespace scope, beyond the limit of "
                      f"{MAX_PUBLIC_DECLARATIONS} (doc/architecture.md, \"The public API\")")
    return [f"{len(public)} public names at namespace scope in {PUBLIC_HEADERS} (at most {MAX_PUBLIC_DECLARATIONS})"]


if __name__ == "__main__":
    sys.exit(main())
