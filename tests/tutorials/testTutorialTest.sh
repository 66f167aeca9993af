#!/bin/bash
# tests/tutorials/TutorialTest.sh and etc/ValidationFunctions must fail a tutorial test whose
# results.txt lacks an entry or holds one that is not a number (nan): awk would read either as
# 0, and checks such as "== 0" or "<= 5" would pass. Each case below runs a small tutorial test
# on a results.txt with a missing line and a nan and expects it to fail, naming the entry;
# the same test on a complete results.txt must pass (so that the failures are the entries').
# usage: testTutorialTest.sh <project dir>
set -u
project=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/testTutorialTest.XXXXXX")
trap 'rm -rf "$work"' EXIT
nFail=0
pass() { echo "PASS: $*"; }
failed() { echo "FAIL: $*"; nFail=$((nFail + 1)); }

mkdir -p "$work/good/validation" "$work/bad/validation"
printf 'crossings 0 -\nleft 3.5 kg\nspeed 0.5 m/s\n' > "$work/good/results.txt"
printf 'crossings nan -\nspeed 0.5 m/s\n' > "$work/bad/results.txt"   # left is missing
for d in good bad; do
    printf '# figure | runs | reference | tolerance | source\ncrossings | all | 0 | == | none\nleft | test | 5 | <= | a bound\nspeed | all | 0.1 * left | > | a ratio\n' \
        > "$work/$d/validation/checks"
done

# A tutorial test script body against results.txt of folder $1: $2 is what it does.
testScript() {
    cat > "$work/test.sh" <<SCRIPT
. "$project/tests/tutorials/TutorialTest.sh"
. "$project/etc/ValidationFunctions"
case=$work/$1
results=$work/$1/results.txt
$2
finish
SCRIPT
    bash "$work/test.sh" > "$work/out" 2>&1
}

# expectFailure <what> <folder> <body> <entry>...: the test fails and its output names each entry.
expectFailure() {
    local what=$1 dir=$2 body=$3 entry
    shift 3
    if testScript "$dir" "$body"; then
        failed "$what: the test passed"; cat "$work/out"; return
    fi
    for entry; do
        grep -q "$entry" "$work/out" || { failed "$what: the output does not name '$entry'"; cat "$work/out"; return; }
    done
    pass "$what"
}
expectSuccess() {
    if testScript "$2" "$3"; then pass "$1"; else failed "$1: the test failed"; cat "$work/out"; fi
}

checks='check "no wall crossings" "$(value crossings) == 0"
check "left <= 5" "$(value left) <= 5"
check "speed" "$(value speed) > 0.1"'
expectSuccess "value and check on a complete results.txt" good "$checks"
expectFailure "value and check: a nan and a missing entry inside check" bad "$checks" crossings left
expectFailure "value in an assignment: a missing entry" bad 'x=$(value left)
echo "never here: $x"' left
expectFailure "value whose result is only printed: a nan" bad 'echo "crossings: $(value crossings)"' crossings
expectFailure "check on a bare nan (awk reads it as 0)" good 'check "nan == 0" "nan == 0"' nan
expectSuccess "checkTutorial on a complete results.txt" good checkTutorial
expectFailure "checkTutorial: a nan and a missing entry" bad checkTutorial crossings left

# safeguardRows (the validation report's safeguards table): one row per run of a case, the
# prefix of a case of several runs, "?" for a figure missing, the goal 1 in 10,000.
printf 'wallCrossings 0 -\nwallSafeguardPer10k 2.5 -\ncollisionsPer10k 0.031 -\n' > "$work/one.txt"
printf 'a_wallSafeguardPer10k 0.1 -\na_collisionsPer10k 3 -\nb_wallSafeguardPer10k 7 -\n' > "$work/two.txt"
printf 'peakForce 3 N\n' > "$work/none.txt"
(
    . "$project/etc/ValidationFunctions"
    [ "$(safeguardRows "$work/one.txt")" = "-|2.5|0.031|1" ] || { echo "one: $(safeguardRows "$work/one.txt")"; exit 1; }
    [ "$(safeguardRows "$work/two.txt" | tr '\n' ' ')" = "a|0.1|3|1 b|7|?|1 " ] ||
        { echo "two: $(safeguardRows "$work/two.txt")"; exit 1; }
    [ -z "$(safeguardRows "$work/none.txt")" ] || exit 1
    ! safeguardRows "$work/missing.txt" 2> /dev/null
) && pass "safeguardRows: per run, prefix, missing figure, goal" || failed "safeguardRows"
[ "$nFail" -eq 0 ]
