# demo.i -- the deck `./tribex.sh demo` runs: for now the silent-boundary example
# (inputs/examples/silent_box.i); the Hertz and DMT indentations take its place as contact lands.
include silent_box.i
