#!/usr/bin/env bash
# sampleForces, toVTK, sampleLithostatic and sampleWallFilm as a user runs them: outputs, -plot with and without gnuplot, and
# errors that name the file, line and keyword. Usage: testPostProcessingUtilities.sh <bindir> <cases>
set -u
bin=$1
cases=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/postProcessing.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0
total=0
check() {  # check <description> <command...>: the command must succeed
  local what=$1; shift
  total=$((total + 1))
  if "$@"; then echo "PASS: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}

cp -r "$cases/hydrostaticTank" "$work/tank"
sed -i 's/^spacing .*/spacing 0.05;/' "$work/tank/system/particleMeshDict"
"$bin/particleMesh" -case "$work/tank" > "$work/log.particleMesh" 2>&1 || { cat "$work/log.particleMesh"; exit 1; }
cp -r "$work/tank/0" "$work/tank/0.5"

check "sampleForces -help exits 0" bash -c "'$bin/sampleForces' -help | grep -q 'Usage: sampleForces'"
check "toVTK -help exits 0" bash -c "'$bin/toVTK' -help | grep -q 'Usage: toVTK'"

"$bin/sampleForces" -case "$work/tank" > "$work/log1" 2>&1
check "sampleForces runs on every time" test $? -eq 0
dat="$work/tank/postProcessing/sampleForces/0/leftWall.dat"
check "the .dat is written under the first time" test -s "$dat"
check "the header names every column with its unit" \
  grep -q "^# Time \[s\]	Fx \[N/m\]	Fy \[N/m\]	Fn \[N/m\]	Ft \[N/m\]	Fpx \[N/m\].*	Mz \[N m/m\]	Mpz \[N m/m\]	Mdz \[N m/m\]	Mfz \[N m/m\]	nWall \[-\]$" "$dat"
check "one row per time" test "$(grep -vc '^#' "$dat")" -eq 2
check "a set with a width gives forces in N" grep -q "Fx \[N\]" "$work/tank/postProcessing/sampleForces/0/sideWalls.dat"
check "no temporary file is left" bash -c "[ -z \"\$(ls -A '$work/tank/postProcessing/sampleForces/0' | grep '^\\.')\" ]"

"$bin/sampleForces" -case "$work/tank" -latestTime > "$work/log2" 2>&1
check "-latestTime writes under its own time" test -s "$work/tank/postProcessing/sampleForces/0.5/leftWall.dat"

if command -v gnuplot > /dev/null 2>&1; then
  "$bin/sampleForces" -case "$work/tank" -plot > "$work/log3" 2>&1; rc=$?
  check "-plot draws a PNG with gnuplot" bash -c "[ $rc -eq 0 ] && head -c 4 '$work/tank/postProcessing/sampleForces/0/leftWall.png' | grep -q PNG"
else
  echo "(gnuplot is not installed here: the PNG check is skipped)"
fi
rm -rf "$work/tank/postProcessing"
out=$(PATH=/nonexistent "$bin/sampleForces" -case "$work/tank" -plot 2>&1); rc=$?
check "-plot without gnuplot exits non-zero and says so" bash -c "[ $rc -ne 0 ] && grep -q 'gnuplot is not installed' <<< \"\$1\"" _ "$out"
check "... after writing every .dat" test -s "$dat" -a -s "$work/tank/postProcessing/sampleForces/0/sideWalls.dat"
PATH=/nonexistent "$bin/sampleForces" -case "$work/tank" > /dev/null 2>&1
check "without -plot gnuplot is not needed" test $? -eq 0

cp "$work/tank/system/sampleForcesDict" "$work/dict.orig"
sed -i 's/patches     (leftWall);/patches     (leftWal);/' "$work/tank/system/sampleForcesDict"
out=$("$bin/sampleForces" -case "$work/tank" 2>&1); rc=$?
check "an unknown patch is an error naming it, the file and the line" \
  bash -c "[ $rc -ne 0 ] && grep -q \"no patch 'leftWal'\" <<< \"\$1\" && grep -q 'sampleForcesDict, line' <<< \"\$1\" && grep -q 'leftWall' <<< \"\$1\"" _ "$out"
rm "$work/tank/system/sampleForcesDict"
out=$("$bin/sampleForces" -case "$work/tank" 2>&1); rc=$?
check "a missing sampleForcesDict is an error naming it" bash -c "[ $rc -ne 0 ] && grep -q 'sampleForcesDict' <<< \"\$1\"" _ "$out"
cp "$work/dict.orig" "$work/tank/system/sampleForcesDict"

"$bin/toVTK" -case "$work/tank" > "$work/log4" 2>&1
check "toVTK converts every time" bash -c "[ -s '$work/tank/VTK/tank_0.vtp' ] && [ -s '$work/tank/VTK/tank_0.5.vtp' ]"
check "the .pvd lists them in order" bash -c "grep -o 'timestep=\"[^\"]*\"' '$work/tank/VTK/tank.pvd' | tr '\n' ' ' | grep -qx 'timestep=\"0\" timestep=\"0.5\" '"
out=$("$bin/toVTK" -case "$work/tank" -time 7 2>&1); rc=$?
check "a time that does not exist: nothing to do, exit 1 (a script can tell)" bash -c "[ $rc -eq 1 ] && grep -q 'no time directory selected.*nothing to do' <<< \"\$1\"" _ "$out"
out=$("$bin/toVTK" -case "$work/tank" -cloud sand 2>&1); rc=$?
check "a missing cloud is an error naming it" bash -c "[ $rc -ne 0 ] && grep -q \"cloud 'sand' not found\" <<< \"\$1\"" _ "$out"

# sampleLithostatic on the tank at rest (0 and its copy 0.5): water at rest is lithostatic
cat > "$work/tank/system/sampleLithostaticDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object sampleLithostaticDict; }
rho      1000;
height   1;
xMin     0.1;
xMax     0.3;
minDepth 0.1;
EOF
"$bin/sampleLithostatic" -case "$work/tank" > "$work/log5" 2>&1
check "sampleLithostatic runs on every time" test $? -eq 0
lith="$work/tank/postProcessing/sampleLithostatic/0/lithostatic.dat"
check "... a row per time, no displacement, p of the tank within 5 % of lithostatic" \
  awk '!/^#/ { n++; if (!($2 < 0.05 && $3 < 0.05 && $4 == 0)) bad++ } END { exit !(n == 2 && !bad) }' "$lith"
sed -i 's/^rho .*/rho -1000;/' "$work/tank/system/sampleLithostaticDict"
out=$("$bin/sampleLithostatic" -case "$work/tank" 2>&1); rc=$?
check "a negative rho is an error naming it, the file and the line" \
  bash -c "[ $rc -ne 0 ] && grep -q 'rho: expected a positive density' <<< \"\$1\" && grep -q 'sampleLithostaticDict, line' <<< \"\$1\"" _ "$out"
rm "$work/tank/system/sampleLithostaticDict"
out=$("$bin/sampleLithostatic" -case "$work/tank" 2>&1); rc=$?
check "a missing sampleLithostaticDict is an error naming it" bash -c "[ $rc -ne 0 ] && grep -q 'sampleLithostaticDict' <<< \"\$1\"" _ "$out"

# sampleWallFilm on the tank at rest: the water is thick against its steep side walls, so no
# film; the dictionary is optional, and a misspelt or bad entry is an error naming it
"$bin/sampleWallFilm" -case "$work/tank" > "$work/log6" 2>&1; rc=$?
check "sampleWallFilm runs without its dictionary, saying what it takes" \
  bash -c "[ $rc -eq 0 ] && grep -q 'no .*sampleWallFilmDict: restSpeed 0.01 m/s, maxThickness 2.5 spacings' '$work/log6'"
film="$work/tank/postProcessing/sampleWallFilm/0/wallFilm.dat"
nWater=$(awk 'FNR == 1 { s = 0 } !s && /^[0-9]+$/ { s = 1; next } s && $1 == "0" { n++ } END { print n }' "$work/tank/0/lagrangian/particles/kind")
check "... a row per time: no film, every water particle at rest" \
  awk -v n="$nWater" '!/^#/ { r++; if (!($2 == 0 && $3 == 0 && $6 == n)) bad++ } END { exit !(r == 2 && !bad && n > 0) }' "$film"
check "... and the film's particles beside it (none)" test "$(grep -vc '^#' "$work/tank/postProcessing/sampleWallFilm/0/wallFilmParticles.dat")" -eq 0
printf 'FoamFile { version 2.0; format ascii; class dictionary; object sampleWallFilmDict; }\nrestSped 0.02;\n' \
  > "$work/tank/system/sampleWallFilmDict"
out=$("$bin/sampleWallFilm" -case "$work/tank" 2>&1); rc=$?
check "a misspelt keyword is an error naming it and the file" \
  bash -c "[ $rc -ne 0 ] && grep -q 'restSped' <<< \"\$1\" && grep -q 'sampleWallFilmDict' <<< \"\$1\"" _ "$out"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object sampleWallFilmDict; }\nmaxThickness -1;\n' \
  > "$work/tank/system/sampleWallFilmDict"
out=$("$bin/sampleWallFilm" -case "$work/tank" 2>&1); rc=$?
check "a negative maxThickness is an error naming it, the file and the line" \
  bash -c "[ $rc -ne 0 ] && grep -q 'maxThickness: expected a positive number of spacings' <<< \"\$1\" && grep -q 'sampleWallFilmDict, line 2' <<< \"\$1\"" _ "$out"

echo "$((total - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
