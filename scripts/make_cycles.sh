#!/usr/bin/env bash
# Writes the curve cycles O9011..O9019 into macros/ from the built ncurve (the spiral's O9010 is
# written by hand). A test checks that the shipped files are what ncurve gen writes.
set -euo pipefail
cd "$(dirname "$0")/.."
ncurve=./build/ncurve
for entry in ellipse:9011 parabola:9012 hyperbola:9013 involute:9014 sine:9015 cycloid:9016 trochoid:9017 \
             helix:9018 rotor:9019; do
  curve=${entry%%:*}
  program=${entry##*:}
  machine=()
  [ "$curve" = hyperbola ] && machine=(--machine profiles/fanuc-lathe.toml)
  "$ncurve" gen "$curve" --form cycle "${machine[@]}" --macro-only -o "macros/O$program.nc" > /dev/null
  echo "macros/O$program.nc: $curve"
done
