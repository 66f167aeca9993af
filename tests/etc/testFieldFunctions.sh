#!/bin/bash
# etc/FieldFunctions: materialParticles and materialPoints on a case written by particleMesh
# (ascii and binary; materialPoints on a 3D scene).
# usage: testFieldFunctions.sh <project dir> <bin dir>
set -u
project=$1
bin=$2
work=$(mktemp -d /tmp/isphTest-FieldFunctions.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fail=1; fi; }

. "$project/etc/FieldFunctions"
mkdir -p "$work/case/system" "$work/case/constant"
cd "$work/case" || exit 1
header='FoamFile { version 2.0; format ascii; class dictionary; object X; }'
echo "$header application isphLandslideFoam; startTime 0; endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1; writeFormat ascii;" > system/controlDict
echo "$header materials { sand { model rigidPlastic; rho 1500; phi 30; } }" > constant/materialProperties
echo "$header dimensions [0 1 -2 0 0 0 0]; value (0 -9.81 0);" > constant/g
cat > system/particleMeshDict <<DICT
$header
spacing 0.1; cloud particles; lattice square; initialPressure lithostatic;
regions { sand { type box; min (0 0 0); max (0.5 0.3 0); material sand; } }
walls { bed { type polyline; points ((-0.2 0 0) (0.7 0 0)); frictionAngle 20; materialSide left; } }
DICT
"$bin/particleMesh" > log.particleMesh 2>&1 || { cat log.particleMesh; exit 1; }
n=$(sed -n 's/^ *sand *\([0-9][0-9]*\) particles.*/\1/p' log.particleMesh | head -1)
out=$(materialParticles 0)
check "one line per sand particle ($n)" '[ "$(printf "%s\n" "$out" | wc -l)" -eq "$n" ]'
check "four numbers a line: x y ux uy, inside the box, at rest" \
    'printf "%s\n" "$out" | awk "NF != 4 || \$1 < 0 || \$1 > 0.5 || \$2 < 0 || \$2 > 0.3 || \$3 != 0 || \$4 != 0 { bad = 1 } END { exit bad }"'
check "a missing time is an error naming the field" \
    '! materialParticles 9 2> err && grep -q "no field 9/lagrangian/particles/kind" err'
# materialPoints: the same box as a 3D scene, 0.2 m wide (two layers at z = 0.05 and 0.15).
sed -i 's/^spacing 0.1;/spacing 0.1; dimension 3; width 0.2;/' system/particleMeshDict
rm -rf 0 && "$bin/particleMesh" > log.particleMesh 2>&1 || { cat log.particleMesh; exit 1; }
out=$(materialPoints 0)
check "materialPoints: one line per sand particle of the 3D scene (2 x $n)" '[ "$(printf "%s\n" "$out" | wc -l)" -eq $((2 * n)) ]'
check "materialPoints: x y z, inside the box, z in the two layers" \
    'printf "%s\n" "$out" | awk "NF != 3 || \$1 < 0 || \$1 > 0.5 || \$2 < 0 || \$2 > 0.3 || (\$3 != 0.05 && \$3 != 0.15) { bad = 1 } END { exit bad }"'
check "materialPoints: a missing time is an error naming the field" \
    '! materialPoints 9 2> err && grep -q "materialPoints: no field 9/lagrangian/particles/kind" err'
sed -i 's/ dimension 3; width 0.2;//' system/particleMeshDict
sed -i 's/writeFormat ascii;/writeFormat binary;/' system/controlDict
rm -rf 0 && "$bin/particleMesh" > log.particleMesh 2>&1
if grep -q 'format *binary' 0/lagrangian/particles/positions 2>/dev/null
then
    check "binary fields are refused with the remedy" \
        '! materialParticles 0 2> err && grep -q "set writeFormat ascii" err'
else
    echo "skip: particleMesh wrote ascii (no binary case to check)"
fi
exit $fail
