#!/bin/sh
# Seed 002's six circular-interpolation cases through `ncurve analyze circle` (docs/papers.md).
# Kv = 1.01 (m/min)/mm = 16.83 /s on X and Y; accelerations in m/s^2 as mm/s^2 x 1000; R 120 mm.
set -e
ncurve=${NCURVE:-./build/ncurve}
dir=$(mktemp -d)
for c in "a 140 1100 1100 30.4" "b 140 1100 750 40.7" "c 180 1100 750 50.2" \
         "d 140 750 750 39.6" "e 140 750 500 46.1" "f 180 750 500 55.2"; do
  set -- $c
  printf '[machine]\naxes = ["X", "Y", "Z"]\n[motion]\nacceleration = [%s, %s, 1000]\n[servo]\nkv = [16.83, 16.83, 16.83]\n' \
    "$3" "$4" > "$dir/$1.toml"
  echo "case $1: V $2 mm/min, a_x $3, a_y $4 mm/s^2, measured e_max $5 um"
  "$ncurve" analyze circle --radius 120 --feed "$2" --machine "$dir/$1.toml" | sed -n '3,7p'
done
rm -rf "$dir"
