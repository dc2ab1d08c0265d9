#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The AVX2 kernels' object file must define no code outside tribex::solver::hex8::avx2.

solver/hex8/avx2_kernels.cpp is the one file built with -mavx2. An inline function it emitted
out of line (a weak symbol) could be the copy the linker keeps for the whole program, and then
baseline code elsewhere would run AVX instructions on a CPU without them. flatten on the entry
point inlines everything; this check holds that: usage check_avx2_object.py "OBJECTS" (the
tribex_solver object list, ';'-separated)."""
import subprocess
import sys

objects = [p for p in sys.argv[1].split(";") if p.endswith("avx2_kernels.cpp.o")]
if len(objects) != 1:
    sys.exit(f"check_avx2_object: expected one avx2_kernels.cpp.o in the object list, found {len(objects)}")
out = subprocess.run(["nm", "-C", "--defined-only", objects[0]], check=True, capture_output=True, text=True).stdout
# Global and weak code (T, W, and i: GNU indirect functions) is what the linker can share between objects;
# local code (t: e.g. the sanitizer's module constructors, a .cold clone) cannot stand in for another object's.
code = [line for line in out.splitlines() if line.split()[1:2] and line.split()[1] in ("T", "W", "t", "i")]
outside = [line for line in code if line.split()[1] != "t" and "tribex::solver::hex8::avx2::" not in line]
print(f"{objects[0]}: {len(code)} code symbol(s) (t: local)")
for line in code:
    print("  " + line)
if not code:
    sys.exit("check_avx2_object: no code symbol at all (was the file built without -mavx2?)")
if outside:
    sys.exit("check_avx2_object: code outside tribex::solver::hex8::avx2 (an inline function emitted out of line):\n  " +
             "\n  ".join(outside))
print("PASS")
