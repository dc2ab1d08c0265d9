#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The layers include only what they may link (docs/architecture.md "Dependency direction"; the root
CMakeLists.txt links the libraries in the same direction): every `#include "LAYER/..."` in a source
file of inputs/keys/, inputs/, mesh/, materials/, contact/ or solver/ names its own layer or one it depends on.
inputs/keys/ (the header-only deck-key declaration) is a layer of its own under inputs/: the ground layer.
Fuzz targets compile their layer alone and follow the same rule.

usage: check_layers.py REPOSITORY
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from check_repo import report  # noqa: E402

KEYS = "inputs/keys"
ALLOWED = {
    KEYS: {KEYS},
    "materials": {"materials", KEYS},
    "inputs": {"inputs", "materials", "contact", "mesh", KEYS},
    "mesh": {"mesh"},
    "contact": {"contact", "mesh", KEYS},
    "solver": {"solver", "inputs", "mesh", "materials", "contact", KEYS},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"(inputs/keys|[a-z_]+)/')


def layer_of(path, layer, root):
    """inputs/keys/ files form their own layer, not the inputs layer."""
    inside_keys = path.relative_to(root).as_posix().startswith(KEYS + "/")
    return KEYS if inside_keys else layer


def main():
    root = pathlib.Path(sys.argv[1])
    problems, files = [], 0
    for layer, allowed in ALLOWED.items():
        for path in sorted((root / layer).rglob("*")):
            if path.suffix not in (".cpp", ".hpp") or layer_of(path, layer, root) != layer:
                continue
            files += 1
            for no, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                m = INCLUDE.match(line)
                if m and m.group(1) in ALLOWED and m.group(1) not in allowed:
                    problems.append(f"{path.relative_to(root)}:{no}: layer '{layer}' includes '{m.group(1)}/', "
                                    f"which it may not depend on (allowed: {', '.join(sorted(allowed))})")
                if m and m.group(1) == "tools":
                    problems.append(f"{path.relative_to(root)}:{no}: layer '{layer}' includes tools/")
    return report(problems, f"{files} files of {len(ALLOWED)} layers checked")


if __name__ == "__main__":
    sys.exit(main())
