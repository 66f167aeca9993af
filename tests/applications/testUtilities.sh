#!/usr/bin/env bash
# The foundation utilities as a user runs them: exit codes, -help, -case, time selection,
# and error messages that name the file, line and keyword. Usage: testUtilities.sh <bindir>
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
check() {  # check <description> <command...>: the command must succeed
  local what=$1; shift
  if "$@"; then echo "PASS: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}

mkdir -p "$work/case/system" "$work/case/0" "$work/case/0.1" "$work/case/0.25" "$work/case/1e-05" "$work/case/constant"
cat > "$work/case/system/controlDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     isphLandslideFoam;   // the solver
endTime         2.5;
DICT
printf 'a 1;\nb 2\nc 3;\n' > "$work/case/system/broken"

check "-help exits 0 and prints the usage" bash -c "'$bin/isphDictionary' -help | grep -q 'Usage: isphDictionary'"
check "getApplication form prints the value" bash -c "[ \"\$('$bin/isphDictionary' -case '$work/case' -entry application -value '$work/case/system/controlDict')\" = isphLandslideFoam ]"
out=$("$bin/isphDictionary" "$work/case/system/broken" 2>&1); rc=$?
check "a missing ';' exits non-zero" test "$rc" -ne 0
check "the error names the file and line" bash -c "grep -q 'system/broken, line 2' <<< \"\$1\"" _ "$out"
out=$("$bin/isphDictionary" -entry nothing "$work/case/system/controlDict" 2>&1); rc=$?
check "a missing keyword exits non-zero and names it" bash -c "[ $rc -ne 0 ] && grep -q \"keyword 'nothing' is undefined\" <<< \"\$1\"" _ "$out"
out=$("$bin/isphDictionary" -entri x "$work/case/system/controlDict" 2>&1); rc=$?
check "an unknown option suggests the nearest" bash -c "[ $rc -ne 0 ] && grep -q 'did you mean -entry' <<< \"\$1\"" _ "$out"
out=$("$bin/isphListTimes" -case "$work/nowhere" 2>&1); rc=$?
check "a missing case directory is an error" bash -c "[ $rc -ne 0 ] && grep -q 'does not exist' <<< \"\$1\"" _ "$out"
check "isphListTimes lists times in order" bash -c "[ \"\$('$bin/isphListTimes' -case '$work/case' | tr '\n' ' ')\" = '0 1e-05 0.1 0.25 ' ]"
check "-noZero" bash -c "[ \"\$('$bin/isphListTimes' -case '$work/case' -noZero | tr '\n' ' ')\" = '1e-05 0.1 0.25 ' ]"
check "-latestTime" bash -c "[ \"\$('$bin/isphListTimes' -case '$work/case' -latestTime)\" = 0.25 ]"
check "-time ranges" bash -c "[ \"\$('$bin/isphListTimes' -case '$work/case' -time '0.05:0.2,0.25' | tr '\n' ' ')\" = '0.1 0.25 ' ]"
out=$("$bin/isphListTimes" -case "$work/case" -time 'a:b' 2>&1); rc=$?
check "a bad -time is an error naming the option" bash -c "[ $rc -ne 0 ] && grep -q -- '-time' <<< \"\$1\"" _ "$out"
"$bin/isphListTimes" -case "$work/case" -noZero -rm
check "-rm removes the selected times and keeps 0" bash -c "[ -d '$work/case/0' ] && [ ! -d '$work/case/0.1' ]"

echo "$((13 - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
