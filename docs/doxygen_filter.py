#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Doxygen input filter for include/projcurve.h (docs/Doxyfile.in).

The C header documents itself in plain /* ... */ comments, which Doxygen
ignores. This filter, run by Doxygen on the header (the file itself is not
changed), turns them into documentation by where they stand:

  - the file's opening comment (before the include guard) becomes the
    file's documentation (\\file);
  - each banner (/* ==== */, /* Title */, /* ==== */) opens a group named by
    its title (a page of the reference) that runs to the next banner;
  - a comment right above a declaration documents it (/** ... */); above
    several declarations in a row (no blank line between), all of them (a
    member group, DISTRIBUTE_GROUP_DOC);
  - a comment after code on its line documents that code (/**< ... */);
  - a comment standing alone (a blank line after it) is added to its
    group's page, after the title;
  - a comment above a #define and a declaration (PROJCURVE_MAX_PIECE_POINTS
    before projcurve_result_piece) documents the declaration: the #define
    moves above the comment.

Usage: doxygen_filter.py FILE (Doxygen's INPUT_FILTER); writes to stdout.
"""
import re
import sys

BANNER = re.compile(r"^/\* =+ \*/\s*$")
TITLE = re.compile(r"^/\*\s*(.*?)\s*\*/\s*$")


def comment_end(lines, start):
    """Index of the line on which the comment opened on lines[start] closes."""
    col = lines[start].index("/*")
    if "*/" in lines[start][col + 2:]:
        return start
    for k in range(start + 1, len(lines)):
        if "*/" in lines[k]:
            return k
    raise SystemExit(f"doxygen_filter: comment opened on line {start + 1} never closes")


def is_code(line):
    s = line.strip()
    return bool(s) and not s.startswith("/*") and not s.startswith("#") and s != "}"


def group_id(title):
    """pc_ and the title's words before a colon or a parenthesis."""
    words = re.split(r"[:(]", title)[0].lower()
    return "pc_" + re.sub(r"[^a-z0-9]+", "_", words).strip("_")


def declarations(lines, start):
    """Lines start.. of the declarations that follow a comment (up to a blank
    line, a comment or a preprocessor line) and how many statements they
    hold; an enum or struct body counts as one."""
    end = start
    statements = 0
    if "{" in lines[start]:
        return start, 1
    while end < len(lines) and is_code(lines[end]):
        if lines[end].rstrip().endswith(";"):
            statements += 1
        end += 1
    return end - 1, statements


def doc_text(lines, start, end):
    """The comment's lines with its opener changed to /**; "e.g. " and
    "i.e. " do not end the brief description (JAVADOC_AUTOBRIEF)."""
    out = [re.sub(r"\b(e\.g|i\.e)\. ", r"\1.\\ ", line) for line in lines[start:end + 1]]
    out[0] = out[0].replace("/*", "/**", 1)
    return out


def filter_header(lines):
    out = []
    group_text = {}  # group id -> the lines of its lone comments
    group_open = False
    seen_file_doc = False
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.lstrip()
        # A banner: open the group of its title.
        if (BANNER.match(line) and i + 2 < len(lines) and TITLE.match(lines[i + 1])
                and BANNER.match(lines[i + 2])):
            title = TITLE.match(lines[i + 1]).group(1)
            # three lines for three, so that Doxygen's line numbers hold
            close = "/** @} */ " if group_open else ""
            out.append(f"{close}/** \\defgroup {group_id(title)} {title}\n")
            out.append(" * @{ */\n")
            out.append("\n")
            group_open = True
            i += 3
            continue
        # The end of the extern "C" block closes the last group.
        if group_open and line.startswith("#ifdef __cplusplus") and i + 1 < len(lines) \
                and lines[i + 1].startswith("}"):
            out.append("/** @} */\n")
            group_open = False
        if "/*" not in line or "*/" in line[:line.find("/*")]:
            out.append(line)
            i += 1
            continue
        col = line.index("/*")
        end = comment_end(lines, i)
        if line[:col].strip() and not line.lstrip().startswith(("#if", "#endif", "#else")):
            # After code: documents that code.
            out.append(line[:col] + line[col:].replace("/*", "/**<", 1))
            out.extend(lines[i + 1:end + 1])
            i = end + 1
            continue
        nxt = end + 1
        following = lines[nxt] if nxt < len(lines) else ""
        if following.startswith(("#ifndef", "#include")) and not seen_file_doc \
                and "SPDX" not in line:
            seen_file_doc = True
            body = doc_text(lines, i, end)
            body[0] = body[0].replace("/**", "/** \\file", 1)
            out.extend(body)
            i = end + 1
            continue
        # #defines between a comment and a declaration go above the comment.
        moved = []
        k = nxt
        while k < len(lines) and lines[k].startswith("#define"):
            k += 1
        if k > nxt and k < len(lines) and is_code(lines[k]):
            moved = lines[nxt:k]
            nxt = k
        if nxt < len(lines) and is_code(lines[nxt]):
            last, statements = declarations(lines, nxt)
            out.extend(moved)
            if statements > 1:
                body = doc_text(lines, i, end)
                body[0] = "/** @{ */ " + body[0]
                decls = list(lines[nxt:last + 1])
                decls[-1] = decls[-1].rstrip("\n") + " /** @} */\n"
                out.extend(body)
                out.extend(decls)
            else:
                out.extend(doc_text(lines, i, end))
                out.extend(lines[nxt:last + 1])
            i = last + 1
            continue
        if group_open and not following.strip() and "SPDX" not in line \
                and not BANNER.match(line):
            # Alone: part of the group's page.
            text = [" *\n", " * " + line[col + 2:].lstrip()] + lines[i + 1:end + 1]
            # each lone comment's own close goes (a group may have several)
            text[-1] = text[-1].replace("*/", "").rstrip() + "\n"
            group_text.setdefault(current_group(out), []).extend(text)
            out.extend("\n" for _ in range(i, end + 1))
            i = end + 1
            continue
        out.extend(lines[i:end + 1])
        i = end + 1
    if group_open:
        out.append("/** @} */\n")
    # The lone comments go to their group's page, after its title.
    result = []
    for line in out:
        m = re.search(r"\\defgroup (\S+)", line)
        if m and m.group(1) in group_text:
            text = group_text[m.group(1)]
            result.append(line)
            result.extend(text)
        else:
            result.append(line)
    return result


def current_group(out):
    for line in reversed(out):
        m = re.search(r"\\defgroup (\S+)", line)
        if m:
            return m.group(1)
    raise SystemExit("doxygen_filter: a group comment outside any group")


def main():
    if len(sys.argv) != 2:
        raise SystemExit("usage: doxygen_filter.py FILE")
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.readlines()
    sys.stdout.write("".join(filter_header(lines)))


if __name__ == "__main__":
    main()
