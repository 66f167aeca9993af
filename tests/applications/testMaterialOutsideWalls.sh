#!/usr/bin/env bash
# Issue 54, item 5: material outside the walls. A copy of tutorials' hydrostaticTank at 0.025 m
# with its water region drawn 0.05 m across the walls and `materialSide left;` on each wall (the
# advice particleMesh gives for auto's tie): particleMesh exited 0 and kept 8 material particles
# beside the tank's bottom corners, outside it (15-75 at other spacings); now it exits 1 naming
# the region, the count per wall patch and a position, and writes nothing. A position edited by
# hand below the bed of a good case: the solver ran it; now it refuses it at start, naming the
# origId, the file and the line.
# Usage: testMaterialOutsideWalls.sh <source dir> <build dir>
set -u
src=$1
bin=$2/bin
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$src/tests/applications/CheckFunctions.sh"  # check, has
export -f has

t=$work/tank
mkdir -p "$t" && cp -r "$src/tutorials/validation/hydrostaticTank/system" "$src/tutorials/validation/hydrostaticTank/constant" "$t"
dict=$t/system/particleMeshDict
sed -i 's/^spacing .*/spacing 0.025;/' "$dict"
sed -i 's/^writeFormat .*/writeFormat ascii;/' "$t/system/controlDict"
cp "$dict" "$work/particleMeshDict.good"

# The region across the walls: auto finds more material on the tank's side (left) as well.
sed -i 's/water { type box; min (0 0 0); max (0.4 0.4 0);/water { type box; min (-0.05 -0.05 0); max (0.45 0.4 0);/' "$dict"
out=$("$bin/particleMesh" -case "$t" 2>&1); rc=$?
check "materialSide auto: particleMesh exits 1 naming the region" bash -c "[ $rc -eq 1 ] && has \"region 'water' puts 8\" \"\$1\"" _ "$out"
sed -i 's/frictionAngle 0; }/frictionAngle 0; materialSide left; }/' "$dict"
out=$("$bin/particleMesh" -case "$t" 2>&1); rc=$?
check "materialSide left: particleMesh exits 1 (it exited 0 with 8 particles outside the tank)" test "$rc" -eq 1
check "... naming the region, its entry, the count per wall patch and a position" \
    bash -c "has \"region 'water' puts 8 of its\" \"\$1\" && has \"4 behind patch 'left', 4 behind patch 'right'\" \"\$1\" \
             && has 'particleMeshDict' \"\$1\" && has 'e.g. at (' \"\$1\"" _ "$out"
check "... and writes no 0/" test ! -e "$t/0"

# A good case, then a position edited by hand: 0.05 m below the bed.
cp "$work/particleMeshDict.good" "$dict"
"$bin/particleMesh" -case "$t" > "$work/log.particleMesh" 2>&1; rc=$?
check "the tank inside its walls: particleMesh exits 0" test "$rc" -eq 0
positions=$t/0/lagrangian/particles/positions
line=$(awk '/^\($/ { print NR + 1; exit }' "$positions")  # origId 0, a material particle
id=$(awk '/^\($/ { print $0; getline; print; exit }' "$t/0/lagrangian/particles/origId" | tail -1)
awk -v n="$line" 'NR == n { $0 = "(0.2 -0.05 0)" } { print }' "$positions" > "$work/positions" && mv "$work/positions" "$positions"
sed -i 's/^endTime .*/endTime 0.01;/' "$t/system/controlDict"
out=$("$bin/isphLandslideFoam" -case "$t" 2>&1); rc=$?
check "a position edited below the bed: the solver exits 1 at start (it ran)" test "$rc" -eq 1
check "... naming the origId, the file, the line and the wall's patch" \
    bash -c "has \"origId $id (line $line) is at (0.2 -0.05 0), 0.05 m behind wall patch 'bottom'\" \"\$1\" \
             && has '0/lagrangian/particles/positions' \"\$1\"" _ "$out"
check "... and writes no time" bash -c "! ls -d '$t'/0.* > /dev/null 2>&1"

echo "$passed passed, $fails failed"
[ "$fails" -eq 0 ] || { echo "$out"; exit 1; }
