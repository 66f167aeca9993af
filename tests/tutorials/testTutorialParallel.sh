#!/bin/bash
# A tutorial's parallel path as its full ./Allrun takes it (runSolver: decomposePar,
# runParallel on the two ranks of system/decomposeParDict, reconstructPar, then the same
# post-processing), at the -test spacing: `Allrun -test -parallel` on a copy, its results.txt
# against the case's validation/checks for -test runs (the same tolerances as the serial
# run's: two ranks sum in another order, which moves the figures within their run-to-run
# band, said in each case's checks).
# usage: testTutorialParallel.sh <project dir> <build dir> <tutorial path under tutorials/>
. "${0%/*}/TutorialTest.sh"
project=$1
build=$2
tutorial=$3
export ISPH_PROJECT_DIR=$project ISPH_BUILD_DIR=$build
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ISPH_PROGRESS=off
export ISPH_MPIRUN_OPTIONS="--bind-to none --mca mpi_yield_when_idle 1"   # (doc/parallel.md)
. "$project/etc/RunFunctions"
. "$project/etc/ValidationFunctions"
case=$build/validation/quickParallel/${tutorial##*/}
results=$case/results.txt
rm -rf "$case"
mkdir -p "$case"
cp -r "$project/tutorials/$tutorial/." "$case/"
(cd "$case" && ./Allclean > /dev/null 2>&1 && ./Allrun -test -parallel > log.Allrun 2>&1) || {
    cat "$case/log.Allrun"
    tail -30 "$case/log.isphLandslideFoam"
    failTest "$tutorial/Allrun -test -parallel failed"
    exit 1
}
cat "$results"
check "the solver ran on 2 MPI ranks (log header)" "$(grep -c '^nProcs *: 2 (MPI ranks)' "$case/log.isphLandslideFoam") == 1"
check "two processor directories" "$(ls -d "$case"/processor* | wc -l) == 2"
end=$(sed -n 's/^endTime *\([0-9.eE+-]*\);.*/\1/p' "$case/system/controlDict")
check "reconstructPar merged the last time ($end)" "$([ -n "$end" ] && [ -d "$case/$end/lagrangian/particles" ] && echo 1 || echo 0) == 1"
checkTutorial
finish
