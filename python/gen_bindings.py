#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generates python/projcurve/_generated.py from include/projcurve.h.

The header is the one source of the enum values, the numeric #defines, the
callback types and the prototypes of every exported function; the package
reads them from the generated module only, so nothing is copied by hand.

    gen_bindings.py            # rewrite projcurve/_generated.py
    gen_bindings.py --check    # exit 1 (and show a diff) when it is stale

The parser knows the header's own regular style (one prototype per
PROJCURVE_API declaration, enums as `typedef enum name { ... } name;`); a
declaration it cannot read is an error, never skipped silently.
"""
import argparse
import difflib
import os
import pprint
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
HEADER = os.path.join(ROOT, "include", "projcurve.h")
CMAKELISTS = os.path.join(ROOT, "CMakeLists.txt")
OUTPUT = os.path.join(HERE, "projcurve", "_generated.py")


class ParseError(Exception):
    pass


def strip_comments(text):
    # newlines kept, so that a #define after a comment stays on its own line
    text = re.sub(r"/\*.*?\*/", lambda m: " " + "\n" * m.group(0).count("\n"), text,
                  flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def parse_enums(text):
    enums = {}
    for name, body, alias in re.findall(
            r"typedef\s+enum\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", text, flags=re.S):
        if name != alias:
            raise ParseError("enum %s typedef'd as %s" % (name, alias))
        members, value = {}, -1
        for item in (i.strip() for i in body.split(",")):
            if not item:
                continue
            m = re.fullmatch(r"(\w+)(?:\s*=\s*(-?\d+))?", item)
            if not m:
                raise ParseError("enum %s: cannot read %r" % (name, item))
            value = int(m.group(2)) if m.group(2) is not None else value + 1
            members[m.group(1)] = value
        enums[name] = members
    return enums


def parse_defines(text):
    """Numeric #defines (integer literals and expressions of earlier ones)."""
    defines = {}
    for name, expr in re.findall(r"^\s*#\s*define\s+(PROJCURVE_\w+)[ \t]+([^\n]+)$", text,
                                 flags=re.M):
        expr = expr.strip()
        if name == "PROJCURVE_API" or expr.startswith("__"):
            continue
        expr = re.sub(r"\b(\d+)[uU]?[lL]*\b", r"\1", expr)
        expr = re.sub(r"\bPROJCURVE_\w+\b",
                      lambda m: str(defines[m.group(0)]) if m.group(0) in defines else "?", expr)
        if not re.fullmatch(r"[0-9+\-*/() ]+", expr):
            continue  # not numeric (attributes, strings)
        defines[name] = int(eval(expr, {"__builtins__": {}}))  # digits and operators only
    return defines


# C parameter / return types -> the package's type codes (mapped to ctypes
# in projcurve/_lib.py).
SCALARS = {
    "void": "void", "int": "int", "unsigned": "uint", "unsigned int": "uint",
    "size_t": "size_t", "double": "double", "float": "float", "long": "long",
    "unsigned long": "ulong", "long long": "longlong", "unsigned long long": "ulonglong",
    "char": "char", "unsigned char": "uchar", "int32_t": "int32", "uint32_t": "uint32",
    "int64_t": "int64", "uint64_t": "uint64", "ptrdiff_t": "ptrdiff",
}


def type_code(ctype, enums, callbacks, where):
    """One C type (without the parameter name) -> a type code."""
    t = re.sub(r"\bconst\b", " ", ctype)
    stars = t.count("*")
    base = " ".join(t.replace("*", " ").split())
    if base in enums:
        base_code = "int"
    elif base in callbacks:
        base_code = "fn:" + base
    elif base in SCALARS:
        base_code = SCALARS[base]
    elif re.fullmatch(r"projcurve_\w+", base):
        # an opaque handle type: only ever used through pointers
        if stars == 0:
            raise ParseError("%s: opaque type %s by value" % (where, base))
        base_code, stars = "handle", stars - 1
    else:
        raise ParseError("%s: unknown type %r" % (where, ctype))
    if base_code == "char" and stars == 1:
        return "string"
    if base_code == "void" and stars >= 1:
        base_code, stars = "handle", stars - 1
    return base_code + "*" * stars


def split_param(param, where):
    """'const double t_range[2]' -> ('const double *', 't_range')."""
    m = re.fullmatch(r"(.*?)(\w+)\s*(\[\s*\w*\s*\])?", param.strip(), flags=re.S)
    if not m or not m.group(1).strip():
        raise ParseError("%s: cannot read parameter %r" % (where, param))
    ctype = m.group(1)
    if m.group(3):
        ctype += "*"
    return ctype, m.group(2)


def parse_params(params, enums, callbacks, where):
    params = " ".join(params.split())
    if params in ("void", ""):
        return []
    out = []
    for p in params.split(","):
        ctype, name = split_param(p, where)
        out.append((name, type_code(ctype, enums, callbacks, where)))
    return out


def parse_callbacks(text, enums):
    callbacks = {}
    pattern = r"typedef\s+([\w\s\*]+?)\s*\(\s*\*\s*(\w+)\s*\)\s*\((.*?)\)\s*;"
    for ret, name, params in re.findall(pattern, text, flags=re.S):
        callbacks[name] = (type_code(ret, enums, {}, name),
                           [code for _, code in parse_params(params, enums, {}, name)])
    return callbacks


def parse_functions(text, enums, callbacks):
    functions = {}
    decls = re.findall(r"PROJCURVE_API\s+([^;{}]*?)\s*;", text, flags=re.S)
    for decl in decls:
        m = re.fullmatch(r"(.*?)\b(projcurve_\w+)\s*\((.*)\)", decl, flags=re.S)
        if not m:
            raise ParseError("cannot read declaration %r" % decl)
        ret, name, params = m.groups()
        functions[name] = (type_code(ret, enums, callbacks, name),
                           parse_params(params, enums, callbacks, name))
    if len(functions) != len(decls):
        raise ParseError("a function is declared twice")
    return functions


def parse_version(cmake_text):
    m = re.search(r"project\(\s*projcurve\s+VERSION\s+(\d+)\.(\d+)\.(\d+)", cmake_text)
    if not m:
        raise ParseError("CMakeLists.txt: no project(projcurve VERSION x.y.z)")
    return "%s.%s.%s" % m.groups()


def generate():
    with open(HEADER, encoding="utf-8") as f:
        raw = f.read()
    with open(CMAKELISTS, encoding="utf-8") as f:
        version = parse_version(f.read())
    text = strip_comments(raw)
    defines = parse_defines(text)
    enums = parse_enums(text)
    callbacks = parse_callbacks(text, enums)
    functions = parse_functions(text, enums, callbacks)

    def block(name, value):
        return "%s = %s\n" % (name, pprint.pformat(value, width=96, sort_dicts=False))

    return ("# SPDX-License-Identifier: BSD-3-Clause\n"
            "# Generated by python/gen_bindings.py from include/projcurve.h and the\n"
            "# project version in CMakeLists.txt. Do not edit: run the script (the test\n"
            "# python_generated_current fails while this file is stale).\n"
            "# Type codes: see _lib.py (handle = an opaque pointer, 'x*' = pointer to x,\n"
            "# 'fn:name' = a callback type of CALLBACKS, string = const char *).\n\n"
            + block("VERSION", version) + "\n"
            + block("ENUMS", enums) + "\n"
            + block("DEFINES", defines) + "\n"
            + block("CALLBACKS", callbacks) + "\n"
            + block("FUNCTIONS", {k: (r, tuple(tuple(p) for p in ps))
                                  for k, (r, ps) in functions.items()}))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="fail when the module is stale")
    args = ap.parse_args()
    try:
        new = generate()
    except ParseError as e:
        print("gen_bindings: include/projcurve.h: %s" % e, file=sys.stderr)
        return 2
    if args.check:
        try:
            with open(OUTPUT, encoding="utf-8") as f:
                old = f.read()
        except OSError as e:
            print("gen_bindings: %s" % e, file=sys.stderr)
            return 1
        if old != new:
            sys.stdout.writelines(difflib.unified_diff(
                old.splitlines(True), new.splitlines(True), "committed", "regenerated"))
            print("python/projcurve/_generated.py is stale: run python/gen_bindings.py",
                  file=sys.stderr)
            return 1
        print("python/projcurve/_generated.py is current (%d lines)" % new.count("\n"))
        return 0
    with open(OUTPUT, "w", encoding="utf-8") as f:
        f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
