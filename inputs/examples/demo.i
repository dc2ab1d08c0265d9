# demo.i -- the deck `./tribex.sh demo` runs: the DMT indentation of a silicon sphere (R = 27 nm)
# on a silicon flat with Lennard-Jones adhesion, W = 0.05 J/m^2, loaded then withdrawn past pull-off
# (verification/dmt/dmt_coarse.i). tribex.sh runs the W = 0 twin (verification/hertz/hertz_coarse.i)
# beside it on the other core, then draws the contact radius against the load for both, with the
# DMT and Hertz curves.
# Run:    build/bin/tribex run inputs/examples/demo.i -o demo_output/dmt
#         build/bin/tribex run verification/hertz/hertz_coarse.i -o demo_output/hertz
#         /usr/bin/python3 verification/dmt/compare.py demo_output/dmt --element-size 0.8 \
#             --hertz-output demo_output/hertz --plot demo_output/demo.png
include ../../verification/dmt/dmt_coarse.i
