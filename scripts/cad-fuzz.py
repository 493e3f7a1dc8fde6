#!/usr/bin/env python3
"""Damaged copies of a CAD file through `tessera info`, and what became of each.

Usage: scripts/cad-fuzz.py [--binary build/tessera-cad] [--input FILE] [--mode refs|numbers]
                           [--count N] [--seed S] [--timeout SECONDS] [--keep DIR]

Each copy of FILE (default: FreeCAD's SOT23.stp) has one to three changes made at random:
`refs` turns a STEP reference (#123) into a missing entity, another one, `$` or `*`; `numbers`
turns a number into 0, -1, 7, 99, 1e+300, 1e-300, -5 or a random one (STEP, IGES and .brep).
Every copy is read by `tessera info` (reading and converting, no mesh) and counted as:
  whole    exit 0 with the undamaged file's faces and edges
  changed  exit 0 with other counts (a face or edge lost, or the damage made a valid change)
  refused  exit 2, an error naming the file
  internal exit 70, limit exit 4, crash (a signal), timeout
docs/hardening.md ("Damaged CAD files") quotes what it printed. The same seed gives the same
copies. Python 3 alone: nothing to install.
"""
import argparse
import collections
import os
import random
import re
import subprocess
import sys
import tempfile

# `info`'s first line; "of zero area" since 2026-11-29 (older binaries can be compared too).
COUNTS = re.compile(rb": (\d+) faces \((\d+) converted, (?:\d+ of zero area, )?(\d+) failed\), (\d+) edges")
NUMBER = re.compile(r"(?<![#\w.])-?\d+(\.\d*)?([eE][-+]?\d+)?(?![\w.])")
REFERENCE = re.compile(r"#(\d+)")


def outcome(binary, path, timeout):
    try:
        run = subprocess.run([binary, "info", path], capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", None
    if run.returncode < 0:
        return "crash", None
    names = {0: "ok", 2: "refused", 4: "limit", 70: "internal"}
    counts = COUNTS.search(run.stdout)
    return names.get(run.returncode, "exit %d" % run.returncode), counts.groups() if counts else None


def damage(lines, mode, rng):
    lines = list(lines)
    for _ in range(rng.randint(1, 3)):
        for _attempt in range(100):
            k = rng.randrange(len(lines))
            pattern = REFERENCE if mode == "refs" else NUMBER
            # STEP references after the '=' only (the entity's own label stays)
            start = lines[k].find("=") + 1 if mode == "refs" else 0
            found = [m for m in pattern.finditer(lines[k]) if m.start() >= start]
            if not found:
                continue
            m = rng.choice(found)
            if mode == "refs":
                new = rng.choice(["#999999", "#%d" % rng.randint(1, 12000), "$", "*"])
            else:
                new = rng.choice(["0", "-1", "7", "99", "1e+300", "1e-300", "-5",
                                  "%.6g" % rng.uniform(-10, 10)])
            lines[k] = lines[k][:m.start()] + new + lines[k][m.end():]
            break
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/tessera-cad")
    parser.add_argument("--input", default="/usr/share/freecad/Mod/Idf/Idflibs/SOT23.stp")
    parser.add_argument("--mode", choices=["refs", "numbers"], default="refs")
    parser.add_argument("--count", type=int, default=150)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--keep", help="write the damaged copies here (default: a temporary folder)")
    args = parser.parse_args()
    if args.mode == "refs" and not args.input.lower().endswith((".stp", ".step")):
        sys.exit("cad-fuzz: --mode refs changes STEP references: give a .stp or .step file")
    with open(args.input, newline="") as f:
        lines = f.read().split("\n")
    extension = os.path.splitext(args.input)[1]
    reference = outcome(args.binary, args.input, args.timeout)
    if reference[0] != "ok" or reference[1] is None:
        sys.exit("cad-fuzz: the undamaged %s does not read (%s)" % (args.input, reference[0]))
    rng = random.Random(args.seed)
    tally = collections.Counter()
    examples = collections.defaultdict(list)
    folder = args.keep or tempfile.mkdtemp(prefix="cad-fuzz-")
    os.makedirs(folder, exist_ok=True)
    for k in range(args.count):
        path = os.path.join(folder, "damaged_%d%s" % (k, extension))
        with open(path, "w", newline="") as f:
            f.write("\n".join(damage(lines, args.mode, rng)))
        kind, counts = outcome(args.binary, path, args.timeout)
        if kind == "ok":
            kind = "whole" if counts == reference[1] else "changed"
        tally[kind] += 1
        examples[kind].append(k)
        if not args.keep:
            os.remove(path)
    if not args.keep:
        os.rmdir(folder)
    print("%s, %s, seed %d, %d copies, by %s:" % (os.path.basename(args.input), args.mode,
                                                  args.seed, args.count, args.binary))
    for kind in ["whole", "changed", "refused", "limit", "internal", "crash", "timeout"]:
        if tally[kind]:
            print("  %-8s %4d  (copies %s)" % (kind, tally[kind], " ".join(map(str, examples[kind][:8]))))
    return 1 if tally["crash"] or tally["internal"] else 0


if __name__ == "__main__":
    sys.exit(main())
