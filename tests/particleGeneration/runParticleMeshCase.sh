#!/bin/bash
# Runs particleMesh on a copy of an example case (never in the source tree) and checks the
# result: exit 0, the cloud's fields written, sane counts in the log, the CSV export, and the
# same 0/ when run with one thread.
#   runParticleMeshCase.sh <particleMesh> <case folder> <min material> <max material>
# With <case folder> = "bad:<case folder>" the case is broken first (spacing -1): then
# particleMesh must fail, name the keyword, and write nothing.
set -u
exe=$1; source=$2; minMaterial=${3:-1}; maxMaterial=${4:-100000000}
bad=0
if [[ $source == bad:* ]]; then bad=1; source=${source#bad:}; fi
work=$(mktemp -d "${TMPDIR:-/tmp}/particleMesh.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -r "$source" "$work/case"
fail() { echo "FAIL: $*"; echo "---- log ----"; cat "$work/log" 2>/dev/null; exit 1; }

if [ $bad = 1 ]; then
    sed -i 's/^spacing .*/spacing -1;/' "$work/case/system/particleMeshDict"
    "$exe" -case "$work/case" -csv > "$work/log" 2>&1 && fail "particleMesh accepted spacing -1"
    grep -q "keyword 'spacing'" "$work/log" || fail "the error does not name the keyword"
    grep -q "particleMeshDict, line" "$work/log" || fail "the error does not name the file and line"
    [ -e "$work/case/0" ] && fail "0/ was written from bad input"
    [ -e "$work/case/postProcessing" ] && fail "postProcessing/ was written from bad input"
    echo "bad input rejected, nothing written"
    exit 0
fi

# Two threads for the main run whatever the caller set (Alltest gives each test one thread):
# the comparison with one thread below needs several here.
OMP_NUM_THREADS=2 "$exe" -case "$work/case" -csv > "$work/log" 2>&1 || fail "particleMesh exited with $?"
cloud="$work/case/0/lagrangian/particles"
for field in positions origId U p material kind patch normal mass cloudProperties; do
    [ -s "$cloud/$field" ] || fail "missing $cloud/$field"
done
line=$(grep "^Cloud 'particles':" "$work/log") || fail "no cloud summary in the log"
read -r total material wall dummy <<< "$(echo "$line" | sed -E 's/.*: ([0-9]+) particles \(([0-9]+) material, ([0-9]+) wall, ([0-9]+) dummy\).*/\1 \2 \3 \4/')"
[ "$total" -eq $((material + wall + dummy)) ] || fail "counts do not add up: $line"
[ "$material" -ge "$minMaterial" ] && [ "$material" -le "$maxMaterial" ] || fail "$material material particles, expected $minMaterial..$maxMaterial"
[ "$wall" -gt 0 ] && [ "$dummy" -ge "$wall" ] || fail "wall $wall / dummy $dummy"
grep -q "^Wall layers: 3" "$work/log" || fail "no wall layer line"
grep -Eq "closest pair 0\.[5-9][0-9]* dx|closest pair 1 dx" "$work/log" || fail "particles closer than dx/2: $(grep 'closest pair' "$work/log")"
head -12 "$cloud/positions" | grep -q FoamFile || fail "positions has no FoamFile header"
grep -q "^$total$" "$cloud/positions" || fail "positions does not hold $total values"
csv="$work/case/postProcessing/particleMesh/particles.csv"
[ "$(wc -l < "$csv")" -eq $((total + 1)) ] || fail "the CSV does not hold $total particles"
# The same output with one thread as with several.
cp -r "$source" "$work/serial"
OMP_NUM_THREADS=1 "$exe" -case "$work/serial" > "$work/serial.log" 2>&1 || fail "particleMesh failed with one thread"
diff -r "$work/case/0" "$work/serial/0" > /dev/null || fail "one thread and several give different 0/"
echo "$line"
