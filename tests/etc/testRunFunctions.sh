#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Tests etc/RunFunctions (getApplication, runApplication, cleanCase, ...).
#
# Usage: bash tests/etc/testRunFunctions.sh PROJECT_DIR
#
# Works in a scratch directory from mktemp; writes nothing in PROJECT_DIR.
# Prints one PASS/FAIL line per check; exits non-zero if any check fails.
#------------------------------------------------------------------------------

# Single-quoted strings below are evaluated later (eval, sh -c) on purpose.
# shellcheck disable=SC2016
set -uo pipefail

if [ "$#" -ne 1 ] || [ ! -f "$1/etc/RunFunctions" ]; then
    echo "Usage: $0 PROJECT_DIR   (the directory holding etc/RunFunctions)" >&2
    exit 2
fi
projectDir=$(cd "$1" && pwd -P)
runFunctions="$projectDir/etc/RunFunctions"

scratch=$(mktemp -d "${TMPDIR:-/tmp}/testRunFunctions.XXXXXX") || exit 2
trap 'rm -rf -- "$scratch"' EXIT

nFail=0
nPass=0
pass() { echo "PASS: $*"; nPass=$((nPass + 1)); }
fail() { echo "FAIL: $*"; nFail=$((nFail + 1)); }
check() { # check "description" command...
    local what=$1
    shift
    if "$@"; then pass "$what"; else fail "$what"; fi
}

# Make the environment independent of the caller's (e.g. a sourced etc/bashrc)
unset ISPH_PROJECT_DIR ISPH_ETC ISPH_BUILD_DIR

# A PATH without isphDictionary, to force getApplication's sed/awk fallback
pathWithoutTool() {
    local dir out=
    local IFS=:
    for dir in $PATH; do
        [ -n "$dir" ] || continue
        [ -x "$dir/isphDictionary" ] && continue
        out="${out:+$out:}$dir"
    done
    echo "$out"
}

# A fake case
caseDir="$scratch/case"
mkdir -p "$caseDir/system" "$caseDir/constant" "$caseDir/0"
cat > "$caseDir/system/controlDict" <<'EOF'
FoamFile
{
    format      ascii;
    class       dictionary;
    object      controlDict;
}
// application notThisOne;   (a commented-out entry)
/* application notThisEither;
   application norThis; */
functions
{
    probe { application nestedNotThisOne; }
}

application     isphLandslideFoam;   // the solver

endTime         1;
EOF

cd "$caseDir" || exit 2

# shellcheck source=/dev/null
. "$runFunctions"

echo "== sourcing"
check "sourcing sets ISPH_PROJECT_DIR to the project" \
    test "${ISPH_PROJECT_DIR:-}" = "$projectDir"
check "sourcing sets ISPH_ETC" test "${ISPH_ETC:-}" = "$projectDir/etc"
check "sourcing puts build/bin on PATH" \
    test "${PATH%%:*}" = "$projectDir/build/bin"
# shellcheck source=/dev/null
. "$runFunctions"
n=$(tr : '\n' <<< "$PATH" | grep -cxF "$projectDir/build/bin")
check "sourcing twice does not duplicate build/bin on PATH" test "$n" = 1

echo "== getApplication"
savedPath=$PATH
PATH=$(pathWithoutTool)
check "isphDictionary is not on PATH (fallback forced)" \
    eval '! command -v isphDictionary >/dev/null'
app=$(getApplication)
check "getApplication (fallback) prints isphLandslideFoam [got '$app']" \
    test "$app" = isphLandslideFoam

fakeBin="$scratch/fakebin"
mkdir -p "$fakeBin"
printf '#!/bin/sh\necho fromTool\n' > "$fakeBin/isphDictionary"
chmod +x "$fakeBin/isphDictionary"
app=$(PATH="$fakeBin:$PATH" getApplication)
check "getApplication uses isphDictionary when on PATH [got '$app']" \
    test "$app" = fromTool
printf '#!/bin/sh\nexit 1\n' > "$fakeBin/isphDictionary"
app=$(PATH="$fakeBin:$PATH" getApplication)
check "getApplication falls back when isphDictionary fails [got '$app']" \
    test "$app" = isphLandslideFoam
PATH=$savedPath

if [ -x "$projectDir/build/bin/isphDictionary" ]; then
    app=$(PATH="$projectDir/build/bin:$PATH" getApplication)
    check "getApplication with the built isphDictionary [got '$app']" \
        test "$app" = isphLandslideFoam
fi

mkdir -p "$scratch/noApp/system"
echo "endTime 1;" > "$scratch/noApp/system/controlDict"
check "getApplication fails without an application entry" \
    eval '! (cd "$scratch/noApp" && PATH=$(pathWithoutTool) getApplication 2>/dev/null)'
check "getApplication fails without system/controlDict" \
    eval '! (cd "$scratch" && getApplication 2>/dev/null)'

echo "== runApplication"
counter="$scratch/counter"
: > "$counter"
# A shell-function "application": counts its runs, writes to stdout and stderr
fakeApp() {
    echo "Exec     : fakeApp $*"   # the banner's line, as the toolkit's applications write it
    echo run >> "$counter"
    echo "fakeApp stdout $* run $(wc -l < "$counter")"
    echo "fakeApp stderr" >&2
    echo End   # as the toolkit's applications end a finished run's log
}
failingApp() {
    echo "something went wrong"
    return 3
}

msg=$(runApplication fakeApp arg1 arg2)
rc=$?
check "runApplication returns 0 for a successful app" test "$rc" = 0
check "runApplication prints 'Running fakeApp on <dir>' [got '$msg']" \
    test "$msg" = "Running fakeApp on $caseDir"
check "runApplication writes log.fakeApp" test -f log.fakeApp
check "log.fakeApp holds the app's stdout with arguments" \
    grep -qx "fakeApp stdout arg1 arg2 run 1" log.fakeApp
check "log.fakeApp holds the app's stderr" grep -qx "fakeApp stderr" log.fakeApp

cp log.fakeApp "$scratch/log.saved"
# (a new script: sourcing RunFunctions again, as an Allrun does; in the same one, a step after
# one that ran runs too)
msg=$(. "$runFunctions"; runApplication fakeApp arg1 arg2)
rc=$?
check "second runApplication returns 0" test "$rc" = 0
check "second runApplication says already run [got '$msg']" \
    test "$msg" = "fakeApp already run on $caseDir: it finished, and nothing it reads changed since (remove log file 'log.fakeApp' to re-run)"
check "second runApplication leaves the log untouched" cmp -s log.fakeApp "$scratch/log.saved"
check "second runApplication does not run the app" test "$(wc -l < "$counter")" = 1

echo "== runApplication: runs again what may have changed"
# Each case as a new script would meet it (RunFunctions sourced afresh).
again() { (. "$runFunctions"; runApplication "$@") 2>&1; }
msg=$(again fakeApp arg1)
check "other arguments: runs again, saying so [got '$msg']" \
    eval 'grep -q "^Running fakeApp again on $caseDir: other arguments" <<< "$msg" && test "$(wc -l < "$counter")" = 2'
(. "$runFunctions"; runApplication -s next fakeApp >/dev/null)
msg=$(. "$runFunctions"; runApplication -o fakeApp arg1; runApplication -s next fakeApp)
check "a step after one that ran runs too [got '$msg']" \
    eval 'grep -q "^Running fakeApp again on $caseDir: an earlier step ran again" <<< "$msg" && test "$(wc -l < "$counter")" = 5'
msg=$(. "$runFunctions"; runApplication fakeApp arg1; runApplication -s next fakeApp)
check "... and is skipped when nothing before it ran" \
    eval 'test "$(grep -c "already run" <<< "$msg")" = 2 && test "$(wc -l < "$counter")" = 5'
sleep 0.05; touch constant/edited
msg=$(again fakeApp arg1)
check "an input newer than the log: runs again [got '$msg']" \
    grep -q "^Running fakeApp again on $caseDir: constant/edited changed since its last run" <<< "$msg"
rm -f constant/edited
printf 'Exec     : fakeApp arg1\nTime = 0.92\n' > log.fakeApp
msg=$(again fakeApp arg1)
check "a log that does not end with End (a stopped run): runs again [got '$msg']" \
    grep -q "^Running fakeApp again on $caseDir: its last run did not finish" <<< "$msg"
check "... and the log is the new run's" grep -qx End log.fakeApp
printf 'Exec     : fakeApp arg1\nCase     : /elsewhere/barrier\nEnd\n' > log.fakeApp
msg=$(again fakeApp arg1)
rc=$?
check "a log of another case (a copied case): refused [status $rc]" test "$rc" = 1
check "... with the advice to clean or clone [got '${msg%%$'\n'*}']" \
    eval 'grep -q "run in another case (/elsewhere/barrier)" <<< "$msg" && grep -q "isphCloneCase" <<< "$msg"'
check "... and the app not run" grep -q "^Case     : /elsewhere/barrier" log.fakeApp
warnApp() { printf -- '--> Warning: rho 1.379 outside 500 to 5000\n--> Note: g implies a slope of 45 deg\n--> Warning: second\nEnd\n'; }
msg=$(again warnApp)
check "the warnings counted on the terminal [got '$msg']" grep -qx "    2 warnings: see log.warnApp" <<< "$msg"
check "... the first of them shown" grep -qx "    warning: rho 1.379 outside 500 to 5000" <<< "$msg"
check "... and the notes" grep -qx "    g implies a slope of 45 deg" <<< "$msg"

runApplication -o fakeApp again >/dev/null
check "-o overwrites the log" \
    test "$(cat log.fakeApp)" = "$(printf 'Exec     : fakeApp again\nfakeApp stdout again run 8\nfakeApp stderr\nEnd')"
runApplication -overwrite fakeApp >/dev/null
check "-overwrite overwrites the log" grep -q "run 9" log.fakeApp
check "-overwrite left no old content" eval '! grep -q "run 8" log.fakeApp'

runApplication -a fakeApp more >/dev/null
check "-a appends to the log" \
    eval 'grep -q "run 9" log.fakeApp && grep -q "more run 10" log.fakeApp'

runApplication -s second fakeApp >/dev/null
check "-s suffix writes log.fakeApp.second" grep -q "run 11" log.fakeApp.second

runApplication sh -c 'echo from a real executable' >/dev/null
check "runApplication runs executables (log.sh)" grep -qx "from a real executable" log.sh

runApplication -o /bin/sh -c 'echo by path' >/dev/null
check "an app given by path logs to log.<basename>" grep -qx "by path" log.sh

err=$(runApplication failingApp 2>&1 >/dev/null)
rc=$?
check "runApplication returns the failing app's status (3) [got $rc]" test "$rc" = 3
check "failure message names the log [got '${err%%$'\n'*}']" \
    grep -q "failingApp failed.*log.failingApp" <<< "$err"
check "failure message shows the end of the log" grep -q "something went wrong" <<< "$err"

# (not as an 'if' condition: that would disable set -e in the subshell)
(set -e; runApplication -o failingApp >/dev/null 2>&1; exit 0)
rc=$?
check "runApplication failure stops a 'set -e' caller [status $rc]" test "$rc" = 3

# A solver stopped by Ctrl-C ends by SIGINT (isphLandslideFoam.cpp): status 130, reported
# as stopped (not failed), and an Allrun's '|| exit 1' then skips what follows.
err=$(runApplication -o sh -c 'echo "Stopped by a signal at time 0.5"; kill -INT $$' 2>&1 >/dev/null)
rc=$?
check "runApplication returns 130 for an app ended by SIGINT [got $rc]" test "$rc" = 130
check "it says stopped by a signal [got '${err%%$'\n'*}']" \
    grep -q "^sh stopped by a signal (exit status 130): see log.sh" <<< "$err"
check "and shows the end of the log" grep -q "Stopped by a signal at time 0.5" <<< "$err"
after=$(runApplication -o sh -c 'kill -INT $$' >/dev/null 2>&1 || exit 1; echo "post-processing")
check "an Allrun's '|| exit 1' stops after it [got '$after']" test -z "$after"

echo "== runApplication: progress on fd 3"
# A fake solver: its own output on stdout and stderr, its progress on $ISPH_PROGRESS_FD
apps="$scratch/apps"
mkdir -p "$apps"
cat > "$apps/progressApp" <<'EOF'
#!/bin/sh
echo "own output"
echo "own error" >&2
echo "fd=${ISPH_PROGRESS_FD:-unset}"
if [ -n "${ISPH_PROGRESS_FD:-}" ]; then
    echo "progress 50%" >&"$ISPH_PROGRESS_FD" || echo "progress fd unusable"
fi
EOF
chmod +x "$apps/progressApp"
logText() { tr '\n' '|' < log.progressApp; }

out=$(runApplication "$apps/progressApp" 2> "$scratch/progress.err")
rc=$?
check "progress: the app succeeds [rc $rc]" test "$rc" = 0
check "progress: stdout says Running [got '$out']" test "$out" = "Running progressApp on $caseDir"
check "progress: the caller's stderr shows the app's progress [got '$(cat "$scratch/progress.err")']" \
    test "$(cat "$scratch/progress.err")" = "progress 50%"
check "progress: log.progressApp holds the app's own output only [got '$(logText)']" \
    test "$(logText)" = "own output|own error|fd=3|"
check "progress: ISPH_PROGRESS_FD is not left set in the caller" test -z "${ISPH_PROGRESS_FD+set}"

runApplication -o -quiet "$apps/progressApp" > /dev/null 2> "$scratch/progress.err"
check "-quiet: nothing on the caller's stderr" test ! -s "$scratch/progress.err"
check "-quiet: the app gets no ISPH_PROGRESS_FD [got '$(logText)']" \
    test "$(logText)" = "own output|own error|fd=unset|"

ISPH_PROGRESS=off runApplication -o "$apps/progressApp" > /dev/null 2> "$scratch/progress.err"
check "ISPH_PROGRESS=off: nothing on stderr, no ISPH_PROGRESS_FD [got '$(logText)']" \
    eval 'test ! -s "$scratch/progress.err" && grep -qx "fd=unset" log.progressApp'

# An ISPH_PROGRESS_FD inherited from an outer run is not passed on with progress off
ISPH_PROGRESS_FD=3 runApplication -o -q "$apps/progressApp" > /dev/null 2>&1
check "-quiet unsets an inherited ISPH_PROGRESS_FD" grep -qx "fd=unset" log.progressApp

runApplication -o "$apps/progressApp" > /dev/null 2>&-
rc=$?
check "progress: a caller without stderr still runs the app [rc $rc, log '$(logText)']" \
    eval 'test "$rc" = 0 && grep -qx "fd=unset" log.progressApp'

runApplication -o "$apps/progressApp" > /dev/null 2> "$scratch/progress.err" 3> "$scratch/fd3"
check "progress goes to the caller's stderr, not to the caller's own fd 3" \
    eval 'test ! -s "$scratch/fd3" && grep -qx "progress 50%" "$scratch/progress.err"'

# A failing solver: its status, the end of its log on stderr (after its progress)
cat > "$apps/failingSolver" <<'EOF'
#!/bin/sh
for i in $(seq 1 30); do echo "step $i"; done
[ -n "${ISPH_PROGRESS_FD:-}" ] && echo "progress 10%" >&"$ISPH_PROGRESS_FD"
echo "FATAL: diverged" >&2
exit 4
EOF
chmod +x "$apps/failingSolver"
err=$(runApplication "$apps/failingSolver" 2>&1 >/dev/null)
rc=$?
check "a failing solver: runApplication returns its status 4 [got $rc]" test "$rc" = 4
check "a failing solver: its progress, then the failure on stderr" \
    test "$(head -n 2 <<< "$err")" = "$(printf 'progress 10%%\nfailingSolver failed (exit status 4): see log.failingSolver')"
check "a failing solver: stderr shows the last 20 lines of its log (step 12 on)" \
    eval 'grep -qx "step 12" <<< "$err" && ! grep -qx "step 11" <<< "$err" && grep -qx "FATAL: diverged" <<< "$err"'
check "a failing solver: the log has no progress" eval '! grep -q progress log.failingSolver'

echo "== runParallel"
# A stand-in for mpirun that logs how it was called and the threads each rank gets.
printf '#!/bin/sh\necho "OMP_NUM_THREADS=$OMP_NUM_THREADS mpirun $*"\n' > "$apps/fakeMpirun"
chmod +x "$apps/fakeMpirun"
printf 'FoamFile { format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains  3;   // ranks\nmethod zoltan;\n' \
    > system/decomposeParDict
check "getNumberOfProcessors reads numberOfSubdomains [got '$(getNumberOfProcessors)']" \
    test "$(getNumberOfProcessors)" = 3
cores=$(nproc)
msg=$(unset OMP_NUM_THREADS; ISPH_MPIRUN="$apps/fakeMpirun" runParallel -q isphLandslideFoam -case here)
rc=$?
check "runParallel returns 0 [got $rc]" test "$rc" = 0
check "runParallel prints 'Running isphLandslideFoam on <dir>' [got '$msg']" \
    test "$msg" = "Running isphLandslideFoam on $(pwd)"
over=; [ 3 -le "$cores" ] || over=" --oversubscribe"
threads=$(( cores / 3 )); [ "$threads" -ge 1 ] || threads=1
check "runParallel runs mpirun -np 3 app -parallel args into log.isphLandslideFoam [got '$(cat log.isphLandslideFoam)']" \
    test "$(cat log.isphLandslideFoam)" = "OMP_NUM_THREADS=$threads mpirun -np 3$over isphLandslideFoam -parallel -case here"
ISPH_MPIRUN="$apps/fakeMpirun" OMP_NUM_THREADS=2 runParallel -q -o -np 1 -s one isphLandslideFoam > /dev/null
check "runParallel -np 1 -s one keeps OMP_NUM_THREADS [got '$(cat log.isphLandslideFoam.one)']" \
    test "$(cat log.isphLandslideFoam.one)" = "OMP_NUM_THREADS=2 mpirun -np 1 isphLandslideFoam -parallel"
err=$(runParallel -np x isphLandslideFoam 2>&1)
check "runParallel -np x is an error [got '$err']" grep -q "whole number" <<< "$err"
rm -f system/decomposeParDict log.isphLandslideFoam*

echo "== runSolver"
# Stand-ins for the three applications: each appends its name and arguments to a trace; the
# fake mpirun above writes how it was called into log.isphLandslideFoam.
mkdir -p "$scratch/solverApps"
for app in decomposePar reconstructPar isphLandslideFoam; do
    printf '#!/bin/sh\necho "%s $*" >> "$SOLVER_TRACE"\n' "$app" > "$scratch/solverApps/$app"
    chmod +x "$scratch/solverApps/$app"
done
# runSolver's steps for the given arguments, as "app args;..." and then the mpirun line
solverSteps() {
    rm -f log.decomposePar log.reconstructPar log.isphLandslideFoam "$scratch/trace"
    touch "$scratch/trace"
    (PATH="$scratch/solverApps:$PATH" SOLVER_TRACE="$scratch/trace" ISPH_MPIRUN="$apps/fakeMpirun" \
        OMPI_ALLOW_RUN_AS_ROOT=${rootVar-1} ISPH_PROGRESS=off runSolver "$@" > "$scratch/solver.out" 2>&1)
    echo "$(tr '\n' ';' < "$scratch/trace")$(grep -o 'mpirun -np [0-9]*' log.isphLandslideFoam 2>/dev/null)"
}
serialRun="isphLandslideFoam ;"
parallelRun="decomposePar ;reconstructPar ;mpirun -np $cores"
check "runSolver without system/decomposeParDict: one process [got '$(solverSteps)']" \
    test "$(solverSteps)" = "$serialRun"
printf 'FoamFile { format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains  %s;\nmethod zoltan;\n' \
    "$cores" > system/decomposeParDict
check "runSolver with as many subdomains as cores: decomposePar, the ranks, reconstructPar [got '$(solverSteps)']" \
    test "$(solverSteps)" = "$parallelRun"
check "runSolver -test: one process [got '$(solverSteps -test)']" test "$(solverSteps -test)" = "$serialRun"
check "runSolver -serial: one process [got '$(solverSteps -serial)']" test "$(solverSteps -serial)" = "$serialRun"
check "runSolver -test -parallel: the ranks [got '$(solverSteps -test -parallel)']" \
    test "$(solverSteps -test -parallel)" = "$parallelRun"
if [ "$(id -u)" -eq 0 ]; then
    got=$(rootVar= solverSteps)
    check "runSolver as root without OMPI_ALLOW_RUN_AS_ROOT: one process [got '$got']" test "$got" = "$serialRun"
    check "and it says why [got '$(cat "$scratch/solver.out")']" grep -q "OMPI_ALLOW_RUN_AS_ROOT=1" "$scratch/solver.out"
fi
printf 'FoamFile { format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains  %s;\nmethod zoltan;\n' \
    "$((cores + 1))" > system/decomposeParDict
check "runSolver with more subdomains than cores: one process [got '$(solverSteps)']" \
    test "$(solverSteps)" = "$serialRun"
check "runSolver -parallel with more subdomains than cores: the ranks [got '$(solverSteps -parallel)']" \
    test "$(solverSteps -parallel)" = "decomposePar ;reconstructPar ;mpirun -np $((cores + 1))"
failing() { printf '#!/bin/sh\nexit 3\n' > "$scratch/solverApps/$1"; }
failing decomposePar
solverSteps -parallel > /dev/null
check "runSolver stops when decomposePar fails (no solver, no reconstructPar)" \
    test ! -e log.isphLandslideFoam -a ! -e log.reconstructPar
rm -f system/decomposeParDict log.*

echo "== isTest/notTest"
check "isTest finds -test" isTest a -test b
check "notTest without -test" notTest a b

echo "== safeguardFigures"
printf '%s\n' 'Wall crossings in the run: 2' \
    'Wall safeguard in the run: 291545 particle-steps (923 per 10,000 material particle-steps)' \
    'Collision separation in the run: 12 particle-steps (0.0381 per 10,000 material particle-steps)' > log.summary
got=$(safeguardFigures log.summary case1_ | tr '\n' ';')
check "safeguardFigures: the three figures with their prefix [got '$got']" \
    test "$got" = "case1_wallCrossings 2 -;case1_wallSafeguardPer10k 923 -;case1_collisionsPer10k 0.0381 -;"
rm -f log.summary

echo "== runVariant"
mkdir -p variantCase/system variantCase/constant
echo base > variantCase/system/isphSchemes
echo other > variantCase/system/isphSchemes.soft
echo soil > variantCase/constant/materialProperties.soft
check "runVariant without its option does nothing" \
    test "$(cd variantCase && runVariant soft a -test && pwd)" = "$(cd variantCase && pwd)" -a ! -e variantCase/soft
got=$(cd variantCase && runVariant soft -soft > /dev/null && pwd)
check "runVariant -soft goes on in soft/ [got '$got']" test "$got" = "$(cd variantCase && pwd)/soft"
check "runVariant: X.soft replaces X in the copy" \
    test "$(cat variantCase/soft/system/isphSchemes)" = other -a "$(cat variantCase/soft/constant/materialProperties)" = soil
check "runVariant leaves the case itself alone" \
    test "$(cat variantCase/system/isphSchemes)" = base -a -e variantCase/system/isphSchemes.soft
rm -rf variantCase

echo "== cleanCase"
mkdir -p 0.1 1 2e-05 100 0.orig postProcessing/probes VTK 0/uniform processor0/0.1 processor1
touch log.extra plot.png results.txt Allrun 0/U 0.1/U constant/transportProperties
cleanCase
for d in 0.1 1 2e-05 100; do
    check "cleanCase removes time directory $d/" test ! -e "$d"
done
check "cleanCase removes log.*" eval '! ls log.* >/dev/null 2>&1'
for f in postProcessing VTK plot.png results.txt processor0 processor1; do
    check "cleanCase removes $f" test ! -e "$f"
done
for f in 0/U 0.orig system/controlDict constant/transportProperties Allrun; do
    check "cleanCase keeps $f" test -e "$f"
done

mkdir -p 0.5
touch log.x
cleanCase0
check "cleanCase0 removes 0/" test ! -e 0
check "cleanCase0 removes time directories and logs" \
    eval 'test ! -e 0.5 && ! ls log.* >/dev/null 2>&1'
check "cleanCase0 keeps constant/ and system/" test -d constant -a -d system

mkdir -p "$scratch/other/0" "$scratch/other/3"
cleanCase "$scratch/other"
check "cleanCase DIR cleans DIR" test -d "$scratch/other/0" -a ! -e "$scratch/other/3"

echo "== POSIX sh"
# Tutorials are '#!/bin/sh' scripts: check the functions work there too.
if command -v dash >/dev/null 2>&1; then posixSh="dash"; else posixSh="sh"; fi
shCase="$scratch/shCase"
mkdir -p "$shCase/system" "$shCase/0" "$shCase/0.2"
cp "$caseDir/system/controlDict" "$shCase/system/"
shOut=$(
    cd "$shCase" && env -u ISPH_PROJECT_DIR -u ISPH_ETC ISPH_ETC="$projectDir/etc" \
        PATH="$(pathWithoutTool)" "$posixSh" -c '
        . "$ISPH_ETC/RunFunctions" || exit 10
        echo "dir=$ISPH_PROJECT_DIR"
        echo "app=$(getApplication)"
        runApplication echo End
        . "$ISPH_ETC/RunFunctions"
        runApplication echo End
        runApplication -s x false; echo "rc=$?"
        cleanCase
        ls -d 0* 2>/dev/null
    ' 2>&1
)
check "$posixSh: RunFunctions finds the project from ISPH_ETC" grep -qx "dir=$projectDir" <<< "$shOut"
check "$posixSh: getApplication" grep -qx "app=isphLandslideFoam" <<< "$shOut"
check "$posixSh: runApplication runs, then refuses" \
    eval 'grep -q "^Running echo on" <<< "$shOut" && grep -q "^echo already run on" <<< "$shOut"'
check "$posixSh: runApplication returns a failing app's status" grep -qx "rc=1" <<< "$shOut"
check "$posixSh: cleanCase keeps 0, removes 0.2" \
    test "$(grep '^0' <<< "$shOut" | tr '\n' ' ')" = "0 "

dashProgress=$(
    cd "$shCase" && env -u ISPH_PROJECT_DIR ISPH_ETC="$projectDir/etc" "$posixSh" -c '
        . "$ISPH_ETC/RunFunctions" || exit 10
        runApplication "$1" 2>&1 >/dev/null' sh "$apps/progressApp"
)
check "$posixSh: runApplication shows the progress on stderr [got '$dashProgress']" \
    eval 'test "$dashProgress" = "progress 50%" && ! grep -q progress "$shCase/log.progressApp"'

# Located by walking up from $PWD (no ISPH_* set, no BASH_SOURCE in dash)
walkOut=$(
    cd "$projectDir/etc" && env -u ISPH_PROJECT_DIR -u ISPH_ETC "$posixSh" -c \
        '. ./RunFunctions && echo "dir=$ISPH_PROJECT_DIR"' 2>&1
)
check "$posixSh: RunFunctions finds the project walking up from \$PWD [got '$walkOut']" \
    test "$walkOut" = "dir=$projectDir"

echo
if [ "$nFail" -ne 0 ]; then
    echo "$posixSh output was:"
    printf '    %s\n' "$shOut"
    echo "testRunFunctions: $nFail FAILED, $nPass passed"
    exit 1
fi
echo "testRunFunctions: all $nPass checks passed"
