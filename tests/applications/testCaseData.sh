#!/usr/bin/env bash
# Issue 54, "nothing lost, nothing mixed": a case's data under misuse and faults, each probe as
# the issue measured it on the unchanged code, and what the applications do now.
# Usage: testCaseData.sh <source dir> <build dir>
set -u
src=$1
bin=$2/bin
work=$(mktemp -d)
background=
trap '[ -n "$background" ] && kill -KILL $background 2>/dev/null; rm -rf "$work"' EXIT
. "$src/tests/applications/CheckFunctions.sh"  # check, has
count() { grep -m1 -A2 '^[0-9]' "$1" | head -1; }  # the size line of an ascii field file
sum() { cat "$1"/lagrangian/particles/* | md5sum; }  # a time's particles, as a checksum

# ---- reconstructPar: a processor folder missing, a time damaged, a root time not its own ----
t=$work/tank
cp -r "$src/tests/postProcessing/cases/hydrostaticTank" "$t"
sed -i 's/^spacing .*/spacing 0.025;/' "$t/system/particleMeshDict"
"$bin/particleMesh" -case "$t" > "$work/log.particleMesh" 2>&1 || { cat "$work/log.particleMesh"; exit 1; }
cp -r "$t/0" "$t/0.1"
cat > "$t/system/decomposeParDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method zoltan;
zoltanCoeffs { algorithm RCB; }
DICT
"$bin/decomposePar" -case "$t" > "$work/log.decomposePar" 2>&1 || { cat "$work/log.decomposePar"; exit 1; }
n=$(count "$t/0/lagrangian/particles/origId")
check "decomposePar records the decomposition in each processor folder" \
    bash -c "grep -q 'numberOfSubdomains 2;' '$t/processor1/decomposition' && grep -q 'particles $n;' '$t/processor0/decomposition'"
before=$(sum "$t/0")
mv "$t/processor1" "$work/processor1"
out=$("$bin/reconstructPar" -case "$t" 2>&1); rc=$?
check "processor1 missing: reconstructPar exits 1 (it exited 0 and wrote half the particles into 0/)" test "$rc" -eq 1
check "... naming the missing folder and the record" \
    bash -c "grep -q 'processor1 is missing' <<< \"\$1\" && grep -q 'numberOfSubdomains 2' <<< \"\$1\"" _ "$out"
check "... 0/ as particleMesh wrote it" test "$(sum "$t/0")" = "$before"
out=$("$bin/toVTK" -case "$t" -parallel 2>&1); rc=$?
check "toVTK -parallel refuses it too" bash -c "[ $rc -eq 1 ] && grep -q 'processor1 is missing' <<< \"\$1\"" _ "$out"
rm "$t"/processor0/decomposition   # a case decomposed before the record: decomposeParDict says 2
out=$("$bin/reconstructPar" -case "$t" 2>&1); rc=$?
check "... and without the record, by decomposeParDict's numberOfSubdomains" \
    bash -c "[ $rc -eq 1 ] && grep -q 'decomposeParDict' <<< \"\$1\" && [ '$(sum "$t/0")' = '$before' ]" _ "$out"
mv "$work/processor1" "$t/processor1"
"$bin/reconstructPar" -case "$t" > "$work/log.reconstructPar" 2>&1; rc=$?
check "the whole decomposition reconstructs (exit 0), 0/ the same particles" \
    bash -c "[ $rc -eq 0 ] && [ '$(count "$t/0/lagrangian/particles/origId")' = '$n' ]"
sed -i "s/^particles .*/particles $((n + 5));/" "$t/processor1/decomposition"
out=$("$bin/reconstructPar" -case "$t" 2>&1); rc=$?
check "a time with fewer particles than the record: exit 1, naming both counts" \
    bash -c "[ $rc -eq 1 ] && grep -q 'hold $n particles, the decomposition has $((n + 5))' <<< \"\$1\"" _ "$out"
sed -i "s/^particles .*/particles $n;/" "$t/processor1/decomposition"
head -c 300 "$t/processor1/0.1/lagrangian/particles/U" > "$work/U" && mv "$work/U" "$t/processor1/0.1/lagrangian/particles/U"
out=$("$bin/reconstructPar" -case "$t" 2>&1); rc=$?
check "a truncated field in one processor: exit 1 (it skipped the time and exited 0)" test "$rc" -eq 1
check "... naming the time, the file and -skipDamaged" \
    bash -c "grep -q 'time 0.1 cannot be read' <<< \"\$1\" && grep -q 'processor1/0.1/lagrangian/particles/U' <<< \"\$1\" && grep -q -- -skipDamaged <<< \"\$1\"" _ "$out"
out=$("$bin/reconstructPar" -case "$t" -skipDamaged 2>&1); rc=$?
check "... -skipDamaged: the others reconstructed, exit 0, the skip said" \
    bash -c "[ $rc -eq 0 ] && grep -q 'time 0.1 is skipped' <<< \"\$1\" && grep -q 'Time = 0: $n particles' <<< \"\$1\"" _ "$out"
check "... -help names both options" \
    bash -c "'$bin/reconstructPar' -help | grep -q -- -skipDamaged && '$bin/reconstructPar' -help | grep -q -- -force"
rm -r "$t/processor1/0.1" && cp -r "$t/processor1/0" "$t/processor1/0.1"  # repaired
other=$work/other
mkdir -p "$other" && cp -r "$t/system" "$t/constant" "$other"
sed -i 's/^spacing .*/spacing 0.03;/' "$other/system/particleMeshDict"
"$bin/particleMesh" -case "$other" > "$work/log.particleMesh.other" 2>&1
rm -rf "$t/0.1" && cp -r "$other/0" "$t/0.1"   # a root time of another particleMesh
before=$(sum "$t/0.1")
out=$("$bin/reconstructPar" -case "$t" -time 0.1 2>&1); rc=$?
check "a root time with another particle count is not replaced: exit 1" \
    bash -c "[ $rc -eq 1 ] && grep -q 'not replaced' <<< \"\$1\" && [ '$(sum "$t/0.1")' = '$before' ]" _ "$out"
"$bin/reconstructPar" -case "$t" -time 0.1 -force > /dev/null 2>&1; rc=$?
check "... -force replaces it" bash -c "[ $rc -eq 0 ] && [ '$(count "$t/0.1/lagrangian/particles/origId")' = '$n' ]"
mv "$t/processor1" "$work/processor1"
out=$("$bin/reconstructPar" -case "$t" -time 0.1 -force 2>&1); rc=$?
check "... and reconstructs from less than the whole, warning" \
    bash -c "[ $rc -eq 0 ] && grep -q 'less than the whole' <<< \"\$1\"" _ "$out"
mv "$work/processor1" "$t/processor1"

# ---- decomposePar: far more subdomains than particles -----------------------------------
sed -i 's/^numberOfSubdomains .*/numberOfSubdomains 100;/' "$t/system/decomposeParDict"
out=$("$bin/decomposePar" -case "$t" -force -time 0 2>&1); rc=$?
check "numberOfSubdomains 100 for $n particles: a warning (1000 gave none)" \
    bash -c "[ $rc -eq 0 ] && grep -q '100 subdomains for .* material particles' <<< \"\$1\" && grep -q 'more than make sense' <<< \"\$1\"" _ "$out"
most=$(grep -o 'numberOfSubdomains [0-9]* or fewer' <<< "$out" | awk '{ print $2 }')
sed -i "s/^numberOfSubdomains .*/numberOfSubdomains $most;/" "$t/system/decomposeParDict"
out=$("$bin/decomposePar" -case "$t" -force -time 0 2>&1); rc=$?
check "... none for the $most subdomains it advises" bash -c "[ $rc -eq 0 ] && [ '$most' -ge 2 ] && ! grep -q 'more than make sense' <<< \"\$1\"" _ "$out"

# ---- post-processing with nothing to do -------------------------------------------------
out=$("$bin/sampleForces" -case "$t" -time 7 2>&1); rc=$?
check "sampleForces -time 7 (no such time): exit 1, nothing to do" \
    bash -c "[ $rc -eq 1 ] && grep -q 'nothing to do' <<< \"\$1\"" _ "$out"

# ---- the solver: a dam break at a coarse spacing ------------------------------------------
d=$work/damBreak
mkdir -p "$d"
cp -r "$src/tutorials/validation/damBreak/system" "$src/tutorials/validation/damBreak/constant" "$d"
sed -i 's/^spacing .*/spacing 0.005715;/' "$d/system/particleMeshDict"
sed -i 's/^writeFormat .*/writeFormat ascii;/; s/^writePrecision .*/writePrecision 17;/; s/^writeInterval .*/writeInterval 0.01;/' \
    "$d/system/controlDict"
"$bin/particleMesh" -case "$d" > "$work/log.particleMesh.d" 2>&1 || { cat "$work/log.particleMesh.d"; exit 1; }
fresh() {  # fresh <dir>: a copy of the dam break at time 0
    rm -rf "$1"; mkdir -p "$1"; cp -r "$d/system" "$d/constant" "$d/0" "$1"
}

# Two solvers on one case.
c=$work/twice
fresh "$c"
sed -i 's/^endTime .*/endTime 10;/' "$c/system/controlDict"
"$bin/isphLandslideFoam" -case "$c" > "$work/log.first" 2>&1 &
background=$!
for i in $(seq 100); do [ -e "$c/isphLock" ] && break; sleep 0.1; done
check "a running solver holds the case lock (pid, host, start, command)" \
    bash -c "grep -q '^pid  *$background\$' '$c/isphLock' && grep -q '^host ' '$c/isphLock' && grep -q '^started ' '$c/isphLock' && grep -q '^command .*isphLandslideFoam' '$c/isphLock'"
out=$("$bin/isphLandslideFoam" -case "$c" 2>&1); rc=$?
check "a second solver on the case: exit 1 (both ran and exited 0)" test "$rc" -eq 1
check "... naming the holder" bash -c "grep -q 'is in use' <<< \"\$1\" && grep -q 'process $background' <<< \"\$1\"" _ "$out"
out=$("$bin/particleMesh" -case "$c" 2>&1); rc=$?
check "... particleMesh too" bash -c "[ $rc -eq 1 ] && grep -q 'is in use' <<< \"\$1\"" _ "$out"
kill -KILL "$background"; wait "$background" 2>/dev/null; background=
check "kill -9 leaves the lock" test -e "$c/isphLock"
latest=$("$bin/isphListTimes" -case "$c" -latestTime 2>/dev/null)
sed -i "s/^endTime .*/endTime $(awk -v t="$latest" 'BEGIN { print t + 0.002 }');/" "$c/system/controlDict"
"$bin/isphLandslideFoam" -case "$c" > "$work/log.third" 2>&1; rc=$?
check "the next solver takes it over (exit 0), saying so" \
    bash -c "[ $rc -eq 0 ] && grep -q 'Took over the case lock .* of an application that has ended' '$work/log.third'"
check "... and leaves no lock at its end" test ! -e "$c/isphLock"

# A fixed time step far past the Courant limit, and one above maxCo.
fixedStep() {  # fixedStep <name> <deltaT> <endTime> <writeInterval>: out, rc; the terminal in $work/terminal.<name>
    c=$work/$1
    fresh "$c"
    sed -i "s/^adjustTimeStep .*/adjustTimeStep no;/; s/^deltaT .*/deltaT $2;/; s/^endTime .*/endTime $3;/; s/^writeInterval .*/writeInterval $4;/" \
        "$c/system/controlDict"
    out=$(ISPH_PROGRESS_FD=3 "$bin/isphLandslideFoam" -case "$c" 3> "$work/terminal.$1" 2>&1); rc=$?
}
fixedStep fixed 0.02 0.4 0.02
check "deltaT 0.02, adjustTimeStep no: exit 1 (it ran to 0.4 at Co 3.8, exit 0)" test "$rc" -eq 1
check "... saying the bound, and the time it stops at" has "is past the stability bound" "$out"
stop=$(grep -o 'past the stability bound at time [0-9.e-]*' <<< "$out" | awk '{ print $NF }')
lastWritten=$("$bin/isphListTimes" -case "$c" -latestTime 2>/dev/null)
check "... the time past the bound ($stop) not written; the last written ($lastWritten) named" \
    bash -c "[ -n '$stop' ] && [ ! -d '$c/$stop' ] && grep -q 'the last time written, $lastWritten,' <<< \"\$1\"" _ "$out"
check "... on the terminal too" has "past the stability bound" "$(cat "$work/terminal.fixed")"
fixedStep aboveMaxCo 4e-3 0.12 0.04
check "deltaT 4e-3 above maxCo 0.2 but below Co 1: runs (exit 0)" test "$rc" -eq 0
check "... a warning on the terminal (there was none)" has "Warning: the fixed time step deltaT 0.004 s" "$(cat "$work/terminal.aboveMaxCo")"
check "... and in the log, with the count at the end" \
    bash -c "grep -q 'above maxCo 0.2' <<< \"\$1\" && grep -q 'Steps above maxCo 0.2 (adjustTimeStep no)' <<< \"\$1\"" _ "$out"

# A huge finite velocity.
c=$work/huge
fresh "$c"
u=$c/0/lagrangian/particles/U
first=$(awk '/^\($/ { print NR + 1; exit }' "$u")
for value in 1e200 1e30; do
    fresh "$c"
    awk -v n="$first" -v v="$value" 'NR == n { $0 = "(" v " 0 0)" } { print }' "$d/0/lagrangian/particles/U" > "$u"
    out=$("$bin/isphLandslideFoam" -case "$c" 2>&1); rc=$?
    check "U = $value in one particle: exit 1 naming the file and line (it blamed the time step or another particle)" \
        bash -c "[ $rc -eq 1 ] && grep -q '0/lagrangian/particles/U, line $first' <<< \"\$1\"" _ "$out"
    check "... the field, the particle, the value and the bound" \
        bash -c "grep -q 'field U of material particle origId' <<< \"\$1\" && grep -q \"|U| = \$2 m/s\" <<< \"\$1\" && grep -q 'free-fall speed over the domain' <<< \"\$1\"" _ "$out" "${value/e/e+}"
done

# A restart without the solver state.
c=$work/state
fresh "$c"
sed -i 's/^endTime .*/endTime 0.02;/' "$c/system/controlDict"
"$bin/isphLandslideFoam" -case "$c" > "$work/log.state" 2>&1 || { cat "$work/log.state"; exit 1; }
rm "$c/0.02/uniform/isphState"
sed -i 's/^endTime .*/endTime 0.03;/' "$c/system/controlDict"
out=$(ISPH_PROGRESS_FD=3 "$bin/isphLandslideFoam" -case "$c" 3> "$work/terminal.state" 2>&1); rc=$?
check "restart without uniform/isphState runs (exit 0)" test "$rc" -eq 0
check "... warning in the log that it will not be bit-identical (there was no line)" has "will not be bit-identical" "$out"
check "... and on the terminal" has "will not be bit-identical" "$(cat "$work/terminal.state")"

echo "$passed passed, $fails failed"
[ "$fails" -eq 0 ]
