#!/bin/bash
# benchmark-smoke: tutorials/benchmarks/speedAccuracy/Allrun -smoke on a copy (every case and
# method at the coarsest spacing; the layer at rest for 0.1 s, the column collapse for 0.2 s,
# the barrier for 1 s by implicit and elasticPlastic),
# then: a row per case and method, every run finished, the errors finite and within loose
# bounds that a broken method fails (a blown-up, creeping, frozen or runaway run), a PNG
# per case, and -repeat 2: two CPU times per finished run, the recorded one their median.   testSpeedAccuracy.sh <project dir> <build dir>
set -u
project=$1
build=$2
work=$(mktemp -d "/tmp/isphTest-speedAccuracy.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp -r "$project/tutorials/benchmarks/speedAccuracy" "$work/"
export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
# -budget is wall clock for the whole smoke (no run starts after it): 400 s, so that a loaded
# machine still runs every case. At load 16-22 on 2 cores (2026-12-04) its 150 s held about
# 23 s of solver CPU (the CSV's cpuTimeRuns): the column collapse's wcsph run was cut
# (notFinished) and the dam break not run, which failed the checks below on the machine's
# load. 400 s plus one run's cap stays inside the test's 600 s timeout.
"$work/speedAccuracy/Allrun" -smoke -repeat 2 -cap 120 -budget 400 > "$work/Allrun.log" 2>&1
rc=$?
cat "$work/Allrun.log"
[ "$rc" -eq 0 ] || { echo "FAIL: Allrun -smoke exited $rc"; exit 1; }
csv=$work/speedAccuracy/results.csv
methods=$(sed -n 's/^methods="\(.*\)"$/\1/p' "$work/speedAccuracy/Allrun")
fail=0

# check <case> <description> <awk condition on a row, $k = column k>: every run of the case
# (not the rows the benchmark does not run: notRun) must satisfy it, and there must be one.
check() {
    local c=$1 what=$2 cond=$3
    if awk -F, -v c="$c" "NR > 1 && \$1 == c && \$8 != \"notRun\" { n++; if (!($cond)) { bad++; print \"  \" \$0 } }
                          END { exit !(n && !bad) }" "$csv"
    then echo "ok:   $c: $what"; else echo "FAIL: $c: $what ($cond)"; fail=1; fi
}
finite() { echo "($1 != \"\" && $1 + 0 == $1 && $1 !~ /nan|inf/)"; }

for c in granularAtRest columnCollapse damBreak barrier
do
    for m in $methods
    do
        n=$(awk -F, -v c="$c" -v m="$m" '$1 == c && $2 == m' "$csv" | wc -l)
        if [ "$n" -eq 1 ]; then echo "ok:   $c $m: one row"; else echo "FAIL: $c $m: $n rows"; fail=1; fi
    done
    [ "$c" = barrier ] && continue   # below: only implicit must finish there
    check "$c" "every run finished, with steps and a cost" "\$8 == \"ok\" && \$5 > 0 && \$6 > 0"
    check "$c" "two timed runs, the cost their median" \
        "split(\$23, t, \";\") == 2 && t[1] > 0 && t[2] > 0 && (\$6 - (t[1] + t[2]) / 2) ^ 2 < 1e-10 * \$6 ^ 2"
done
# The dam break is water: explicit plasticity is implicit there, elasticPlastic is wcsph.
for m in explicit elasticPlastic
do
    if awk -F, -v m=$m '$1 == "damBreak" && $2 == m && $8 != "notRun" { exit 1 }' "$csv"
    then echo "ok:   damBreak $m: not run"; else echo "FAIL: damBreak $m was run"; fail=1; fi
done

# The layer at rest (20 mm, 0.1 s, five particles over the depth), judged by the tractions on
# bed-parallel planes, which statics fixes (p itself is not: README). A one-thread run is
# deterministic (the -repeat 2 below fails a repeat that takes other steps), so there is no
# run-to-run noise to size these limits by: they are failure detectors, each well between the
# measured values (the smoke run of 2026-12-04) and what a broken method gives. sigma_nn within 50 % (L2)
# of rho |g| cos(beta) depth (p = 0 is 100 %; measured: implicit 19.2 %, explicit 22.6 %, wcsph
# 8.1 %, elasticPlastic 18.4 %), sigma_nt within 80 % of rho |g| sin(beta) depth (tau = 0 is
# 100 %; measured 34.3, 42.9, 47.9, 49.6 %), nothing moved more than dx/4 = 5 mm (measured
# below 1 mm; a creeping layer does: explicit plasticity with etaMax 100 moved 11.6 mm in 0.1 s).
check granularAtRest "L2 error of sigma_nn < 0.5" "$(finite '$11') && \$11 < 0.5"
check granularAtRest "L2 error of sigma_nt < 0.8" "$(finite '$12') && \$12 < 0.8"
check granularAtRest "largest displacement < dx/4" "$(finite '$13') && \$13 < 0.25 * \$3"
# The column collapse (10 mm, 0.2 s, against the final deposit, toe 0.4423 m): the toe has
# left the column (error above -50 %: a column that does not move is at -55 %; measured -38.6
# to -40.0 %; elasticPlastic -37.7 %) and is not past the measured final toe by more than 20 % (a runaway is); the
# surface within 4 cm RMS of the final one (the column is 10 cm high; measured 2.8-3.0 cm).
check columnCollapse "run-out error in (-50 %, 20 %)" "$(finite '$14') && \$14 > -50 && \$14 < 20"
check columnCollapse "surface RMS < 0.04 m" "$(finite '$15') && \$15 < 0.04"
# The dam break (a/5, 0.17 s): the front within 25 % of Martin & Moyce for T <= 3 at every
# written time, 15 % on average (measured: implicit 9.8 % and 6.2 %, wcsph 14.6 % and 6.2 %; a
# front that stays at Z = 1 is 73 % behind the measured Z = 3.6 at T = 3).
check damBreak "largest front error < 25 %" "$(finite '$16') && \$16 < 25"
check damBreak "mean front error < 15 %" "$(finite '$17') && \$17 < 15"

# The barrier (10.8 mm, 1 s, through the impact at 0.83 s). implicit finishes; elasticPlastic
# with the column's stiffness stops when the impact compresses a particle by more than 10 %
# (0.77 s; README), which must be named, not an unexplained exit; explicit and wcsph are not
# run in the smoke. Failure detectors, as above (one thread is deterministic; measured
# 2026-12-05): the barrier's peak of 0.02 s means, 819.6 N, above 100 N (a barrier the sand
# never reaches reads 0) and below 5,000 N (a blown-up run's spikes); the walls against the
# load cell over the last 0.25 s, mid-impact, within 100 % (measured +21.8 % along the bed,
# +40.4 % normal to it; a force routine that loses a wall is off by its whole share).
if awk -F, '$1 == "barrier" && $2 == "implicit" && $8 == "ok" && $5 > 0 && $6 > 0 { found = 1 } END { exit !found }' "$csv"
then echo "ok:   barrier implicit finished"; else echo "FAIL: barrier implicit did not finish"; fail=1; fi
if awk -F, '$1 == "barrier" && $8 != "notRun" && $8 !~ /^(ok|notFinished|diverged|leftTheDomain|compressedBeyondWcsphLimit|didNotConverge|wallCrossings)$/ { bad = 1; print "  " $0 }
            END { exit bad }' "$csv"
then echo "ok:   barrier: every run finished or named why not"; else echo "FAIL: barrier: a run stopped without a named reason"; fail=1; fi
awk -F, '$1 == "barrier" && $2 == "implicit"' "$csv" > "$work/barrierImplicit.csv"
barrierCheck() {
    if awk -F, "{ n++; if (!($2)) bad = 1 } END { exit !(n && !bad) }" "$work/barrierImplicit.csv"
    then echo "ok:   barrier implicit: $1"; else echo "FAIL: barrier implicit: $1 ($2)"; fail=1; fi
}
barrierCheck "peak force in (100, 5000) N" "$(finite '$18') && \$18 > 100 && \$18 < 5000"
barrierCheck "walls against the load cell within 100 % along the bed" "$(finite '$20') && \$20 > -100 && \$20 < 100"
barrierCheck "walls against the load cell within 100 % normal to it" "$(finite '$21') && \$21 > -100 && \$21 < 100"

if command -v gnuplot > /dev/null 2>&1
then
    for c in granularAtRest columnCollapse damBreak barrier
    do
        if head -c 4 "$work/speedAccuracy/$c.png" 2> /dev/null | grep -q PNG
        then echo "ok:   $c.png written"; else echo "FAIL: no $c.png"; fail=1; fi
    done
else
    echo "(gnuplot is not installed here: the PNG checks are skipped)"
fi
exit $fail
