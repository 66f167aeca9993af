#!/bin/bash
# benchmark-smoke: tutorials/benchmarks/scaling/Allrun at its smallest size (10k particles,
# 3 steps, one thread, the column collapse, each run twice: -repeat 2; on 1 and on 2 MPI ranks)
# on a copy: its CSV rows hold what the issue asks for, with values a working solver gives
# (bounds stated below); then the column as a 3D slab (-cases columnCollapse3D), 2 steps. OpenMPI refuses root (CI) unless told: set here.
#   testScaling.sh <project dir> <build dir>
. "$1/tests/tutorials/TutorialTest.sh"
project=$1 build=$2
work=$(mktemp -d /tmp/isphTest-scaling.XXXXXX)
scratch=$work
cp -r "$project/tutorials/benchmarks/scaling" "$work/"
export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export ISPH_MPIRUN_OPTIONS="--oversubscribe --bind-to none --mca mpi_yield_when_idle 1"
if ! "$work/scaling/Allrun" -sizes 10k -threads 1 -ranks "1 2" -steps 3 -cases columnCollapse -repeat 2 > "$work/Allrun.log" 2>&1
then
    cat "$work/Allrun.log"
    exit 1
fi
cat "$work/Allrun.log"
csv=$work/scaling/results.csv
row=$(sed -n 2p "$csv")
field() { echo "$row" | cut -d, -f"$1"; }
check "one row per rank count" "$(wc -l < "$csv") == 3"
check "the rows are of 1 and 2 ranks" "$(field 14) == 1 && $(sed -n 3p "$csv" | cut -d, -f14) == 2"
check "both rank counts have the same particles" "$(field 2) == $(sed -n 3p "$csv" | cut -d, -f2)"
check "about 10k material particles (9,000-11,000)" "$(field 2) >= 9000 && $(field 2) <= 11000"
check "walls and dummies counted in all particles" "$(field 3) > $(field 2)"
check "3 steps" "$(field 5) == 3"
check "a wall time, and particle-steps per second consistent with it" \
      "$(field 6) > 0 && ($(field 8) * $(field 6) / ($(field 2) * 3) - 1)^2 < 1e-4"
check "mean neighbours of a 2D lattice with h = 1.3 dx (15-25)" "$(field 9) >= 15 && $(field 9) <= 25"
check "PPE iterations of BoomerAMG-PCG (1-50)" "$(field 10) >= 1 && $(field 10) <= 50"
check "peak memory reported (10-2000 MB)" "$(field 11) >= 10 && $(field 11) <= 2000"
runs=$(field 13)
check "both repeats' wall times recorded" "$(echo "$runs" | wc -w) == 2"
lower=$(echo "$runs" | tr ' ' '\n' | sort -g | head -1)
check "the row is the median run's (the lower of two): wall time $(field 6) s of $runs" "($(field 6) - $lower)^2 < 1e-6"
share=$(awk -F, 'NR > 1 && $7 == 1 { s += $6 } END { print s }' "$work/scaling/phases.csv")
check "the phase shares add up to 100% (99-101)" "$share >= 99 && $share <= 101"
check "the PPE solve is among the phases of each rank count" "$(grep -c ',PPE solve,' "$work/scaling/phases.csv") == 2"
check "the 2-rank run's phases include its migration and ghosts" "$(grep -c ',migration and ghosts,.*,2$' "$work/scaling/phases.csv") == 1"
check "summary.txt written, a spread per rank count" "$(grep -c 'spread' "$work/scaling/summary.txt") == 2"
check "summary.txt has the 1 / 2 ranks speed-up of the step" "$(grep -c '1 / 2 ranks: .* s / .* s = .*x$' "$work/scaling/summary.txt") >= 1"

# The 3D case: the spacing from the material's volume, the slab between side walls.
cp -r "$project/tutorials/benchmarks/scaling" "$work/scaling3D"
if ! "$work/scaling3D/Allrun" -sizes 10k -threads 1 -steps 2 -cases columnCollapse3D > "$work/Allrun3D.log" 2>&1
then
    cat "$work/Allrun3D.log"
    exit 1
fi
row=$(sed -n 2p "$work/scaling3D/results.csv")
log=$work/scaling3D/runs/columnCollapse3D-10k-1-np1-r1/log.isphLandslideFoam
check "3D: the solver ran a 3D cloud" "$(grep -c '^ *3D, [0-9]* particles' "$log") == 1"
check "3D: about 10k material particles (9,000-11,000)" "$(field 2) >= 9000 && $(field 2) <= 11000"
check "3D: mean neighbours of a cubic lattice with h = 1.3 dx (55-80)" "$(field 9) >= 55 && $(field 9) <= 80"
check "3D: side walls in the cloud (the patch sideWalls)" \
      "$(grep -c 'sideWalls' "$work/scaling3D/runs/columnCollapse3D-10k-mesh/0/lagrangian/particles/cloudProperties") >= 1"
finish
