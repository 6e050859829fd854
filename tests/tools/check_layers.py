#!/usr/bin/env python3
"""Dependencies run downhill: a folder of src/core or src/app includes only folders of a lower
layer (or itself). The layers are the table below, lowest first; docs/architecture.md explains
them. Exits 1 listing every include that goes up or sideways, or a folder the table lacks.

    python3 tests/tools/check_layers.py            # the source tree next to this script
    python3 tests/tools/check_layers.py --self-test  # proves it catches an upward include
"""
import os
import re
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

# Folders on one line are one layer: they may not include each other.
CORE_LAYERS = [
    ["common"],
    ["geometry"],
    ["project"],
    ["contour"],
    ["kinematics", "construction", "spline", "follower"],
    ["analysis", "design"],
    ["fillet", "toolpath"],
    ["closure"],
    ["forces"],
    ["timing", "export", "evaluation"],
    ["io"],
]
# The app's folders sit on the whole core; the main window's parts (window/) on them all, and
# mainwindow.*, main.cpp and screenshot.* on top.
APP_LAYERS = [
    ["widgets"],
    ["messages"],
    ["document", "engine"],
    ["models", "files", "export"],
    ["views", "dialogs"],
    ["window"],
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/', re.M)


def rank_table(layers):
    return {folder: rank for rank, line in enumerate(layers) for folder in line}


def violations(root):
    problems = []
    core = rank_table(CORE_LAYERS)
    app = rank_table(APP_LAYERS)
    for part, ranks, below in (("src/core", core, {}), ("src/app", app, core)):
        base = os.path.join(root, part)
        for folder in sorted(os.listdir(base)):
            path = os.path.join(base, folder)
            if not os.path.isdir(path):
                continue
            if folder not in ranks:
                problems.append(f"{part}/{folder}: not in the layer table of {__file__}")
                continue
            for name in sorted(os.listdir(path)):
                if not name.endswith((".h", ".cpp")):
                    continue
                text = open(os.path.join(path, name), encoding="utf-8").read()
                for included in INCLUDE.findall(text):
                    if included == folder or included in below:
                        continue
                    if included not in ranks:
                        continue  # a library's header ("gtest/…"), or a generated one
                    if ranks[included] >= ranks[folder]:
                        problems.append(f"{part}/{folder}/{name} includes {included}/ "
                                        f"(layer {ranks[included]}, not below {ranks[folder]})")
    return problems


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        for folder in ("project", "design"):
            os.makedirs(os.path.join(tmp, "src", "core", folder))
        os.makedirs(os.path.join(tmp, "src", "app"))
        with open(os.path.join(tmp, "src", "core", "project", "validate.cpp"), "w") as f:
            f.write('#include "design/motion_design.h"\n')
        found = violations(tmp)
        if len(found) != 1 or "project/validate.cpp includes design/" not in found[0]:
            print("self-test failed:", found)
            return 1
    print("self-test: an upward include is caught")
    return 0


def main():
    if "--self-test" in sys.argv:
        return self_test()
    found = violations(ROOT)
    for problem in found:
        print(problem)
    if found:
        print(f"{len(found)} include(s) against the layers")
        return 1
    print("every include runs downhill")
    return 0


if __name__ == "__main__":
    sys.exit(main())
