#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Shows that check_bad_input.py can fail: docs/bad-input.md with a row
taken out, a function renamed, an abbreviation, a test renamed, a backticked
file that is not there and a test that does not call its function must each
give their problem, and the page as it is none.

Usage: check_bad_input_selftest.py [project root]   (exit 0: the checker works)
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_bad_input  # noqa: E402


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    header = os.path.join(root, "include", "projcurve.h")
    tests = os.path.join(root, "tests")
    with open(os.path.join(root, "docs", "bad-input.md"), encoding="utf-8") as f:
        page = f.read()
    row = "| `projcurve_face_destroy` | accepted | — | — | — | test_api_bad_input_shape |\n"
    mutations = [
        ("a row taken out", page.replace(row, ""), "no row for projcurve_face_destroy"),
        ("a function renamed", page.replace("`projcurve_face_destroy`", "`projcurve_face_free`"),
         "projcurve_face_free is not a function"),
        ("an abbreviation", page.replace("`projcurve_face_destroy`", "`_destroy`"),
         "an abbreviated name"),
        ("a test renamed", page.replace(row, row.replace("test_api_bad_input_shape",
                                                         "test_api_no_such_test")),
         "test test_api_no_such_test does not exist"),
        ("a file that is not there",
         page.replace(row, row.replace("test_api_bad_input_shape",
                                       "test_api_bad_input_shape, `no-such-corpus-file`")),
         "no-such-corpus-file is no file under tests/"),
        ("a test that does not call the function",
         page.replace(row, row.replace("test_api_bad_input_shape", "test_api_basics")),
         "none of the tests test_api_basics calls projcurve_face_destroy"),
        ("a row twice", page.replace(row, row + row), "projcurve_face_destroy already has a row"),
    ]
    failures = 0
    problems, _, _ = check_bad_input.check(header, os.path.join(root, "docs", "bad-input.md"), tests)
    if problems:
        print("the page as it is: %d problems, expected none" % len(problems))
        failures += 1
    if row not in page:
        print("the row the mutations change is not in the page")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        for what, text, expected in mutations:
            doc = os.path.join(tmp, "bad-input.md")
            with open(doc, "w", encoding="utf-8") as f:
                f.write(text)
            problems, _, _ = check_bad_input.check(header, doc, tests)
            if not any(expected in p for p in problems):
                print("%s: expected a problem with %r, got %r" % (what, expected, problems))
                failures += 1
            else:
                print("%s: found" % what)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
