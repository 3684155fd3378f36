"""The C++ core stays short: at most MAX_LONG functions of cpp/kresling and cpp/python (the
tests under cpp/tests are not counted) are longer than LONG lines, from the first line of
the signature to the closing brace. A lambda counts as part of the function it is written
in. `python tests/package/test_cpp_function_lengths.py` lists the long ones, longest first."""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
COUNTED = [ROOT / "cpp" / "kresling", ROOT / "cpp" / "python"]
LONG = 60
MAX_LONG = 10


SPECIAL = re.compile(r"//|/\*|R\"|[\"'#]")


def blank_out(text):
    """`text` with comments, string and character literals and preprocessor lines replaced
    by spaces (line breaks kept), so that braces and parentheses in them do not count."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text.startswith('R"', i) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            delimiter = re.match(r'R"([^(]*)\(', text[i:]).group(1)
            j = text.find(")" + delimiter + '"', i) + len(delimiter) + 2
        elif text[i] in "\"'" and not (text[i] == "'" and i and text[i - 1].isalnum()):
            j = i + 1  # a literal; a quote after a digit is a digit separator (1'000)
            while j < n and text[j] != text[i]:
                j += 2 if text[j] == "\\" else 1
            j += 1
        elif text[i] == "#" and text[text.rfind("\n", 0, i) + 1:i].strip() == "":
            j = i
            while True:  # a directive, with its continuation lines
                j = text.find("\n", j)
                j = n if j < 0 else j
                if j == n or text[j - 1] != "\\":
                    break
                j += 1
        else:
            special = SPECIAL.search(text, i + 1)
            j = special.start() if special else n
            out.append(text[i:j])  # plain code up to the next comment, literal or '#'
            i = j
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def closing_brace(code, i):
    depth = 0
    for j in range(i, len(code)):
        depth += {"{": 1, "}": -1}.get(code[j], 0)
        if depth == 0:
            return j
    return len(code) - 1


def function_lengths(text):
    """(name, first line, length in lines) of each function defined in C++ source `text`:
    a brace block opened after a parameter list at namespace or class scope. A brace-
    initialised member in a constructor's initialiser list (`a_{x}`) is skipped."""
    code = blank_out(text)
    found, scopes = [], []  # scopes: 'scope' (namespace, class) or 'other' (enum, table)
    head, i = 0, 0  # head: where the current declaration starts
    while i < len(code):
        c = code[i]
        if c == ";":
            head = i + 1
        elif c == "}":
            if scopes:
                scopes.pop()
            head = i + 1
        elif c == "{":
            header = code[head:i].strip()
            before = code[i - 1] if i else " "
            if re.search(r"\b(namespace|extern)\b", header) and "(" not in header:
                scopes.append("scope")
            elif re.search(r"\b(class|struct|union)\b", header) and "(" not in header \
                    and not re.search(r"\benum\b", header):
                scopes.append("scope")
            elif "(" in header and (before.isalnum() or before in "_>"):
                i = closing_brace(code, i) + 1  # a member's brace initialiser
                continue
            elif "(" in header and not re.match(r"^[^(]*[^=!<>]=[^=]", header):
                end = closing_brace(code, i)
                start = head + len(code[head:i]) - len(code[head:i].lstrip())
                names = re.findall(r"([~\w:]+|operator\S+)\s*\(", code[start:i])
                first = code.count("\n", 0, start) + 1
                found.append((names[0] if names else "?", first,
                              code.count("\n", 0, end) + 2 - first))
                i, head = end + 1, end + 1
                continue
            else:
                scopes.append("other")
                i = closing_brace(code, i) + 1
                scopes.pop()
                head = i
                continue
            head = i + 1
        i += 1
    return found


def long_functions(roots=COUNTED, limit=LONG):
    """(length, 'path:line', name) of every function over `limit` lines, longest first."""
    rows = []
    for root in roots:
        for path in sorted(root.rglob("*.[ch]pp")):
            for name, line, length in function_lengths(path.read_text(encoding="utf-8")):
                if length > limit:
                    rows.append((length, f"{path.relative_to(ROOT)}:{line}", name))
    return sorted(rows, reverse=True)


def test_few_cpp_functions_are_long():
    rows = long_functions()
    assert len(rows) <= MAX_LONG, "\n".join(f"{n} lines: {where} {name}" for n, where, name in rows)


SAMPLE = '''#include "a.hpp"  // {
namespace kresling::solvers {
namespace {
constexpr double kTable[] = {1.0, 2.0};
enum class Kind { a, b };
}  // namespace

struct Outer {
  int member() const {
    return 1;
  }
};

Follower::Follower(int x) : a_{x}, b_(x) {
  const char* s = "}";
  auto f = [&](int y) {
    return y;
  };
}

double twice(double x) { return 2 * x; }
}  // namespace kresling::solvers
'''


def test_the_counter_measures_functions_not_other_braces():
    # Three functions: a member in a class, a constructor with a brace-initialised member
    # and a lambda inside (one function, the initialiser skipped, the brace in the string
    # ignored), a one-liner; the table and the enum are no functions.
    assert function_lengths(SAMPLE) == [("member", 9, 3), ("Follower::Follower", 14, 6),
                                        ("twice", 21, 1)]


def test_a_long_function_is_reported(tmp_path):
    body = "\n".join(f"  x += {k};" for k in range(LONG))
    (tmp_path / "long.cpp").write_text(f"int grow(int x) {{\n{body}\n  return x;\n}}\n")
    global ROOT
    saved, ROOT = ROOT, tmp_path
    try:
        rows = long_functions([tmp_path])
    finally:
        ROOT = saved
    assert rows == [(LONG + 3, "long.cpp:1", "grow")]


if __name__ == "__main__":
    rows = long_functions()
    for length, where, name in rows:
        print(f"{length:4d}  {where}  {name}")
    print(f"{len(rows)} functions over {LONG} lines in cpp/kresling and cpp/python "
          f"(at most {MAX_LONG} allowed)")
    sys.exit(len(rows) > MAX_LONG)
