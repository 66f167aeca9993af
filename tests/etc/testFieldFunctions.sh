#!/bin/bash
# etc/FieldFunctions: materialParticles on a case written by particleMesh (ascii and binary).
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
