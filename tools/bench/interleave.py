#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Interleaved timing of two tribex binaries on the same `tribex bench block` command: the binaries
alternate, the order flipped every round, so that the host's drift falls on both alike.

usage: interleave.py ROUNDS OLD_BINARY NEW_BINARY -- [bench block arguments]
  e.g. interleave.py 16 /tmp/tribex_old build/bin/tribex -- --n 40 --element fully_integrated --steps 100

Prints each run's loop ns per element per step (the command's last line, ns_per_element_step=),
the medians and minima, the ratio of the medians and the paired ratio: the median of the per-round
ratios NEW/OLD (the two runs of a round are next to each other in time). Exit 2 on bad arguments or
a binary that does not run the benchmark.
"""
import statistics
import subprocess
import sys


def fail(message):
    print(f"interleave.py: {message}", file=sys.stderr)
    sys.exit(2)


def bench(binary, args):
    try:
        done = subprocess.run([binary, "bench", "block"] + args, capture_output=True, text=True)
    except OSError as error:
        fail(f"{binary}: {error.strerror}; give the path of a tribex executable")
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines or not lines[-1].startswith("ns_per_element_step="):
        first = (done.stderr.strip().splitlines() or ["no output"])[0]
        fail(f"{binary} bench block {' '.join(args)}: exit {done.returncode}: {first}")
    return float(lines[-1].split("=", 1)[1])


def main(argv):
    if len(argv) < 4 or argv[3] != "--":
        fail("usage: interleave.py ROUNDS OLD_BINARY NEW_BINARY -- [bench block arguments]")
    try:
        rounds = int(argv[0])
    except ValueError:
        fail(f"ROUNDS '{argv[0]}' is not a whole number; give e.g. 16")
    if rounds < 1:
        fail("ROUNDS must be at least 1")
    old, new, args = argv[1], argv[2], argv[4:]
    times = {old: [], new: []}
    for r in range(rounds):
        for binary in ((old, new) if r % 2 == 0 else (new, old)):
            times[binary].append(bench(binary, args))
    for label, binary in (("old", old), ("new", new)):
        print(f"{label} {binary}: " + " ".join(f"{t:.1f}" for t in times[binary]))
    m_old, m_new = statistics.median(times[old]), statistics.median(times[new])
    paired = sorted(b / a for a, b in zip(times[old], times[new]))
    print(f"ns/element/step median (min): old {m_old:.1f} ({min(times[old]):.1f}), new {m_new:.1f} "
          f"({min(times[new]):.1f}); ratio of medians {m_new / m_old:.3f}; paired ratio "
          f"{statistics.median(paired):.3f} (range {paired[0]:.3f}-{paired[-1]:.3f})")


if __name__ == "__main__":
    main(sys.argv[1:])
