#!/usr/bin/env python3
"""End-to-end checks of the projcurve command.

usage: check_cli.py PART PROJCURVE SHARED_DIR WORK_DIR
PART is one of: usage, info, demo, cases. Exit 0 = pass, 1 = fail, 77 = skip.
"""
import json
import os
import shutil
import subprocess
import sys

failures = []


def run(args, expect_code, what):
    proc = subprocess.run(args, capture_output=True, text=True, timeout=240)
    if proc.returncode != expect_code:
        failures.append(f"{what}: exit {proc.returncode}, expected {expect_code}\n"
                        f"  command: {' '.join(args)}\n  stderr: {proc.stderr.strip()}")
    return proc


def check(cond, what):
    if not cond:
        failures.append(what)


def xml_valid(path):
    """xmllint --noout; None when xmllint is not installed."""
    if shutil.which("xmllint") is None:
        return None
    return subprocess.run(["xmllint", "--noout", path], capture_output=True).returncode == 0


def part_usage(exe, shared, work):
    case = os.path.join(shared, "cases", "song_yong_example1.igs")
    run([exe], 2, "no command")
    run([exe, "frobnicate"], 2, "unknown command")
    for cmd in ([], ["demo"], ["info"], ["project"]):
        out = run([exe] + cmd + ["--help"], 0, f"{' '.join(cmd) or 'top'} --help").stdout
        check("usage: projcurve" in out, f"{cmd} --help prints a usage line")
    run([exe, "info"], 2, "info without a file")
    run([exe, "info", "/nonexistent/x.igs"], 2, "info on a missing file")
    run([exe, "project", case], 2, "project without --dir/--orthogonal")
    run([exe, "project", case, "--dir", "1,2"], 2, "--dir with two numbers")
    run([exe, "project", case, "--dir", "0,0,-1", "--orthogonal"], 2, "both modes")
    run([exe, "project", case, "--dir", "0,0,-1", "--tol", "-1"], 2, "negative tolerance")
    run([exe, "project", case, "--dir", "0,0,-1", "--angle", "x"], 2, "non-numeric angle")
    run([exe, "project", case, "--dir", "0,0,-1", "--bogus"], 2, "unknown option")
    run([exe, "project", "/nonexistent/x.igs", "--dir", "0,0,-1"], 2, "missing input")
    run([exe, "project", case, "--dir", "0,0,0"], 1, "zero direction: projection fails")
    teapot = os.path.join(shared, "data", "real", "teapot_newell_spd.txt")
    run([exe, "project", teapot, "--dir", "0,0,-1"], 2, "surfaces without curves")


def part_info(exe, shared, work):
    expect = {"sunglasses_lens.igs": 9, "hammer.iges": 45, "linkrods.step": 18,
              "car_shell1.xml": 8, "teapot_newell_spd.txt": 32}
    for name, n in expect.items():
        out = run([exe, "info", os.path.join(shared, "data", "real", name)], 0, name).stdout
        check(f": {n} surface(s)" in out, f"info {name} reports {n} surfaces:\n{out[:300]}")
    out = run([exe, "info", os.path.join(shared, "data", "real", "hammer.iges")], 0, "").stdout
    check("skipped" in out and "IGES entity 144" in out, "info lists skipped trimmed surfaces")


def part_demo(exe, shared, work):
    os.makedirs(work, exist_ok=True)
    out = run([exe, "demo", "-o", work], 0, "demo").stdout
    check("Example 1" in out and "branch" in out, f"demo summary:\n{out}")
    for name, branches in (("example1", 1), ("freeform", 1)):
        with open(os.path.join(work, name + ".json")) as f:
            data = json.load(f)
        check(len(data["branches"]) == branches, f"{name}: {len(data['branches'])} branches")
        for b in data["branches"]:
            check(b["start"] == "curve_start" and b["end"] == "curve_end",
                  f"{name}: branch spans the curve ({b['start']} .. {b['end']})")
            check(b["t_range"][0] == 0 and b["t_range"][1] == 1, f"{name}: t_range {b['t_range']}")
            check(b["pieces"] > 0 and b["degree"] > 0, f"{name}: composed")
        svg = os.path.join(work, name + ".svg")
        valid = xml_valid(svg)
        if valid is None:
            print("xmllint not installed: SVG well-formedness not checked")
        else:
            check(valid, f"{svg} passes xmllint")
        info = run([exe, "info", os.path.join(work, name + ".igs")], 0, f"info {name}.igs").stdout
        # the input curve and the branch (read back through its 142)
        check("1 surface(s), 2 curve(s)" in info, f"{name}.igs read back:\n{info}")


def manifest(shared):
    rows = []
    with open(os.path.join(shared, "cases", "MANIFEST.tsv")) as f:
        header = None
        for line in f:
            fields = line.rstrip("\n").split("\t")
            if line.startswith("#"):
                header = [h.lstrip("#") for h in fields]
                continue
            if header and len(fields) >= len(header) - 1:
                rows.append(dict(zip(header, fields)))
    return rows


def part_cases(exe, shared, work):
    os.makedirs(work, exist_ok=True)
    for case in manifest(shared):
        name = case["name"]
        igs = os.path.join(shared, "cases", name + ".igs")
        out_json = os.path.join(work, name + ".json")
        out_svg = os.path.join(work, name + ".svg")
        args = [exe, "project", igs, "--tol", case["tol_dist"], "--angle", case["tol_angle_deg"],
                "--json", out_json, "--svg", out_svg, "-o", os.path.join(work, name + ".igs")]
        if case["mode"] == "orthogonal":
            args.append("--orthogonal")
        else:
            args += ["--dir", f"{case['dir_x']},{case['dir_y']},{case['dir_z']}"]
        if run(args, 0, name).returncode != 0:
            continue
        with open(out_json) as f:
            data = json.load(f)
        expected = int(case["expected_branches"])
        got = len(data["branches"])
        check(got == expected, f"{name}: {got} branches, MANIFEST expects {expected}")
        tol = float(case["tol_dist"])
        for b in data["branches"]:
            # traced points satisfy the projection condition far below eps_D,
            # and the composed curve stays within eps_D of them
            check(b["residual"] is not None and b["residual"] <= tol * 1e-3,
                  f"{name}: residual {b['residual']} > {tol * 1e-3}")
            check(b["deviation"] is not None and b["deviation"] <= tol,
                  f"{name}: deviation {b['deviation']} > eps_D {tol}")
        valid = xml_valid(out_svg)
        check(valid is None or valid, f"{out_svg} passes xmllint")


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    part, exe, shared, work = sys.argv[1:]
    if part in ("info", "cases", "usage") and not os.path.isdir(os.path.join(shared, "cases")):
        print(f"SKIP: {shared}/cases not found")
        return 77
    {"usage": part_usage, "info": part_info, "demo": part_demo, "cases": part_cases}[part](
        exe, shared, work)
    for f in failures:
        print("FAIL:", f)
    print(f"check_cli {part}: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
