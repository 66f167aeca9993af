#!/bin/bash
# Shared by the tutorial tests: run a tutorial's Allrun -test on a copy, as a user would, and
# check its results.txt against the checks the case declares in validation/checks
# (etc/ValidationFunctions). The copy is kept in <build dir>/validation/quick/<case>, where
# tutorials/Allrun-validation -quick -reuse (ctest tutorial.validation) writes the report from
# the same runs.
#   . TutorialTest.sh
#   runTutorial <project dir> <build dir> <tutorial path under tutorials/>   # sets case, results
#   barrierClone <project dir> <build dir> <name>   sets scratch and case: a clone of the barrier
#   checkTutorial                  the case's validation/checks for a -test run
#   value <name>                   the value of a results.txt line "name value unit"; a missing,
#                                  repeated or non-numeric entry (nan included) fails the test,
#                                  naming the entry
#   check <description> <awk condition>  prints ok/FAIL; a failure, or an operand that is not
#                                  a number, fails the test
#   finish                         ends the test: status 1 if anything failed
#   scratch=<dir>                  a folder of the test's own, removed at the end
set -eu
fail=0
scratch=
failures=$(mktemp "${TMPDIR:-/tmp}/isphTutorialTest.XXXXXX")
# Whatever way the script ends, a recorded failure fails it (value() runs in a subshell when
# its result is substituted, so failures are recorded in a file).
trap 'status=$?; [ ! -s "$failures" ] || status=1; rm -rf "$failures" ${scratch:+"$scratch"}; exit $status' EXIT

failTest() {
    echo "FAIL: $*"
    echo "$*" >> "$failures"
    fail=1
}

runTutorial() {
    local project=$1 build=$2 tutorial=$3
    export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
    . "$project/etc/RunFunctions"
    . "$project/etc/ValidationFunctions"
    case=$build/validation/quick/${tutorial##*/}
    results=$case/results.txt
    if ! runValidationCase "$project/tutorials/$tutorial" "$case" test
    then
        cat "$case/log.Allrun"
        find "$case" -name log.isphLandslideFoam -exec tail -30 {} \;
        failTest "$tutorial/Allrun -test failed"
        exit 1
    fi
    cat "$results"
}

# barrierClone <project dir> <build dir> <name>: a user's shell (the build's bin on PATH, no
# progress lines) and case=$scratch/<name>, a clone of the barrier tutorial (isphCloneCase)
barrierClone() {
    export ISPH_PROJECT_DIR=$1 ISPH_BUILD_DIR=$2 ISPH_PROGRESS=off
    export PATH="$2/bin:$PATH"
    . "$1/etc/RunFunctions"
    . "$1/etc/ValidationFunctions"
    scratch=$(mktemp -d "${TMPDIR:-/tmp}/isphBarrier.XXXXXX")
    case=$scratch/$3
    isphCloneCase "$1/tutorials/landslides/barrier" "$case" > /dev/null
}

checkTutorial() {
    checkFigures "$case" test || failTest "figures of $case/results.txt outside their tolerance (above)"
}

value() {
    figureValue "$results" "$1" || { failTest "results.txt entry '$1' missing or not a number"; return 1; }
}

check() {
    # Every operand must be a number: a bare word (nan, inf, a name) reads as 0 in awk.
    local words
    words=$(echo "$2" | sed -E 's/(^|[^A-Za-z_0-9.])[0-9]*[.]?[0-9]+([eE][-+]?[0-9]+)?/\1/g' | grep -oE '[A-Za-z_][A-Za-z_0-9]*' || true)
    if [ -n "$words" ]; then
        failTest "$1 (not a number: $(echo $words) in '$2')"
    elif awk "BEGIN { exit !($2) }" 2> /dev/null; then
        echo "ok:   $1"
    else
        failTest "$1 ($2)"
    fi
}

finish() {
    exit 0   # the EXIT trap turns it into 1 when anything failed
}
