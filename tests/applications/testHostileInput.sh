#!/usr/bin/env bash
# The probes of issue 34 as a careful user's mistakes and a crashing machine would make them,
# each run against the applications: none may crash (exit 134/139), hang or lose a time
# directory; each bad input is a clear error (file, line, limit) with exit status 1.
# Usage: testHostileInput.sh <source dir> <build dir>
set -u
src=$1
bin=$2/bin
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$src/tests/applications/CheckFunctions.sh"  # check, has
deadPid() { sh -c 'echo $$'; }       # a process that has ended

# ---- dictionaries ----------------------------------------------------------------------
{ printf 'a { %.0s' $(seq 10000); printf '} %.0s' $(seq 10000); } > "$work/deep"
out=$("$bin/isphDictionary" "$work/deep" 2>&1); rc=$?
check "10,000 nested dictionaries: exit 1, not a crash" test "$rc" -eq 1
check "... naming the limit" has "nested more than 100 levels" "$out"
printf 'a 1;\n#include "/dev/zero"\n' > "$work/zero"
out=$(timeout 60 "$bin/isphDictionary" "$work/zero" 2>&1); rc=$?
check "#include \"/dev/zero\": exit 1 at once" test "$rc" -eq 1
check "... naming the file, line and why" has "zero, line 2" "$out"
check "... a character device" has "a character device, not a regular file" "$out"

# ---- particleMesh: a spacing that asks for too many particles ---------------------------
d=$work/damBreak
mkdir -p "$d"
cp -r "$src/tutorials/validation/damBreak/system" "$src/tutorials/validation/damBreak/constant" "$d"
for spacing in 1e-10 1e-20; do
    sed -i "s/^spacing .*/spacing $spacing;/" "$d/system/particleMeshDict"
    out=$(timeout 120 "$bin/particleMesh" -case "$d" 2>&1); rc=$?
    check "particleMesh spacing $spacing: exit 1 at once, nothing allocated" test "$rc" -eq 1
    check "... the estimate, the limit and where to raise it" \
        bash -c "grep -q 'more than maxParticles 1e+07' <<< \"\$1\" && grep -q 'raise maxParticles in system/particleMeshDict' <<< \"\$1\" && grep -q 'particleMeshDict, line' <<< \"\$1\"" _ "$out"
done
check "... and no 0/ written" test ! -e "$d/0"
# Out of memory (an address-space limit below what the scene needs, the limit raised): a fatal
# error naming what was being built, the log kept. (Not with AddressSanitizer, which reserves
# terabytes of address space and cannot run under ulimit -v.)
if ! ldd "$bin/particleMesh" | grep -q libasan; then
    sed -i "s/^spacing .*/spacing 1e-5;\nmaxParticles 1e9;/" "$d/system/particleMeshDict"
    (ulimit -v 400000; OMP_NUM_THREADS=2 "$bin/particleMesh" -case "$d" > "$work/log.oom" 2>&1); rc=$?
    check "particleMesh out of memory: exit 1, not an abort (134)" test "$rc" -eq 1
    check "... naming what it was building" has "out of memory while building the material particles of 1 region(s) at spacing 1e-05 m" "$(cat "$work/log.oom")"
    check "... the log kept (the scene and the estimate)" has "estimate: 6.57e+07 particles (maxParticles 1e+09)" "$(cat "$work/log.oom")"
fi

# ---- interrupted writes, replaces and purges -------------------------------------------
c=$work/case
mkdir -p "$c/system" "$c/0/lagrangian/particles" "$c/0.1/lagrangian/particles"
printf 'FoamFile { class dictionary; object controlDict; }\nendTime 1;\n' > "$c/system/controlDict"
pid=$(deadPid)
mkdir -p "$c/.0.2.old.$pid/lagrangian/particles" "$c/.0.2.tmp.$pid/lagrangian" "$c/.0.3.tmp.$pid" \
    "$c/.0.05.trash.$pid/lagrangian/particles" "$c/postProcessing/x"
echo complete > "$c/.0.2.old.$pid/lagrangian/particles/U"
echo half > "$c/postProcessing/x/.f.dat.tmp.$pid.0"
out=$("$bin/isphListTimes" -case "$c" 2>"$work/err"); rc=$?
err=$(cat "$work/err")
check "a time hidden by a replace killed between its renames is restored" test "$out" = "$(printf '0\n0.1\n0.2')"
check "... with its complete content" grep -q complete "$c/0.2/lagrangian/particles/U"
check "... and said (on stderr, as isphListTimes' stdout is parsed)" has "restored $c/0.2" "$err"
check "the unfinished writes and the purge's rest are removed" \
    bash -c "[ -z \"\$(ls -A '$c' | grep '^\\.')\" ] && [ -z \"\$(ls -A '$c/postProcessing/x')\" ]"
check "... and said" has "1 restored, 4 removed, 0 left alone" "$err"
sleep 300 & running=$!
mkdir -p "$c/.0.4.tmp.$running"
out=$("$bin/isphListTimes" -case "$c" 2>"$work/err")
check "the staging of a running process is left alone" test -d "$c/.0.4.tmp.$running"
check "... and said" has "process $running may still be writing it" "$(cat "$work/err")"
kill "$running"; wait "$running" 2>/dev/null
"$bin/isphListTimes" -case "$c" -time 0.1 -rm 2>/dev/null
check "isphListTimes -rm removes a time and leaves nothing behind" \
    bash -c "[ ! -e '$c/0.1' ] && [ -z \"\$(ls -A '$c' | grep '^\\.0\\.1')\" ]"

# ---- the solver's start-up checks ---------------------------------------------------------
r=$work/restart
mkdir -p "$r"
cp -r "$src/tutorials/validation/damBreak/system" "$src/tutorials/validation/damBreak/constant" "$r"
sed -i 's/^spacing .*/spacing 0.005715;/' "$r/system/particleMeshDict"
sed -i 's/^writeFormat .*/writeFormat ascii;/; s/^writePrecision .*/writePrecision 17;/; s/^writeInterval .*/writeInterval 0.01;/' \
    "$r/system/controlDict"
"$bin/particleMesh" -case "$r" > "$work/log.particleMesh.restart" 2>&1 || { cat "$work/log.particleMesh.restart"; exit 1; }
endLine=$(grep -n '^endTime' "$r/system/controlDict" | cut -d: -f1)
sed -i 's/^endTime .*/endTime -1;/' "$r/system/controlDict"
out=$("$bin/isphLandslideFoam" -case "$r" 2>&1); rc=$?
check "endTime before the start: exit 1, not 0 after zero steps" test "$rc" -eq 1
check "... naming controlDict's endTime line" has "controlDict, line $endLine" "$out"
check "... and what to do" has "endTime -1 is not after the start time 0" "$out"
sed -i 's/^endTime .*/endTime 0.02;/' "$r/system/controlDict"
sed -i 's/^writeInterval .*/writeInterval 1e-12;/' "$r/system/controlDict"
out=$("$bin/isphLandslideFoam" -case "$r" 2>&1); rc=$?
check "writeInterval 1e-12: exit 1, not a time directory every step" test "$rc" -eq 1
check "... naming writeInterval" has "writeInterval 1e-12 s is shorter than the time step" "$out"
check "... and nothing written" test "$(ls -d "$r"/[0-9]* | wc -l)" -eq 1
sed -i 's/^writeInterval .*/writeInterval 0.01;/' "$r/system/controlDict"
"$bin/isphLandslideFoam" -case "$r" > "$work/log.solver" 2>&1
check "the dam break runs to 0.02" test -d "$r/0.02"
pos=$r/0.02/lagrangian/particles/positions
first=$(awk '/^\($/ { print NR + 1; exit }' "$pos")
cp "$pos" "$work/positions.good"
awk -v n="$first" 'NR == n { $0 = "(3 -5 0)" } { print }' "$work/positions.good" > "$pos"
sed -i 's/^endTime .*/endTime 0.03;/' "$r/system/controlDict"
out=$("$bin/isphLandslideFoam" -case "$r" 2>&1); rc=$?
check "a particle moved out of the scene: exit 1, not a free fall" test "$rc" -eq 1
check "... naming the positions file and line" has "0.02/lagrangian/particles/positions, line $first" "$out"
check "... the scene's domain" has "outside the scene's domain" "$out"
mv "$r/0.02/uniform/isphState" "$work/isphState.good"   # as written before the state was
out=$("$bin/isphLandslideFoam" -case "$r" 2>&1); rc=$?
check "... also from a time without the solver state (the domain of 0/)" \
    bash -c "[ $rc -eq 1 ] && grep -q 'the bounding box of the particles of .*/0/lagrangian/particles' <<< \"\$1\"" _ "$out"
mv "$work/isphState.good" "$r/0.02/uniform/isphState"
u=$r/0.02/lagrangian/particles/U
cp "$work/positions.good" "$pos"
cp "$u" "$work/U.good"
awk -v n="$first" 'NR == n { $0 = "(0 nan 0)" } { print }' "$work/U.good" > "$u"
out=$("$bin/isphLandslideFoam" -case "$r" 2>&1); rc=$?
check "a nan in U: exit 1 naming the file and line" has "0.02/lagrangian/particles/U, line $first" "$out"
check "... not a finite number" has "'nan' is not a finite number" "$out"
cp "$work/U.good" "$u"
"$bin/isphLandslideFoam" -case "$r" > "$work/log.solver" 2>&1; rc=$?
check "repaired, the restart runs on to 0.03" bash -c "[ $rc -eq 0 ] && [ -d '$r/0.03' ]"

# ---- SIGKILL at random moments while the solver writes and purges ------------------------
k=$work/killed
mkdir -p "$k"
cp -r "$src/tutorials/validation/damBreak/system" "$src/tutorials/validation/damBreak/constant" "$k"
sed -i 's/^spacing .*/spacing 0.005715;/' "$k/system/particleMeshDict"
sed -i 's/^endTime .*/endTime 10;/; s/^writeInterval .*/writeInterval 0.002;/; s/^purgeWrite .*/purgeWrite 2;/' \
    "$k/system/controlDict"
"$bin/particleMesh" -case "$k" > "$work/log.particleMesh.killed" 2>&1 || { cat "$work/log.particleMesh.killed"; exit 1; }
complete=0
for delay in 0.7 0.45 1.1 0.3 0.9 0.6; do
    "$bin/isphLandslideFoam" -case "$k" > "$work/log.killed" 2>&1 &
    solver=$!
    sleep "$delay"
    kill -KILL "$solver" 2>/dev/null; wait "$solver" 2>/dev/null
    "$bin/isphListTimes" -case "$k" > "$work/times" 2> "$work/recovered"
    ok=true
    for time in $(cat "$work/times"); do  # every listed time is complete: every field reads
        "$bin/toVTK" -case "$k" -time "$time" > "$work/log.toVTK.killed" 2>&1 || ok=false
        grep -q "skipped" "$work/log.toVTK.killed" && ok=false
    done
    [ -z "$(ls -A "$k" | grep '^\.')" ] || ok=false   # nothing left hidden after the recovery
    $ok && complete=$((complete + 1))
done
check "after 6 SIGKILLs while writing and purging, every listed time is complete and nothing hidden is left" \
    test "$complete" -eq 6
sed -i 's/^endTime .*/endTime 0.5;/' "$k/system/controlDict"
latest=$("$bin/isphListTimes" -case "$k" -latestTime 2>/dev/null)
sed -i "s/^endTime .*/endTime $(awk -v t="$latest" 'BEGIN { print t + 0.004 }');/" "$k/system/controlDict"
"$bin/isphLandslideFoam" -case "$k" > "$work/log.killed.restart" 2>&1; rc=$?
check "... and the run restarts from the latest (exit 0)" test "$rc" -eq 0

# ---- post-processing over incomplete or damaged times -----------------------------------
t=$work/tank
cp -r "$src/tests/postProcessing/cases/hydrostaticTank" "$t"
sed -i 's/^spacing .*/spacing 0.05;/' "$t/system/particleMeshDict"
"$bin/particleMesh" -case "$t" > "$work/log.particleMesh" 2>&1 || { cat "$work/log.particleMesh"; exit 1; }
for time in 0.1 0.2 0.3; do cp -r "$t/0" "$t/$time"; done
rm "$t/0.1/lagrangian/particles/U"                                 # half-deleted
awk 'NR == 25 { $0 = "nan" } { print }' "$t/0/lagrangian/particles/p" > "$t/0.2/lagrangian/particles/p"
pLine=$(awk 'NR == 25' "$t/0.2/lagrangian/particles/p")
out=$("$bin/toVTK" -case "$t" 2>&1); rc=$?
check "toVTK stops at an incomplete time: exit 1, a script can tell (issue 54)" test "$rc" -eq 1
check "... naming the time, the missing file and the option to carry on" \
    bash -c "grep -q 'time 0.1 cannot be read' <<< \"\$1\" && grep -q '0.1/lagrangian/particles/U' <<< \"\$1\" && grep -q -- '-skipDamaged' <<< \"\$1\"" _ "$out"
check "... -help names that option" bash -c "'$bin/toVTK' -help | grep -q -- '-skipDamaged'"
"$bin/toVTK" -case "$t" -skipDamaged > "$work/log.toVTK" 2>&1; rc=$?
check "toVTK -skipDamaged goes past an incomplete time and a nan: exit 0" test "$rc" -eq 0
check "... the .pvd lists the readable times" \
    bash -c "[ \"\$(grep -c 'DataSet' '$t/VTK/tank.pvd')\" -eq 2 ] && ! grep -q '_0.1.vtp\|_0.2.vtp' '$t/VTK/tank.pvd'"
check "... warns naming the missing file" has "time 0.1 is skipped" "$(cat "$work/log.toVTK")"
check "... and the nan with its file and line" has "0.2/lagrangian/particles/p, line 25" "$(cat "$work/log.toVTK")"
check "... not a finite number" has "'nan' is not a finite number" "$(cat "$work/log.toVTK")"
check "... and counts the skipped" has "2 of 4 selected times were skipped" "$(cat "$work/log.toVTK")"
"$bin/sampleForces" -case "$t" > "$work/log.sampleForces" 2>&1; rc=$?
check "sampleForces stops there too (exit 1)" test "$rc" -eq 1
"$bin/sampleForces" -case "$t" -skipDamaged > "$work/log.sampleForces" 2>&1; rc=$?
check "sampleForces -skipDamaged skips them (exit 0)" test "$rc" -eq 0
check "... no nan in the forces" bash -c "! grep -qi nan '$t/postProcessing/sampleForces/0/leftWall.dat'"
out=$("$bin/sampleForces" -case "$t" -time 0.2 2>&1); rc=$?
check "sampleForces on the nan time alone: exit 1" test "$rc" -eq 1
check "... naming the file and line" has "0.2/lagrangian/particles/p, line 25" "$out"

echo "$passed passed, $fails failed"
[ "$fails" -eq 0 ]
