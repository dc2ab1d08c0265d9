#!/bin/sh
# SPDX-License-Identifier: MIT
# usage: cli_end_to_end.sh TRIBEX WORKDIR
set -eu
tribex=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
py=/usr/bin/python3

"$tribex" friction-test --help > /dev/null
"$tribex" friction-test synth ringdown -o ring.csv --seed 5 2> /dev/null
"$tribex" friction-test calibrate ring.csv --json > ring.json
# Valid JSON, and Eq. 2.4 recovers the generating k = 0.38 N/m within 3 sigma of the fit alone
# (the mass uncertainty is the report's 6.7% on top).
$py -c '
import json, sys
d = json.load(open("ring.json"))
k = d["stiffness"]; w = d["omega0"]
kfit = 2 * k["value"] * w["uncertainty"] / w["value"]
assert abs(k["value"] - 0.38) < 3 * kfit, (k, kfit)
assert abs(k["uncertainty"] / k["value"] - 0.15 / 2.25) < 1e-3, k
'
"$tribex" friction-test synth static -o ramp.csv --seed 6 2> /dev/null
"$tribex" friction-test static ramp.csv --stiffness 4.5 --gap 2um --area 0.24mm^2 -o ramp.png > ramp.txt 2> /dev/null
grep -q '^mu_s' ramp.txt
test -s ramp.png || { echo "no PNG written"; exit 1; }
head -c 8 ramp.png | od -c | grep -q 'P   N   G' || { echo "ramp.png is not a PNG"; exit 1; }

# Dynamic: FOTAS mu_d = 0.28 at F_N + F_adh = 400 nN; the JSON carries friction_force, damping, mu_d.
"$tribex" friction-test synth dynamic -o dyn.csv --friction-force 112nN --static-force 136nN --seed 8 2> /dev/null
"$tribex" friction-test dynamic dyn.csv --stiffness 0.38 --normal-force 400nN --json > dyn.json
$py -c '
import json
d = json.load(open("dyn.json"))
for key in ("friction_force", "damping", "mu_d"):
    assert "uncertainty" in d[key], key
m = d["mu_d"]
assert abs(m["value"] - 0.28) < 3 * m["uncertainty"], m
assert abs(d["friction_force"]["value"] - 112e-9) < 3 * d["friction_force"]["uncertainty"], d
'

printf 'time[s],position[nm]\n0,1\n2,2\n1,3\n' > backwards.csv
set +e
"$tribex" friction-test calibrate backwards.csv 2> err.txt
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "expected exit 2, got $rc"; exit 1; }
grep -q 'backwards.csv:4: column .time. does not increase' err.txt || { cat err.txt; exit 1; }
[ "$(wc -l < err.txt)" -eq 1 ] || { echo "error is not one line"; cat err.txt; exit 1; }
echo "friction-test CLI end to end: ok"
