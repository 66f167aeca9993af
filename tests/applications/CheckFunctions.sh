# Sourced by the application test scripts: check <description> <command...> passes when the
# command succeeds and counts it (passed, fails: the caller prints and exits on them); has
# <text> <output> greps an output for a text.
passed=0 fails=0
check() {
  local what=$1; shift
  if "$@"; then echo "PASS: $what"; passed=$((passed + 1)); else echo "FAIL: $what"; fails=$((fails + 1)); fi
}
has() { grep -q -- "$1" <<< "$2"; }
