#!/bin/bash
# Issue 53: never report what did not run. The barrier's ./Allrun -test stopped by SIGINT in
# the middle of the solver's run writes no figures and exits non-zero; ./Allrun -test again
# skips particleMesh (its run finished, nothing changed), continues the solver from the time
# it stopped at (saying why it runs again) to endTime, and writes the finished run's figures:
# the sand at rest at the end (the load cell within 1 % of the weight along the bed, as the
# case's validation/checks asks), the force history joined over both parts up to 2.5 s.
# usage: testContinueAfterStop.sh <project dir> <build dir>
. "${0%/*}/TutorialTest.sh"
barrierClone "$1" "$2" barrier
cd "$case" || exit 1

./Allrun -test > log.Allrun1 2>&1 &
allrun=$!
# Wait for the solver to pass 0.5 s of its 2.5 s, then stop it as Ctrl-C does.
for _ in $(seq 600)
do
    grep -q '^Time = 0\.[5-9]' log.isphLandslideFoam 2> /dev/null && break
    kill -0 "$allrun" 2> /dev/null || break
    sleep 0.5
done
solver=$(sed -n 's/^PID *: //p' log.isphLandslideFoam 2> /dev/null | head -n 1)
[ -n "$solver" ] && kill -INT "$solver"
status=0
wait "$allrun" || status=$?
cat log.Allrun1
check "the stopped Allrun exits non-zero" "$status != 0"
[ ! -e results.txt ] || failTest "figures were written for a run that was stopped"
grep -q "^Stopped by a signal at time" log.isphLandslideFoam || failTest "the solver's log says it stopped"
stoppedAt=$(ls -d [0-9]* | sort -g | tail -n 1)
check "it stopped before endTime (at $stoppedAt s)" "$stoppedAt < 2.5"

./Allrun -test > log.Allrun2 2>&1 || { tail -30 log.Allrun2; failTest "the second Allrun -test failed"; exit 1; }
cat log.Allrun2
grep -q "^particleMesh already run on" log.Allrun2 || failTest "particleMesh, finished and unchanged, is not run again"
grep -q "^Running isphLandslideFoam again on .*: its last run did not finish" log.Allrun2 ||
    failTest "the solver runs again and says why"
firstTime=$(sed -n 's/^Time = \([0-9.eE+-]*\) .*/\1/p' log.isphLandslideFoam | head -n 1)
check "the solver continued from the time it stopped at ($stoppedAt s; first step to $firstTime s)" \
    "$firstTime > $stoppedAt && $firstTime < $stoppedAt + 0.01"
check "to endTime" "$(ls -d [0-9]* | sort -g | tail -n 1) == 2.5"
[ "$(awk 'NF { last = $0 } END { print last }' log.isphLandslideFoam)" = End ] || failTest "the solver's log ends with End"
results=$case/results.txt
check "the finished run's deposit at rest: load cell within 1 % of the weight along the bed" \
    "$(value loadCellAlongBed) > 0.99 * $(value sandWeightAlongBed) && $(value loadCellAlongBed) < 1.01 * $(value sandWeightAlongBed)"
check "the force history runs to the end of the run" \
    "$(awk '!/^#/ { t = $1 } END { print t }' postProcessing/barrierForce.dat) > 2.49"
check "and has no step twice (the two parts joined at the restart)" \
    "$(awk '!/^#/ { if ($1 <= last) bad++; last = $1 } END { print bad + 0 }' postProcessing/barrierForce.dat) == 0"
check "a peak force from the impact" "$(value peakForce) > $(value residualForce)"
finish
