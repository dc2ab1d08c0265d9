# demo.i -- the deck `./tribex.sh demo` runs: the Hertz indentation of a silicon sphere
# (R = 27 nm) on a silicon flat (verification/hertz/hertz_coarse.i, about 2 minutes here);
# tribex.sh then draws the FE contact radius and approach against Hertz.
# Run:    build/bin/tribex run inputs/examples/demo.i -o demo_output
#         /usr/bin/python3 verification/hertz/compare.py demo_output --element-size 0.8 --plot demo.png
include ../../verification/hertz/hertz_coarse.i
