#!/usr/bin/env python3
"""No file-private name twice in one namespace of a unity-built library (#47).

  check_private_names.py [BUILD_DIR/unity_targets.txt]    exit 1 and the clashes if any

With FGSG_UNITY_BUILD, CMake compiles a library's .cpp files in batches of eight: each
batch is one translation unit. A name that two files of the library keep to themselves
in the same namespace (declared directly in an anonymous namespace - a function,
variable, type, alias or unscoped enumerator - or `static` at namespace scope) is then
defined twice in one unit as soon as both files land in one batch: a redefinition error,
and batch membership shifts whenever a file is added. This check reports every such
name, whatever the batches, with file:line of each definition.

Sources: CMake writes BUILD_DIR/unity_targets.txt at generate time (CMakeLists.txt,
FGSG_UNITY_TARGETS), one line per batched target: `target<TAB>source dir<TAB>sources`,
the sources being the target's SOURCES, `;`-separated. That is the very list the batches
are made from, with any generator and whether FGSG_UNITY_BUILD is on or off; nothing is
reconstructed from globs or from build.ninja.

The names are found by a small reader: comments, literals and preprocessor lines are
blanked, then braces are followed, and only the declarations at namespace scope are cut
into tokens. Overloads count as one name; an alias repeated word for word (`using
Complex = std::complex<double>;`) is a legal redeclaration, so it does not count.
"""
import bisect
import collections
import os
import re
import sys
from typing import NamedTuple

# What holds no code: its text must not count as braces or names. A number is matched
# only so that the ' of 1'000 starts no character literal. A # appears nowhere else than
# in a preprocessor line (its \-continued lines with it). The look-ahead on the first
# character is only for speed (3 times faster).
NOT_CODE = re.compile(r"""(?=[/"'\#\dRuUL])(?:
    (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<literal>(?:u8|[uUL])?R"(?P<delimiter>[^(\s]*)\(.*?\)(?P=delimiter)"
               |"(?:[^"\\\n]|\\.)*"|'(?:[^'\\\n]|\\.)*')
  | (?P<number>\b\d[\w']*)
  | (?P<preprocessor>\#(?:[^\n\\]|\\.)*)
)""", re.VERBOSE | re.DOTALL)
BOUNDARY = re.compile(r"[{};]")
TOKEN = re.compile(r"""[A-Za-z_]\w*|::|""|\S""")


def blank_non_code(text):
    """The text with comments and preprocessor lines blank and each literal "", its
    newlines kept so that line numbers stay."""
    def blank(m):
        if m.lastgroup == "number":
            return m.group()
        kept = '""' if m.lastgroup in ("literal", "delimiter") else " "
        return kept + "\n" * m.group().count("\n")
    return NOT_CODE.sub(blank, text)


def skip_template_and_attributes(head):
    """The declaration without its leading `template <...>` and `[[...]]` parts."""
    i = 0
    while i < len(head):
        if head[i][0] == "template" and i + 1 < len(head) and head[i + 1][0] == "<":
            depth, i = 0, i + 1
            while i < len(head):
                depth += {"<": 1, ">": -1}.get(head[i][0], 0)
                i += 1
                if depth == 0:
                    break
        elif head[i][0] == "[" and i + 1 < len(head) and head[i + 1][0] == "[":
            while i < len(head) and not (head[i][0] == "]" and head[i - 1][0] == "]"):
                i += 1
            i += 1
        else:
            break
    return head[i:]


def is_function(head):
    """A `(` before any `=` outside angle brackets: a function, declared or defined."""
    angle = 0
    for text, _ in head:
        if text in ("<", ">"):
            angle += 1 if text == "<" else -1
        elif angle == 0 and text in ("=", "("):
            return text == "("
    return False


def in_member_initializers(head):
    """`A::A(...) : x_{...}`: the `{` after `x_` opens an initializer, not the body."""
    depth, after_parameters = 0, False
    for i, (text, _) in enumerate(head):
        depth += {"(": 1, ")": -1}.get(text, 0)
        if depth == 0 and text == ":" and i > 0 and head[i - 1][0] == ")":
            after_parameters = True
    return after_parameters and re.match(r"[A-Za-z_>]", head[-1][0]) is not None


CLASS_KEYS = ("struct", "class", "union", "enum")
NOT_NAMES = {"static_assert", "operator", "extern", "friend", "namespace"}


def declared_names(head, defines_body):
    """[(name, offset)] the declaration `head` introduces; `defines_body`: it ends in `{`."""
    name = first_declared_name(head, defines_body)
    if name is None:
        return []
    names = [name]
    # `constexpr int kA = 1, kB = 2;`: each name after a comma outside parentheses.
    rest = head[head.index(name) + 1:]
    depth = 0
    for i, (text, _) in enumerate(rest):
        depth += {"(": 1, "[": 1, ")": -1, "]": -1}.get(text, 0)
        if depth == 0 and text == ",":
            after = [t for t in rest[i + 1:i + 3] if t[0] not in ("*", "&")]
            if after and re.match(r"[A-Za-z_]", after[0][0]):
                names.append(after[0])
    return names


def first_declared_name(head, defines_body):
    """(name, offset) of the first name the declaration `head` introduces, or None."""
    head = skip_template_and_attributes(head)
    words = [text for text, _ in head]
    if not words or words[0] in NOT_NAMES:
        return None
    if words[0] == "using":  # an alias; `using namespace x;` and `using x::y;` declare nothing new
        return head[1] if len(words) > 2 and words[2] == "=" else None
    if words[0] == "typedef":
        for i in range(len(words) - 2):  # typedef R (*Name)(...);
            if words[i] == "(" and words[i + 1] in ("*", "&"):
                return head[i + 2]
        identifiers = [t for t in head if re.match(r"[A-Za-z_]", t[0])]
        return identifiers[-1] if identifiers else None
    rest = [t for t in head if t[0] not in ("static", "inline", "constexpr", "const")]
    if rest and rest[0][0] in CLASS_KEYS:
        # A class or enum counts where it is defined; `struct X;` and `struct X f();` do not.
        keys = 2 if len(rest) > 1 and rest[1][0] in ("class", "struct") else 1
        after = [t[0] for t in rest[keys + 1:keys + 2]]
        if defines_body and len(rest) > keys and after in ([], [":"], ["final"]):
            return rest[keys]
        return None
    # A variable or function: the identifier before the first `(`, `=`, `[`, `{` or `,`
    # outside angle brackets, unless qualified (a member of a class defined elsewhere).
    angle, end = 0, len(head)
    for i, (text, _) in enumerate(head):
        if text in ("<", ">"):
            angle += 1 if text == "<" else -1
        elif angle == 0 and text in ("(", "=", "[", "{", ","):
            end = i
            break
    if end == 0 or not re.match(r"[A-Za-z_]", head[end - 1][0]) or head[end - 1][0] in NOT_NAMES:
        return None
    if "operator" in words[:end] or (end >= 2 and head[end - 2][0] == "::"):
        return None
    return head[end - 1]


class Private(NamedTuple):
    name: str
    line: int
    namespace: str    # the enclosing named namespaces, "a::b"; "" for the global one
    alias: str        # an alias's declaration, word for word; "" for anything else


def private_names(text):
    """[Private] of the names a .cpp file keeps to itself: declared directly in an
    anonymous namespace, or `static` at namespace scope (outside classes and functions)."""
    code = blank_non_code(text)
    line_starts = [0] + [m.end() for m in re.finditer("\n", code)]
    found = []
    scopes = []      # the open namespaces' names: "" for an anonymous one (extern "C" too)
    nested = 0       # depth inside a class's, function's or initializer's braces
    on_close = None  # what the declaration does once those braces close
    head = []        # the tokens (text, offset) of the declaration read at namespace scope
    skip = False     # reading the rest of a declaration recorded at its `{`
    start = 0        # where the text not yet read begins
    enum_body = None  # where the body of an unscoped enum being skipped begins

    def add(name, offset, alias=""):
        line = bisect.bisect_right(line_starts, offset)
        found.append(Private(name, line, "::".join(s for s in scopes if s), alias))

    def record(defines_body):
        words = [t[0] for t in head]
        anonymous = bool(scopes) and scopes[-1] == ""
        if anonymous or ("static" in words and "extern" not in words):
            for name, offset in declared_names(head, defines_body):
                add(name, offset, " ".join(words) if words[0] in ("using", "typedef") else "")
        return anonymous

    def add_enumerators(body_start, body_end):
        """An unscoped enum's enumerators are names of the enclosing namespace too: the
        first word of each item between commas outside parentheses."""
        depth, item_start = 0, True
        for t in TOKEN.finditer(code, body_start, body_end):
            text = t.group()
            depth += {"(": 1, ")": -1}.get(text, 0)
            if item_start and re.match(r"[A-Za-z_]", text):
                add(text, t.start())
            item_start = depth == 0 and text == ","

    for m in BOUNDARY.finditer(code):
        brace = m.group()
        if nested:
            nested += {"{": 1, "}": -1, ";": 0}[brace]
            if nested == 0:
                if on_close == "continue":  # after a member initializer
                    head.append(("{}", m.start()))
                if enum_body is not None:
                    add_enumerators(enum_body, m.start())
                    enum_body = None
                skip = on_close == "skip"
                start = m.end()
            continue
        if not skip:
            head += [(t.group(), t.start()) for t in TOKEN.finditer(code, start, m.start())]
        start = m.end()
        if brace == "{":
            words = [t[0] for t in head]
            if words == ["namespace"]:
                scopes.append("")
                head = []
            elif words[:1] == ["namespace"] or words[:2] == ["inline", "namespace"] or words == ["extern", '""']:
                scopes.append("".join(w for w in words if w not in ("inline", "namespace", "extern", '""')))
                head = []
            else:
                if skip:
                    on_close = "skip"
                elif in_member_initializers(head):
                    on_close = "continue"
                else:
                    # After a function's body the next declaration starts; after a
                    # class's or an initializer's braces, this one goes on to its `;`.
                    private = record(defines_body=True)
                    declaration = [t[0] for t in skip_template_and_attributes(head)]
                    if private and declaration[:1] == ["enum"] and declaration[1:2] not in (["class"], ["struct"]):
                        enum_body = m.end()
                    on_close = "next" if is_function(skip_template_and_attributes(head)) else "skip"
                    head = []
                nested = 1
        elif brace == "}":
            if scopes:
                scopes.pop()
            head, skip = [], False
        else:
            if head and not skip:
                record(defines_body=False)
            head, skip = [], False
    if scopes or nested:  # the reader lost its way: say so rather than miss names
        raise ValueError("unbalanced braces (a construct this reader does not know)")
    return found


def read_targets(manifest):
    """{target: [source path]} of the .cpp files CMake batches, from unity_targets.txt."""
    targets = {}
    with open(manifest) as f:
        for row in f:
            if not row.strip():
                continue
            target, source_dir, sources = row.rstrip("\n").split("\t")
            targets[target] = [os.path.normpath(os.path.join(source_dir, s))
                               for s in sources.split(";") if s.endswith((".cpp", ".cc", ".cxx"))]
    return targets


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    manifest = argv[1] if len(argv) > 1 else os.path.join(root, "build", "unity_targets.txt")
    if not os.path.isfile(manifest):
        print(f"check_private_names: {manifest} not found: configure the build first (cmake -B build)",
              file=sys.stderr)
        return 2
    clashes = 0
    for target, sources in read_targets(manifest).items():
        where = collections.defaultdict(list)  # (namespace, name) -> [(file:line, alias)]
        for path in sources:
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            try:
                names = private_names(text)
            except ValueError as e:
                print(f"{os.path.relpath(path, root)}: {e}", file=sys.stderr)
                return 2
            seen = set()
            for p in names:
                if (p.namespace, p.name) not in seen:  # a declaration and its definition: one place
                    seen.add((p.namespace, p.name))
                    where[p.namespace, p.name].append((f"{os.path.relpath(path, root)}:{p.line}", p.alias))
        for (namespace, name), places in sorted(where.items()):
            aliases = {alias for _, alias in places}
            if len(places) > 1 and not (len(aliases) == 1 and "" not in aliases):
                clashes += 1
                qualified = f"{namespace}::{name}" if namespace else name
                print(f"{target}: `{qualified}` is private to {len(places)} files, which one unity batch "
                      f"would define twice (FGSG_UNITY_BUILD): {', '.join(place for place, _ in places)}")
    if clashes:
        print(f"{clashes} private name(s) defined in several files of one library: give each a name "
              "of its file, or share one definition from a header", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
