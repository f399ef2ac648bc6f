#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks docs/bad-input.md against include/projcurve.h and tests/.

Every PROJCURVE_API function of the header must have exactly one row; every
row must name only functions of the header, and its test column only tests
that exist: a test_* or fuzz_* name is a test source tests/**/<name>.c (or
.cpp, .py, .sh), a `backticked` name a file or folder under tests/ (a fuzz
corpus entry); and at least one of the row's test sources must call each
function of the row.

Row format (the tables whose first column is "function" and last "test"):
the first cell lists the row's functions by full name, each in backticks;
a first cell with no `projcurve_` name is a note row (a situation, not a
function) and only its tests are checked.

Usage: check_bad_input.py [project root]   (exit 0: consistent, 1: not)
"""
import os
import re
import sys

API_RE = re.compile(r"\bPROJCURVE_API\b[^;{]*?\b(projcurve_[a-z0-9_]+)\s*\(", re.S)
NAME_RE = re.compile(r"`(projcurve_[a-z0-9_]+)`")
TEST_RE = re.compile(r"\b((?:test|fuzz)_[a-z0-9_]+)\b")
FILE_RE = re.compile(r"`([^`]+)`")
SOURCE_EXTENSIONS = (".c", ".cpp", ".py", ".sh")  # what a test program is made of


def header_functions(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)  # comments name functions too
    text = re.sub(r"^\s*#.*$", " ", text, flags=re.M)   # the PROJCURVE_API definition
    return set(API_RE.findall(text))


def split_row(line):
    cells = line.strip().strip("|").split("|")
    return [c.strip() for c in cells]


def doc_rows(path):
    """(line number, function names, first cell, test cell) of each table row."""
    rows = []
    in_table = False
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for number, line in enumerate(lines, 1):
        if not line.startswith("|"):
            in_table = False
            continue
        cells = split_row(line)
        if not in_table:
            in_table = cells[0] == "function" and cells[-1] == "test"
            continue
        if set(line) <= set("|-: "):
            continue  # the separator row
        rows.append((number, NAME_RE.findall(cells[0]), cells[0], cells[-1]))
    return rows


def test_files(tests_dir):
    """name without extension -> path of each test source under tests/, and
    every file and folder name."""
    sources, names = {}, set()
    for root, dirs, files in os.walk(tests_dir):
        names.update(dirs)
        for f in files:
            names.add(f)
            stem, ext = os.path.splitext(f)
            if ext in SOURCE_EXTENSIONS:
                sources.setdefault(stem, os.path.join(root, f))
    return sources, names


def text_of(path, cache):
    """The text of a test source, read once a check (cache: path -> text)."""
    if path not in cache:
        with open(path, encoding="utf-8", errors="replace") as f:
            cache[path] = f.read()
    return cache[path]


def check(header, doc, tests_dir):
    """The problems of doc against header and tests_dir, the number of
    functions and of functions with a row."""
    functions = header_functions(header)
    sources, names = test_files(tests_dir)
    problems, seen, cache = [], {}, {}
    if not functions:
        problems.append("include/projcurve.h: no PROJCURVE_API function found")
    for number, funcs, first, tests in doc_rows(doc):
        where = "docs/bad-input.md:%d" % number
        if re.search(r"`_[a-z]", first):
            problems.append("%s: an abbreviated name in %r (write each name in full)"
                            % (where, first))
        named_tests = TEST_RE.findall(tests)
        files = [f for f in FILE_RE.findall(tests) if not TEST_RE.fullmatch(f)]
        if not named_tests:
            problems.append("%s: no test named in %r" % (where, tests))
        for t in named_tests:
            if t not in sources:
                problems.append("%s: test %s does not exist (no tests/**/%s.c, .cpp, .py or .sh)"
                                % (where, t, t))
        for f in files:
            if f not in names:
                problems.append("%s: %s is no file under tests/" % (where, f))
        texts = [text_of(sources[t], cache) for t in named_tests if t in sources]
        for fn in funcs:
            if fn not in functions:
                problems.append("%s: %s is not a function of include/projcurve.h" % (where, fn))
                continue
            if fn in seen:
                problems.append("%s: %s already has a row (line %d)" % (where, fn, seen[fn]))
            seen.setdefault(fn, number)
            if texts and not any(re.search(r"\b%s\b" % fn, t) for t in texts):
                problems.append("%s: none of the tests %s calls %s"
                                % (where, ", ".join(named_tests), fn))
    for fn in sorted(functions - set(seen)):
        problems.append("docs/bad-input.md: no row for %s" % fn)
    return problems, len(functions), len(seen)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    problems, n_functions, n_rows = check(os.path.join(root, "include", "projcurve.h"),
                                          os.path.join(root, "docs", "bad-input.md"),
                                          os.path.join(root, "tests"))
    for p in problems:
        print(p)
    print("%d functions in the header, %d with a row, %d problems"
          % (n_functions, n_rows, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
