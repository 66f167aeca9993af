#!/usr/bin/env bash
# Runs one libFuzzer target for a fixed time from a seed corpus taken from the tutorials, after
# replaying the inputs kept under tests/fuzz/regressions/<target>/. Fails on any finding (a
# crash, a sanitizer report, an uncaught exception, an input slower than 10 s, more than 2 GB);
# the input is left in <builddir>/fuzz/artifacts/<target>/: add it to tests/fuzz/regressions/
# <target>/ with the fix. Prints the executions made.
# Usage: runFuzzer.sh <fuzzer> <target> <seconds> <source dir> <build dir> [seed]
set -u
fuzzer=$(realpath "$1") target=$2 seconds=$3 src=$(realpath "$4") build=$(realpath "$5") seed=${6:-1}
work=$(mktemp -d "${TMPDIR:-/tmp}/isphFuzz.$target.XXXXXX")
trap 'rm -rf "$work"' EXIT
seeds=$work/seeds
mkdir -p "$seeds" "$work/corpus" "$build/fuzz/artifacts/$target"

# A field file as the field targets take it: a byte for the type (0 scalar, 1 label, 2 vector,
# 3 symmTensor), then the whole file (ascii) or the data after the header (binary).
typeByte() {
    case $(sed -n 's/^ *class *\([A-Za-z]*\);.*/\1/p' "$1" | head -1) in
    labelField) printf '\001' ;; vectorField) printf '\002' ;; symmTensorField) printf '\003' ;; *) printf '\000' ;;
    esac
}
fieldSeeds() {  # fieldSeeds ascii|binary: particleMesh's fields of the hydrostatic tank, coarse
    local c=$work/tank
    rm -rf "$c"
    mkdir -p "$c"
    cp -r "$src/tutorials/validation/hydrostaticTank/system" "$src/tutorials/validation/hydrostaticTank/constant" "$c"
    sed -i 's/^spacing .*/spacing 0.1;/' "$c/system/particleMeshDict"
    sed -i "s/^writeFormat .*/writeFormat $1;/" "$c/system/controlDict"
    "$build/bin/particleMesh" -case "$c" > "$work/log.particleMesh" 2>&1 || { cat "$work/log.particleMesh"; exit 1; }
    for f in "$c"/0/lagrangian/particles/*; do
        [ "$(head -c 2000 "$f" | grep -ac FoamFile)" -gt 0 ] || continue
        if [ "$1" = ascii ]; then
            { typeByte "$f"; cat "$f"; } > "$seeds/$(basename "$f")"
        else
            { typeByte "$f"; sed '1,/^\/\/ \* \* \*/d' "$f"; } > "$seeds/$(basename "$f")"
        fi
    done
}

case $target in
dictionary)
    find "$src/tutorials" "$src/etc/caseDicts" "$src/tests" -type f \( -path '*/system/*' -o -path '*/constant/*' \
        -o -path '*/caseDicts/*' \) ! -name '*.csv' -size -64k | while read -r f; do
        cp "$f" "$seeds/$(echo "${f#"$src"/}" | tr / _)"
    done ;;
csvPoints)
    find "$src/tutorials" "$src/tests" -type f -name '*.csv' -size -64k | while read -r f; do
        cp "$f" "$seeds/$(echo "${f#"$src"/}" | tr / _)"
    done ;;
fieldAscii) fieldSeeds ascii ;;
fieldBinary) fieldSeeds binary ;;
*) echo "runFuzzer.sh: unknown target $target" >&2; exit 2 ;;
esac
echo "seed corpus: $(ls "$seeds" | wc -l) inputs from the tutorials"

regressions=$src/tests/fuzz/regressions/$target
if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
    echo "replaying $(ls "$regressions" | wc -l) regression inputs from tests/fuzz/regressions/$target"
    "$fuzzer" -timeout=10 -rss_limit_mb=2048 "$regressions"/* > "$work/regressions.log" 2>&1 || {
        tail -40 "$work/regressions.log"; echo "FAIL: a regression input fails again"; exit 1; }
fi

cd "$work" || exit 1   # an input's relative #include is looked up here
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -seed="$seed" -print_final_stats=1 \
    -artifact_prefix="$build/fuzz/artifacts/$target/" "$work/corpus" "$seeds" > "$work/fuzz.log" 2>&1
rc=$?
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/fuzz.log")
echo "fuzz_$target: ${runs:-?} executions in $seconds s, corpus $(ls "$work/corpus" | wc -l) new inputs, exit $rc"
if [ "$rc" -ne 0 ]; then
    tail -60 "$work/fuzz.log"
    echo "FAIL: a finding; the input is in $build/fuzz/artifacts/$target/"
    exit 1
fi
