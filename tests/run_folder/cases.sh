#!/bin/sh
# SPDX-License-Identifier: MIT
# The output folder as a resource the run owns (issue 54, items 1-8, 14, 15; README.md "The output
# folder"). usage: cases.sh CASE TRIBEX SOURCE_DIR, run in an empty working folder (CMakeLists.txt).
# Each case prints what it checks and exits 1 at the first broken promise.
set -u
case_name=$1 T=$2 SRC=$3
W=$SRC/inputs/examples/wave_bar.i MW=$SRC/tests/parallel/mpi_wave.i EW=$SRC/tests/output/exodus_wave.i
rm -rf work && mkdir work && cd work || exit 1  # a fresh folder of its own inside the working folder

fail() { echo "FAIL: $*"; exit 1; }
# A listing of a folder with every file's checksum (hidden files included): equal before and after
# means the folder was left as it was.
snapshot() { (cd "$1" && find . -type f -o -type p | LC_ALL=C sort | while read -r f; do
  if [ -p "$f" ]; then echo "fifo $f"; else echo "$(cksum < "$f") $f"; fi; done) }
expect_rc() {  # expect_rc WANT command...: the exit code; stderr kept in err.txt
  want=$1; shift
  "$@" > out.txt 2> err.txt; rc=$?
  cat out.txt err.txt
  [ "$rc" -eq "$want" ] || fail "exit $rc, expected $want: $*"
}
expect_err() { grep -q -- "$1" err.txt || fail "stderr lacks '$1'"; }  # after what the run did is checked

case $case_name in
item1_restart_of_other_run_leaves_folder)
  # A restart into a folder that holds another run: refused before history.csv is cut or log.txt appended.
  expect_rc 0 "$T" run "$W" -o X --quiet
  expect_rc 130 "$T" run "$MW" -o S --stop-at-step 50 --quiet
  snapshot X > before.txt
  expect_rc 2 "$T" run "$MW" --restart S/restart.h5 -o X --quiet
  snapshot X > after.txt
  cmp before.txt after.txt || fail "the refused restart changed folder X"
  expect_err "cannot resume into output folder X: it holds the outputs of run"
  ;;
item2_restart_into_same_mesh_other_run)
  # The same mesh, another run (E = 100 GPa) in folder A: refused naming both runs; A untouched.
  sed 's/youngs modulus = 160 GPa/youngs modulus = 100 GPa/' "$MW" > soft.i
  expect_rc 0 "$T" run soft.i -o A --quiet
  expect_rc 130 "$T" run "$MW" -o S --stop-at-step 50 --quiet
  snapshot A > before.txt
  expect_rc 2 "$T" run "$MW" --restart S/restart.h5 -o A --quiet
  snapshot A > after.txt
  cmp before.txt after.txt || fail "the refused restart changed folder A"
  a=$(sed -n 's/.*"run_id": "\([0-9a-f]*\)".*/\1/p' A/summary.json)
  s=$(sed -n 's/.*"run_id": "\([0-9a-f]*\)".*/\1/p' S/summary.json)
  [ -n "$a" ] && [ -n "$s" ] && [ "$a" != "$s" ] || fail "summary.json lacks distinct run ids ('$a', '$s')"
  expect_err "holds the outputs of run $a"
  expect_err "S/restart.h5 was written by run $s"
  # Its own folder resumes as before.
  expect_rc 0 "$T" run "$MW" --restart S/restart.h5 -o S --quiet
  ;;
item3_restart_allow_changed_other_mesh)
  # --restart-allow-changed with another mesh (same counts, another size): results.h5 holds one mesh,
  # so the run refuses S and starts new results files in a new folder.
  expect_rc 130 "$T" run "$MW" -o S --stop-at-step 50 --quiet
  sed 's/size = 4 4 60 nm/size = 4 4 66 nm/' "$MW" > longer.i
  snapshot S > before.txt
  expect_rc 2 "$T" run longer.i --restart S/restart.h5 -o S --restart-allow-changed --quiet
  snapshot S > after.txt
  cmp before.txt after.txt || fail "the refused restart changed folder S"
  expect_err "the mesh differs from the one its results files hold"
  expect_rc 0 "$T" run longer.i --restart S/restart.h5 -o N --restart-allow-changed --quiet
  /usr/bin/python3 - N/results.h5 <<'PY' || fail "N/results.h5 does not hold the new mesh"
import sys, h5py
f = h5py.File(sys.argv[1], "r")
z = f["/mesh/coordinates"][:, 2].max()
print("N/results.h5: mesh z max", z, f.attrs["length_unit"])
sys.exit(0 if abs(z - 66.0) < 1e-9 else 1)
PY
  ;;
item4_fresh_run_keeps_files_it_did_not_write)
  mkdir O && echo data > O/restart_notes.h5 && echo notes > O/log.txt
  "$T" run "$W" -o O --quiet > out.txt 2> err.txt
  [ "$(cat O/restart_notes.h5)" = data ] && [ "$(cat O/log.txt)" = notes ] || fail "a file the run did not write changed"
  expect_rc 2 "$T" run "$W" -o O --quiet
  [ "$(ls -A O | wc -l)" -eq 2 ] || fail "the refused run left files in O: $(ls -A O)"
  expect_err "holds log.txt, which this run would write but no earlier tribex run there wrote"
  # Without the clash the run goes on and keeps restart_notes.h5; a rerun removes only its own files.
  rm O/log.txt
  expect_rc 0 "$T" run "$W" -o O --quiet
  expect_rc 0 "$T" run "$W" -o O --quiet
  [ "$(cat O/restart_notes.h5)" = data ] || fail "restart_notes.h5 was removed or changed"
  grep -q "removed 6 file(s) of an earlier run" O/log.txt || fail "log.txt does not count the earlier run's 6 files"
  ;;
item5_input_mesh_in_output_folder)
  # A deck reading M/results.exo (an earlier run's results) run with -o M: the mesh is kept, twice.
  expect_rc 0 "$T" run "$EW" -o M --quiet
  cp M/results.exo mesh_copy.exo
  perl -0pe 's/\n\s*begin generated box (\w+).*?end generated box \1//sg; s/(begin finite element model \w+)/$1\n    database name = M\/results.exo/; s/^(\s*)format = both$/$1format = xdmf/mg' "$EW" > on_results.i
  expect_rc 0 "$T" run on_results.i -o M --quiet
  cp M/log.txt first_log.txt
  expect_rc 0 "$T" run on_results.i -o M --quiet
  cmp M/results.exo mesh_copy.exo || fail "the input mesh M/results.exo changed"
  grep -q "kept the earlier run's results.exo: the deck reads it" first_log.txt || fail "log.txt does not say results.exo was kept"
  # A deck that would write the file it reads is refused.
  sed 's/^\( *\)format = xdmf$/\1format = both/' on_results.i > writes_input.i
  expect_rc 2 "$T" run writes_input.i -o M --quiet
  cmp M/results.exo mesh_copy.exo || fail "the input mesh M/results.exo changed"
  expect_err "the deck reads results.exo in output folder M, which this run would write"
  ;;
item6_outputs_onto_fifo_device_folder)
  # Only regular files are replaced: a FIFO or folder as an output path is exit 2, one line, kept.
  mkfifo f.msh f.exo f.png f.csv && mkdir d.msh
  afm="$SRC/inputs/data/afm/di-1.di --channel 0 --window 187.5nm,187.5nm,8nm,8nm --element-size 2nm --depth 8nm"
  dmt="--model dmt --radius 27nm --reduced-modulus 84.1GPa"
  expect_rc 0 "$T" mesh afm $afm -o box.msh
  expect_rc 0 "$T" fit synth -o fr.csv --tau 100MPa --W 0.05J/m^2 --loads=-6nN,30nN $dmt
  for target in f.msh f.exo d.msh; do
    timeout 20 "$T" mesh convert box.msh $target > out.txt 2> err.txt; echo "exit $?" >> codes.txt; cat err.txt
    [ "$(wc -l < err.txt)" -le 1 ] || fail "more than one line"
  done
  timeout 20 "$T" mesh afm $afm -o f.msh 2> err_afm.txt; echo "exit $?" >> codes.txt
  timeout 20 "$T" fit friction fr.csv $dmt -o f.png 2> err_png.txt; echo "exit $?" >> codes.txt
  timeout 20 "$T" fit synth -o f.csv --tau 100MPa --W 0.05J/m^2 --loads=-6nN,30nN $dmt 2> err_csv.txt; echo "exit $?" >> codes.txt
  for f in f.msh f.exo f.png f.csv; do [ -p $f ] || fail "$f is no longer a FIFO"; done
  [ -d d.msh ] || fail "d.msh is no longer a folder"
  [ "$(sort -u codes.txt)" = "exit 2" ] || fail "exit codes $(cat codes.txt | tr '\n' ' '), expected 2 each"
  grep -q "f.msh is a FIFO (named pipe), not a regular file" err_afm.txt || fail "mesh afm: $(cat err_afm.txt)"
  grep -q "f.png is a FIFO (named pipe)" err_png.txt || fail "fit friction: $(cat err_png.txt)"
  grep -q "f.csv is a FIFO (named pipe)" err_csv.txt || fail "fit synth: $(cat err_csv.txt)"
  ;;
item7_second_run_into_live_folder)
  # A run into a folder another live run holds: exit 2 naming its pid and host; the first run unharmed.
  sed 's/termination time = 20 ps/termination time = 200 ps/' "$W" > long.i
  "$T" run long.i -o C --quiet > first.txt 2>&1 &
  first=$!
  i=0; while [ ! -s C/history.csv ] && [ $i -lt 300 ]; do sleep 0.05; i=$((i + 1)); done
  [ -s C/history.csv ] || fail "the first run did not start"
  expect_rc 2 "$T" run "$MW" -o C --quiet
  wait $first || fail "the first run failed: $(cat first.txt)"
  grep -q '"status": "normal termination"' C/summary.json || fail "the first run's summary.json"
  grep -q "deck long.i" C/log.txt || fail "log.txt is not the first run's"
  [ ! -e C/.tribex_lock ] || fail "the lock file stayed after the run"
  expect_err "is in use by another tribex run (pid $first on host $(uname -n)"
  ;;
item8_leftover_restart_part_removed)
  # A restart file cut by a SIGKILL leaves restart_0.h5.part (made here by hand: the same state);
  # the next fresh run removes it with the earlier run's other files.
  expect_rc 130 "$T" run "$MW" -o P --stop-at-step 50 --quiet
  head -c 100000 P/restart_0.h5 > P/restart_0.h5.part
  expect_rc 0 "$T" run "$MW" -o P --quiet
  [ ! -e P/restart_0.h5.part ] || fail "restart_0.h5.part stayed"
  ;;
item14_path_too_long_or_no_descriptors)
  # A folder path of 4,080 characters: the folder can be made, history_columns.csv in it cannot (PATH_MAX 4096).
  long=$(printf 'p%.0s' $(seq 1 200))
  out=base; while [ ${#out} -lt 3870 ]; do out=$out/$long; done
  out=$out/$(printf 'q%.0s' $(seq 1 $((4079 - ${#out}))))
  [ ${#out} -eq 4080 ] || fail "path of ${#out} characters"
  mkdir base
  expect_rc 2 "$T" run "$W" -o "$out" --quiet
  [ -z "$(ls -A base)" ] || fail "the refused run left $(ls -A base) in base"
  expect_err "(PATH_MAX)"
  # The descriptor limit: not in the sanitizer build (TRIBEX_SANITIZED, tests/run_folder/CMakeLists.txt),
  # whose runtime probes memory through a pipe and, with no descriptor left, reports a false invalid vptr.
  if [ -z "${TRIBEX_SANITIZED:-}" ]; then
    expect_rc 2 sh -c "ulimit -n 5; exec '$T' run '$W' -o U --quiet"
    [ ! -e U ] || fail "the refused run left U: $(ls -A U)"
    grep -q "free space" err.txt && fail "the message blames free space"
    expect_err "too many open files (ulimit -n)"
  fi
  ;;
item15_mesh_extensions)
  afm="$SRC/inputs/data/afm/di-1.di --channel 0 --window 187.5nm,187.5nm,8nm,8nm --element-size 2nm --depth 8nm"
  expect_rc 0 "$T" mesh afm $afm -o out.exo
  [ "$(head -c 3 out.exo)" = CDF ] || fail "out.exo is not Exodus II (netCDF)"
  expect_rc 0 "$T" mesh convert out.exo box.msh
  "$T" mesh convert out.exo x.txt; rc=$?
  [ ! -e x.txt ] || fail "x.txt was written"
  expect_rc 2 "$T" mesh convert out.exo x.txt
  expect_err "unknown mesh extension '.txt'; give a gmsh .msh or an Exodus II .exo, .e, .g or .gen file"
  expect_rc 2 "$T" mesh afm $afm -o out.vtk
  [ ! -e out.vtk ] || fail "out.vtk was written"
  expect_err "unknown mesh extension '.vtk'"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo "PASS $case_name"
