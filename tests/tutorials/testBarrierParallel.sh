#!/bin/bash
# The flagship's parallel path as its full ./Allrun takes it (decomposePar, runParallel on the
# two ranks of system/decomposeParDict, reconstructPar, then the same post-processing), at the
# -test spacing: `Allrun -test -parallel` on a copy, its results.txt against the case's
# validation/checks for -test runs (the same tolerances as the serial run's: two ranks sum in
# another order, which moves the figures within their run-to-run band, said in the checks).
# usage: testBarrierParallel.sh <project dir> <build dir>
. "${0%/*}/TutorialTest.sh"
project=$1
build=$2
export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ISPH_PROGRESS=off
export ISPH_MPIRUN_OPTIONS="--bind-to none --mca mpi_yield_when_idle 1"   # (doc/parallel.md)
. "$project/etc/RunFunctions"
. "$project/etc/ValidationFunctions"
case=$build/validation/quickParallel/barrier
results=$case/results.txt
rm -rf "$case"
mkdir -p "$case"
cp -r "$project/tutorials/landslides/barrier/." "$case/"
(cd "$case" && ./Allclean > /dev/null 2>&1 && ./Allrun -test -parallel > log.Allrun 2>&1) || {
    cat "$case/log.Allrun"
    tail -30 "$case/log.isphLandslideFoam"
    failTest "landslides/barrier/Allrun -test -parallel failed"
    exit 1
}
cat "$results"
check "the solver ran on 2 MPI ranks (log header)" "$(grep -c '^nProcs *: 2 (MPI ranks)' "$case/log.isphLandslideFoam") == 1"
check "two processor directories" "$(ls -d "$case"/processor* | wc -l) == 2"
check "reconstructPar merged the last time" "$([ -d "$case/2.5/lagrangian/particles" ] && echo 1 || echo 0) == 1"
checkTutorial
finish
