#!/bin/bash
# Shared by the tutorial tests: run a tutorial's Allrun -test on a copy, as a user would, and
# check figures of its results.txt.
#   . TutorialTest.sh
#   runTutorial <project dir> <build dir> <tutorial path under tutorials/>   # sets case, results
#   value <name>                       the value of a results.txt line "name value unit"
#   check <description> <awk condition>  prints ok/FAIL; a failure sets fail=1
#   exit $fail
set -eu
fail=0

runTutorial() {
    local project=$1 build=$2 tutorial=$3
    work=$(mktemp -d "/tmp/isphTest-${tutorial##*/}.XXXXXX")
    trap 'rm -rf "$work"' EXIT
    case=$work/${tutorial##*/}
    cp -r "$project/tutorials/$tutorial" "$case"
    export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
    if ! "$case/Allrun" -test > "$work/Allrun.log" 2>&1
    then
        cat "$work/Allrun.log"
        find "$case" -name log.isphLandslideFoam -exec tail -30 {} \;
        exit 1
    fi
    results=$case/results.txt
    cat "$results"
}

value() {
    awk -v k="$1" '$1 == k { print $2; found = 1 } END { exit !found }' "$results" \
        || { echo "FAIL: no '$1' in results.txt" >&2; echo nan; }
}

check() {
    if awk "BEGIN { exit !($2) }"; then echo "ok:   $1"; else echo "FAIL: $1 ($2)"; fail=1; fi
}
