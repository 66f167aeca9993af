#!/bin/bash
# Issue 53's user: a copy of the barrier tutorial that has been run, turned into their own
# scene. A copy made with cp -r (holding the other run's output) is refused with the advice to
# clean it or use isphCloneCase, and its old results.txt is not rebuilt; a clone edited as a
# user would (slope 55 deg in constant/g with isphDictionary -set; the barrier moved to
# x = 1.8 m and the wall friction 20 deg in a particleMeshDict written OpenFOAM style, entries
# over several lines), then ./Allrun -test: results.txt and the plot titles give the new
# spacing, slope, barrier and friction, and the impact estimate is that of the flow arriving at
# the new barrier (not 0); the terminal shows the slope g implies.
# usage: testUserScene.sh <project dir> <build dir>
. "${0%/*}/TutorialTest.sh"
barrierClone "$1" "$2" ran
ran=$case
(cd "$ran" && ./Allrun -test > log.Allrun 2>&1) || { tail -30 "$ran/log.Allrun"; failTest "the barrier's Allrun -test failed"; exit 1; }

echo "--- a copy made with cp -r"
cp -r "$ran" "$scratch/copied"
cp "$ran/results.txt" "$scratch/results.before"
if (cd "$scratch/copied" && ./Allrun -test > log.Allrun 2>&1)
then
    failTest "the copy holding another run's output ran (it must be refused)"
fi
cat "$scratch/copied/log.Allrun"
grep -q "is the log of a run in another case ($ran)" "$scratch/copied/log.Allrun" ||
    failTest "the refusal names the other case"
grep -q "isphCloneCase <case> <copy>" "$scratch/copied/log.Allrun" || failTest "the refusal advises isphCloneCase"
cmp -s "$scratch/copied/results.txt" "$scratch/results.before" || failTest "the copy's old results.txt was rewritten"

echo "--- a clone, edited"
mine=$scratch/mine
isphCloneCase "$ran" "$mine"
leftovers=$(cd "$mine" && ls -d log.* results.txt postProcessing VTK ./*.png 0 0.* [1-9]* 2> /dev/null || true)
[ -z "$leftovers" ] || failTest "the clone holds output: $leftovers"
cd "$mine" || exit 1
g=$(awk 'BEGIN { t = 55 * atan2(1, 1) / 45; printf "(%.7g %.7g 0)", 9.81 * sin(t), -9.81 * cos(t) }')
isphDictionary -entry value -set "$g" constant/g || failTest "isphDictionary -set value in constant/g"
cat > system/particleMeshDict <<'DICT'
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      particleMeshDict;
}

spacing         0.0036;
lattice         square;
initialPressure lithostatic;

regions
{
    sand
    {
        type        box;
        min         (0 0 0);
        max         (0.5 0.242 0);
        material    sand;
    }
}

walls
{
    back
    {
        type            polyline;
        points          ((0 0.4 0) (0 0 0));
        frictionAngle   20;
    }
    bed
    {
        type            polyline;
        points
        (
            (0 0 0)
            (2.9 0 0)
        );
        frictionAngle   20;
    }
    barrier
    {
        type            box;
        min             (1.8 0 0);
        max             (1.82 0.3 0);
        frictionAngle   20;
    }
    catch
    {
        type            polyline;
        points          ((2.9 0 0) (2.9 3.0 0));
        frictionAngle   20;
        materialSide    left;
    }
}
DICT
./Allrun -test > log.Allrun 2>&1 || { tail -30 log.Allrun; failTest "the edited clone's Allrun -test failed"; exit 1; }
cat log.Allrun
results=$mine/results.txt
check "the spacing of the run" "$(value spacing) == 0.0108"
check "the slope from constant/g" "$(value slope) == 55"
check "the barrier's position" "$(value barrierPosition) == 1.8"
check "the barrier's height" "$(value barrierHeight) == 0.3"
check "the wall friction" "$(value wallFriction) == 20"
check "the width" "$(value width) == 0.3"
check "an impact estimate from the flow arriving at the new barrier" "$(value impactEstimate) > 100"
check "the peak per metre of width, in kN/m" "$(value peakForcePerWidth) * 1000 * 0.3 - $(value peakForce) < 0.01 * $(value peakForce)"
check "sand held behind the barrier" "$(value massBehindBarrier) > 1"
grep -q "Normal force of the sand on the barrier (55.0 deg slope; barrier 0.3 m high at x = 1.8 m; 0.3 m wide)" log.Allrun ||
    failTest "barrierForce.png's title gives the slope and the barrier"
grep -q "deposit.png (Sand at t = 2.5 s (55.0 deg slope" log.Allrun || failTest "deposit.png's title gives the slope"
grep -q "55.0 deg from -y" log.Allrun || failTest "the terminal shows the slope g implies"
finish
