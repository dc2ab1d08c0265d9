#!/bin/sh
# SPDX-License-Identifier: MIT
# Bounds on every loop and every size read from a file or an argument (issue 54, items 9, 11, 12,
# 16, 17). usage: cases.sh CASE TRIBEX SOURCE_DIR, run in an empty working folder (CMakeLists.txt).
# Each case prints what it checks and exits 1 at the first broken promise.
set -u
case_name=$1 T=$2 SRC=$3
MW=$SRC/tests/parallel/mpi_wave.i W=$SRC/inputs/examples/wave_bar.i PY=/usr/bin/python3
rm -rf work && mkdir work && cd work || exit 1

fail() { echo "FAIL: $*"; exit 1; }
expect_rc() {  # expect_rc WANT command...: the exit code within 20 s (a hang is killed); stderr in err.txt
  want=$1; shift
  timeout -s KILL 20 "$@" > out.txt 2> err.txt; rc=$?
  cat out.txt err.txt
  [ "$rc" -eq "$want" ] || fail "exit $rc, expected $want: $*"
}
expect_err() { grep -q -- "$1" err.txt || fail "stderr lacks '$1'"; }
one_line() { [ "$(wc -l < err.txt)" -le 1 ] || fail "stderr has $(wc -l < err.txt) lines, expected one"; }
nothing_written() { [ ! -e "$1" ] || fail "$1 was left behind: $(ls -A "$1")"; }
# A restart file of the wave bar at step 50 (0.1 s), in S/.
restart_file() { expect_rc 130 "$T" run "$MW" -o S --stop-at-step 50 --quiet; }
# edited NAME KIND VALUE: a copy e.h5 of S/restart.h5 with one dataset replaced, resumed into R: exit 2 naming it.
edited() {
  $PY "$SRC/tests/bounds/edit_restart.py" S/restart.h5 e.h5 "$1" "$2" "$3" || fail "cannot edit the restart file"
  expect_rc 2 "$T" run "$MW" --restart e.h5 -o R --quiet
  expect_err "e.h5: error: restart dataset '$1'"
  one_line
  nothing_written R
}

case $case_name in
item9_tiny_output_increment)
  # A results or history time increment of 1e-30 s: check and run refuse it naming the line and the bound.
  for deck in results_time_increment_tiny history_time_increment_tiny; do
    for cmd in "check" "run -o O --quiet"; do
      expect_rc 2 "$T" $cmd "$SRC/tests/bad_decks/$deck.i"
      expect_err "$deck.i:[0-9]*:[0-9]*: error: 'time increment' 1e-30 s gives 2e+19 output times"
      expect_err "more than the limit of 1e+08"
      nothing_written O
    done
  done
  ;;
item9_restart_scheduling_values)
  # Scheduling values of an edited restart file: refused, not a hang in DeckRun::write_outputs.
  restart_file
  edited results_next real -1
  edited history_next real nan
  edited time real 1e300
  edited time real inf
  edited stable_dt real -inf
  # The file as written resumes.
  expect_rc 0 "$T" run "$MW" --restart S/restart.h5 -o S --quiet
  ;;
item11_restart_dataset_size)
  # A dataset stating 2^40 values (8.8 TB) in a 100 kB file: exit 2 naming the size, nothing allocated.
  restart_file
  edited u huge 0
  expect_err "states 1099511627776 values (8.8e+03 GB), more than the file's"
  ;;
item17_restart_edited_step_dt_type)
  restart_file
  edited step int -5
  expect_err "is not a step number"
  edited dt_n real -1
  edited dt_half real -1e-13
  edited u int same
  expect_err "is integer-typed; tribex writes it as float64"
  ;;
item12_argument_bounds)
  # Sizes from arguments, checked before allocating: exit 2 naming the bound, nothing written.
  expect_rc 2 "$T" pstd --sampling 1e-30m -o P --no-plots --quiet  # was SIGFPE (rc 136)
  expect_err "at --sampling 1e-30 m) needs 6e+24 samples, more than the limit of 1e8 samples"
  one_line
  expect_rc 2 "$T" pstd --sampling 1e-15m -o P --no-plots --quiet
  expect_err "more than the limit of 1e8 samples"
  expect_rc 2 "$T" pstd --substrate-length 1e3m -o P --no-plots --quiet
  expect_err "the synthetic substrate (--substrate-length 1000 m at --source-dx 1e-08 m) needs 1e+11 samples"
  nothing_written P
  expect_rc 2 "$T" fit synth --radius 27nm --A 0.5 --b 0.3 --tau 100MPa --W 0.05J/m^2 --points 2000000000 -o f.csv
  expect_err "--points 2000000000 is more than the limit of 10000000"
  expect_rc 2 "$T" friction-test synth ringdown --samples-per-cycle 2000000000 -o r.csv
  expect_err "= 2.4e+10 samples, more than the limit of 1e7"
  expect_rc 2 "$T" friction-test synth ringdown --cycles 1e9 -o r.csv
  expect_err "--cycles 1e+09 x --samples-per-cycle 50 = 5e+10 samples, more than the limit of 1e7"
  one_line
  nothing_written f.csv
  nothing_written r.csv
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
echo "PASS $case_name"
