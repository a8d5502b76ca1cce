#!/usr/bin/env python3
"""Doxygen's INPUT_FILTER for the public headers (docs/api/Doxyfile): their comments are plain `//`
comments, the project's style; this turns them into Doxygen's, so the headers stay as they are.

- the comment that opens a header (after `#pragma once`) documents the file (\\file);
- a comment on lines of its own, outside function bodies, documents what follows it (`///`);
- a comment after a member or enumerator on its line documents that one (`///<`).
Their text is taken literally: `<`, `>`, `&`, `\\`, `@` and `#` are escaped (`<kind>` is no HTML tag).
"""
import re
import sys

OWN_LINE = re.compile(r"^(\s*)//(?!/) ?(.*)$")
TRAILING = re.compile(r"^(.*?[;,{]\s*)//(?!/) ?(.*)$")
SCOPE = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b|^\s*(public|private|protected):")


def literal(text):
    return re.sub(r"([\\<>&@#%$])", r"\\\1", text)


def code_part(line):
    """The line without its comment and string literals, for counting braces."""
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    return line.split("//", 1)[0]


def doxygen(lines):
    out = []
    opening = True  # still in the file's opening comment
    scopes = []  # per open brace: True for a namespace, class or enum, False for a body or initializer
    pending_scope = False  # a class or namespace head whose brace is on a later line
    for line in lines:
        in_scope = all(scopes)
        own = OWN_LINE.match(line)
        if opening and line.strip() == "#pragma once":
            out.append(line)
            continue
        if opening and own:
            if not any(l.startswith("//!") for l in out):
                out.append("//! \\file")
            out.append("//! " + literal(own.group(2)))
            continue
        opening = False
        if own and in_scope:
            out.append(f"{own.group(1)}/// {literal(own.group(2))}")
            continue
        trailing = TRAILING.match(line)
        if trailing and in_scope and '"' not in trailing.group(1):
            out.append(f"{trailing.group(1)}///< {literal(trailing.group(2))}")
        else:
            out.append(line)
        code = code_part(line)
        head = bool(SCOPE.match(code)) and not re.match(r"^\s*(public|private|protected):", code)
        for ch in code:
            if ch == "{":
                scopes.append(head or pending_scope)
                head = pending_scope = False
            elif ch == "}" and scopes:
                scopes.pop()
        if head and ";" not in code:
            pending_scope = True
    return out


if __name__ == "__main__":
    with open(sys.argv[1], encoding="utf-8") as f:
        text = f.read().split("\n")
    sys.stdout.write("\n".join(doxygen(text)))
