#!/bin/bash
# The Fei Tsui Road landslide tutorial, short: tutorials/landslides/feiTsui/Allrun -test (0.5 m
# spacing, both water tables) on a copy, then its results.txt:
#  - more water, longer run-out: with the 4 m water table (phi_e 22.33 deg) the deposit's front
#    (where the debris is 1 m deep) is at least as far out as with the 2 m one (23.24 deg; the
#    front moves in 0.5 m bins) and more debris lies on the road (by more than 1 %; measured
#    3.5 % at this spacing, 5.8 % at the tutorial's);
#  - the slide leaves the cut: each front at least 5 m out over the road (the slip surface is
#    steeper than either equivalent friction, so the mass must slide off the cut);
#  - the infinite-slope estimate of phi_e for this section's mean depth lies below the weak
#    layer's 29 deg and falls with the water table;
#  - no particle crossed a wall.
# usage: testFeiTsui.sh <project dir> <build dir>
. "${0%/*}/TutorialTest.sh"
runTutorial "$1" "$2" landslides/feiTsui
r2=$(value waterTable2m_runOut)
r4=$(value waterTable4m_runOut)
e2=$(value waterTable2m_infiniteSlopeEstimate)
e4=$(value waterTable4m_infiniteSlopeEstimate)
d2=$(value waterTable2m_debrisOnRoad)
d4=$(value waterTable4m_debrisOnRoad)
check "deposit front with a 4 m water table $r4 m >= that with 2 m $r2 m" "$r4 >= $r2"
check "debris on the road with a 4 m water table $d4 m3 > 1.01 x that with 2 m $d2 m3" "$d4 > 1.01 * $d2"
check "the 2 m slide leaves the cut: front $r2 m >= 5 m" "$r2 >= 5"
check "infinite-slope estimates $e4 deg < $e2 deg < 29 deg" "$e4 < $e2 && $e2 < 29"
check "no wall crossings" "$(value waterTable2m_wallCrossings) == 0 && $(value waterTable4m_wallCrossings) == 0"
exit $fail
