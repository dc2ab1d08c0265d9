#!/bin/sh
# SPDX-License-Identifier: MIT
# Issue 54 item 13: a run into a folder on a 1 MiB tmpfs with only FREE_KIB free (a filler file takes the
# rest): set-up ends with exit 2 and one line naming the space, "no space left on device (N bytes free in
# FOLDER) while writing FILE", never "fix its permissions", and no summary.json. Needs root (mount).
#   check_disk_setup.sh TRIBEX DECK FREE_KIB
tribex=$1 deck=$2 free=$3 d=disk_setup_${3}k
umount "$d" 2>/dev/null
rm -rf "$d" && mkdir "$d" && mount -t tmpfs -o size=1m tmpfs "$d" || { echo "cannot mount a small tmpfs (the test needs root)"; exit 1; }
head -c $(((1024 - free) * 1024)) /dev/zero > "$d/filler" 2>/dev/null
"$tribex" run "$deck" -o "$d/out" --quiet > "$d.txt" 2>&1
rc=$?
summary=absent
test -e "$d/out/summary.json" && summary=present
umount "$d"
cat "$d.txt"
echo "exit $rc, summary.json $summary"
test $rc -eq 2 && test $summary = absent && ! grep -q "fix its permissions" "$d.txt" &&
  grep -q "^error: .*no space left on device ([0-9]* bytes free in [^)]*$d/out)" "$d.txt"
