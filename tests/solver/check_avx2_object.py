#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The AVX2 and AVX-512 kernels' object files must define no code outside their own namespaces.

solver/hex8/avx2_kernels.cpp and avx512_kernels.cpp are the files built with -mavx2 and -mavx512f.
An inline function one of them emitted out of line (a weak symbol) could be the copy the linker keeps
for the whole program, and then baseline code elsewhere would run AVX or AVX-512 instructions on a
CPU without them. flatten on each entry point inlines everything; this check holds that: usage
check_avx2_object.py "OBJECTS" (the tribex_solver object list, ';'-separated)."""
import subprocess
import sys

KERNELS = {"avx2_kernels.cpp.o": "tribex::solver::hex8::avx2::", "avx512_kernels.cpp.o": "tribex::solver::hex8::avx512::"}
failed = False
for suffix, namespace in KERNELS.items():
    objects = [p for p in sys.argv[1].split(";") if p.endswith("/" + suffix)]
    if len(objects) != 1:
        sys.exit(f"check_avx2_object: expected one {suffix} in the object list, found {len(objects)}")
    out = subprocess.run(["nm", "-C", "--defined-only", objects[0]], check=True, capture_output=True, text=True).stdout
    # Global and weak code (T, W, and i: GNU indirect functions) is what the linker can share between objects;
    # local code (t: e.g. the sanitizer's module constructors, a .cold clone) cannot stand in for another object's.
    code = [line for line in out.splitlines() if line.split()[1:2] and line.split()[1] in ("T", "W", "t", "i")]
    outside = [line for line in code if line.split()[1] != "t" and namespace not in line]
    print(f"{objects[0]}: {len(code)} code symbol(s) (t: local)")
    for line in code:
        print("  " + line)
    if not code:
        print(f"check_avx2_object: {suffix}: no code symbol at all (was the file built without its -m flag?)")
        failed = True
    if outside:
        print(f"check_avx2_object: {suffix}: code outside {namespace} (an inline function emitted out of line):\n  " +
              "\n  ".join(outside))
        failed = True
if failed:
    sys.exit(1)
print("PASS")
