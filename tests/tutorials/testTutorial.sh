#!/bin/bash
# A tutorial as a user runs it, short: tutorials/<tutorial>/Allrun -test on a copy, then its
# results.txt against the checks the case declares in validation/checks (each with the
# reference, the tolerance and the measured run-to-run noise behind it).
# usage: testTutorial.sh <project dir> <build dir> <tutorial path under tutorials/>
. "${0%/*}/TutorialTest.sh"
runTutorial "$1" "$2" "$3"
checkTutorial
finish
