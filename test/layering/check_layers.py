#!/usr/bin/env python3
"""Checks that every #include of the project's sources points down the layers written in
docs/architecture.md (the table under "Layers"): a folder may include itself and every folder it
stands on, directly or through others. Prints each include that breaks the table and exits 1;
exits 0 when all of them keep it.

Usage: check_layers.py [REPO_ROOT]
"""
import os
import re
import sys

ROOTS = ["ompl_core", "ompl_mm", "ompl_phys", "ompl_mmphys", "ompl_bench", "apps", "benchmarks", "python"]
ROW = re.compile(r"^\|\s*`([^`]+)`\s*\|(.*)\|\s*$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def read_table(doc):
    """{folder: set of folders it stands on directly}, from the rows between the layer markers."""
    stands_on, inside = {}, False
    with open(doc, encoding="utf-8") as f:
        for line in f:
            if "<!-- layers:begin -->" in line:
                inside = True
            elif "<!-- layers:end -->" in line:
                inside = False
            elif inside:
                match = ROW.match(line.strip())
                if match:
                    stands_on[match.group(1)] = set(re.findall(r"`([^`]+)`", match.group(2)))
    if not stands_on:
        sys.exit(f"{doc}: no layer table between <!-- layers:begin --> and <!-- layers:end -->")
    for folder, below in stands_on.items():
        for name in below - set(stands_on):
            sys.exit(f"{doc}: '{folder}' stands on '{name}', which is not a row of the table")
    return stands_on


def allowed(stands_on):
    """{folder: every folder it may include}: itself and all it stands on, transitively."""
    reach = {}

    def below_and_self(folder):
        # the table is a stack, so the recursion ends at the bottom rows (stands on nothing)
        if folder not in reach:
            reach[folder] = {folder}.union(*(below_and_self(b) for b in stands_on[folder]))
        return reach[folder]

    for folder in stands_on:
        below_and_self(folder)
    return reach


def folder_of(path, folders):
    """The longest folder of the table that holds path, or None."""
    best = None
    for folder in folders:
        if (path == folder or path.startswith(folder + "/")) and (best is None or len(folder) > len(best)):
            best = folder
    return best


def resolve(include, source, root):
    """The repository path of an included project file, or None for a file outside the project."""
    for base in (os.path.dirname(source), "", "apps", "test"):
        candidate = os.path.normpath(os.path.join(base, include))
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "../.."))
    doc = os.path.join(root, "docs", "architecture.md")
    stands_on = read_table(doc)
    reach = allowed(stands_on)
    faults, checked = [], 0
    for top in ROOTS:
        for directory, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                source = os.path.relpath(os.path.join(directory, name), root)
                home = folder_of(source, stands_on)
                if home is None:
                    faults.append(f"{source}: its folder is not in the layer table of docs/architecture.md")
                    continue
                with open(os.path.join(root, source), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        target = resolve(match.group(1), source, root)
                        if target is None:
                            continue
                        checked += 1
                        there = folder_of(target, stands_on)
                        if there not in reach[home]:
                            faults.append(f"{source}:{number}: {home} must not include {target} ({there})")
    for fault in faults:
        print(fault)
    print(f"layers: {checked} includes checked, {len(faults)} against the table")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
