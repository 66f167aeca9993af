#!/bin/bash
# Issue 53: a misspelt keyword never changes a result silently. On the still-water tank (coarse,
# 0.01 s): 'maxCO 0.2;' in system/controlDict stops the solver with a non-zero exit, the file,
# the line and "did you mean maxCo?" (it used to warn in the log and run with maxCo 1); a name
# used only as a $variable is the user's own and runs; a keyword given twice is refused.
# usage: testMisspeltKeyword.sh <project dir> <build dir>
set -u
project=$1
bin=$2/bin
scratch=$(mktemp -d "${TMPDIR:-/tmp}/isphMisspelt.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
nFail=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; nFail=$((nFail + 1)); }

c=$scratch/tank
mkdir -p "$c"
cp -r "$project/tutorials/validation/hydrostaticTank/system" "$project/tutorials/validation/hydrostaticTank/constant" "$c"/
"$bin/isphDictionary" -entry endTime -set 0.01 "$c/system/controlDict"
"$bin/isphDictionary" -entry writeInterval -set 0.01 "$c/system/controlDict"
"$bin/particleMesh" -case "$c" -spacing 0.04 > "$c/log.particleMesh" 2>&1 || { cat "$c/log.particleMesh"; exit 1; }
controlDict=$(cat "$c/system/controlDict")
line=$(grep -n '^maxCo ' "$c/system/controlDict" | cut -d: -f1)

# refused <what> <sed script> <pattern>...: controlDict edited by the script stops the solver
# with a non-zero exit, a message matching every pattern, and no time written
refused() {
    local what=$1 script=$2 out rc
    shift 2
    sed "$script" <<< "$controlDict" > "$c/system/controlDict"
    out=$("$bin/isphLandslideFoam" -case "$c" 2>&1)
    rc=$?
    [ "$rc" -ne 0 ] && pass "$what: the solver exits non-zero ($rc)" || fail "$what: the solver exited 0"
    for pattern; do
        grep -q "$pattern" <<< "$out" && pass "$what: '$pattern'" || fail "$what: no '$pattern' in: $out"
    done
    [ ! -d "$c/0.01" ] && pass "$what: nothing was run" || fail "$what: a time was written"
}

refused "maxCO" 's/^maxCo /maxCO /' "unknown keyword 'maxCO'.*(did you mean maxCo?)" "system/controlDict, line $line"

# a $variable close to a keyword: the user's own name
sed 's/^maxCo .*/maxCo0 0.2;\nmaxCo $maxCo0;/' <<< "$controlDict" > "$c/system/controlDict"
if "$bin/isphLandslideFoam" -case "$c" > "$c/log.variable" 2>&1 && [ -d "$c/0.01" ]
then
    pass "a \$variable named maxCo0 is allowed: the run reached 0.01 s"
else
    fail "a \$variable: $(tail -5 "$c/log.variable")"
fi
grep -q "unknown keyword" "$c/log.variable" && fail "the \$variable was warned about" || pass "no warning for the \$variable"
rm -rf "$c/0.01"

refused "maxCo twice" 's/^maxCo .*/maxCo 0.2;\nmaxCo 0.5;/' "keyword 'maxCo' is given twice.*first at line $line"

echo "testMisspeltKeyword: $nFail failed"
[ "$nFail" -eq 0 ]
