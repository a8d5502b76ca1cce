#!/usr/bin/env python3
"""Function lengths by brace matching: every function body in the host's C++ sources (host/, and python/, the
Python module's bindings) and the OpenCL kernels,
from the line its signature starts on to the line of its closing brace (as lizard's "length").

    scripts/function_lengths.py [--top N] [--check]

--check fails (exit 1) when a function in host/ or python/ is longer than 120 lines or one in kernels/ longer than 200
(issue 44: long functions are where bugs and duplicated checks hide). Lambdas and local classes count
toward the function that holds them. Comments, strings and preprocessor lines are skipped; of an #if block
only the first branch is read (so that braces split across its branches balance), and a function's length
is its source lines as written.
"""
import argparse
import os
import re
import sys

LIMITS = {"host": 120, "python": 120, "kernels": 200}
CONTAINER = re.compile(r"^(?:template\s*<.*>\s*)?(?:namespace|class|struct|union|enum)\b|^extern\s+\"C\"", re.S)
SIGNATURE = re.compile(r"\)\s*(?:const\s*)?(?:noexcept\s*)?(?:override\s*)?(?:final\s*)?(?:->\s*[\w:<>,\s*&]+)?\s*"
                       r"(?::\s*[\w:]+\s*[({].*)?$", re.S)


def strip(text):
    """The text with comments, string and character literals and preprocessor lines blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            j = i
            while j < n and (text[j] != "\n" or text[j - 1] == "\\"):
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c in "\"'":
            m = re.match(r'R"([^(]*)\(', text[i - 1:i + 20]) if c == '"' and i and text[i - 1] == "R" else None
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                j = n if end < 0 else end + len(m.group(1)) + 2
            else:
                j = i + 1
                while j < n and text[j] != c:
                    j += 2 if text[j] == "\\" else 1
                j += 1
            out.append(c + re.sub(r"[^\n]", " ", text[i + 1:j - 1]) + c)
            i = j
            continue
        out.append(c)
        at_line_start = c == "\n" or (at_line_start and c in " \t")
        i += 1
    return "".join(out)


def first_branches(text):
    """The text with every #else and #elif branch blanked (newlines kept): braces split across the branches of
    an #if then balance as in the first branch, which is measured."""
    out, skipping = [], []
    for line in text.split("\n"):
        d = re.match(r"\s*#\s*(if|ifdef|ifndef|elif|else|endif)\b", line)
        if d and d.group(1) in ("if", "ifdef", "ifndef"):
            skipping.append(False)
        elif d and d.group(1) in ("elif", "else") and skipping:
            skipping[-1] = True
        elif d and d.group(1) == "endif" and skipping:
            skipping.pop()
        out.append("" if any(skipping) and not d else line)
    return "\n".join(out)


def functions(path):
    """(name, first line, last line) of every outermost function body in the file."""
    text = strip(first_branches(open(path, encoding="utf-8", errors="replace").read()))
    found, stack, head_start = [], [], 0
    for i, c in enumerate(text):
        if c in ";":
            head_start = i + 1
        elif c == "{":
            head = text[head_start:i].strip()
            in_function = any(kind == "function" for kind, _, _ in stack)
            if in_function:
                kind = "inner"
            elif CONTAINER.match(head) or "(" not in head or not SIGNATURE.search(head):
                kind = "container"
            else:
                kind = "function"
            start = head_start + (len(text[head_start:i]) - len(text[head_start:i].lstrip()))
            stack.append((kind, start, head))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind, start, head = stack.pop()
                if kind == "function":
                    signature = re.sub(r"__attribute__\s*\(\(.*?\)\)", "", head, flags=re.S)
                    name = re.sub(r"\s+", " ", signature.split("(")[0]).split(" ")[-1]
                    found.append((name, text.count("\n", 0, start) + 1, text.count("\n", 0, i) + 1))
            head_start = i + 1
    return found


def sources(root):
    for top in LIMITS:
        for folder, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith((".cpp", ".hpp", ".h", ".cl")):
                    yield top, os.path.join(folder, f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--top", type=int, default=15, help="print the N longest functions (default 15)")
    ap.add_argument("--check", action="store_true", help="exit 1 when a function exceeds its folder's limit")
    args = ap.parse_args()
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    rows = []
    for top, path in sources(root):
        for name, first, last in functions(path):
            rows.append((last - first + 1, os.path.relpath(path, root), first, name, top))
    rows.sort(reverse=True)
    for length, path, line, name, _ in rows[:args.top]:
        print("%5d  %s:%d  %s" % (length, path, line, name))
    over = [r for r in rows if r[0] > LIMITS[r[4]]]
    for length, path, line, name, top in over:
        print("TOO LONG: %s:%d %s is %d lines (limit %d in %s/)" % (path, line, name, length, LIMITS[top], top))
    print("function_lengths: %d functions, %d over the limits (host %d, kernels %d lines)"
          % (len(rows), len(over), LIMITS["host"], LIMITS["kernels"]))
    return 1 if args.check and over else 0


if __name__ == "__main__":
    sys.exit(main())
