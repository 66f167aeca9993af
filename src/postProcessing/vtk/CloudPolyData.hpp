#pragma once
// A cloud as VTK PolyData, what toVTK writes for one time: one vertex per particle, every
// selected particle field as point data, and what users look at beside them:
//  - point data: each field under its own name (labels as Int32; vectors 3 components;
//    symmTensors as full 3×3 tensors, 9 components xx xy xz yx yy yz zx zy zz, which ParaView
//    recognises), plus the derived
//      magU    |U| [m/s]                              (when U is selected)
//      stress  σ = −p I + τ, 9 components [Pa]        (when p is selected; τ: the `tau`
//              field when it is selected too, else the pressure part only)
//  - field data: TimeValue (ParaView's time), materialNames and patchNames (string arrays that
//    the `material` and `patch` labels index) and kindNames (material wall dummy, for `kind`).
// With noWalls only material particles (kind 0) are kept.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "postProcessing/vtk/CloudFields.hpp"

namespace isph {

struct PolyDataOptions {
  bool noWalls = false;  // leave out wall and dummy particles
};

vtkSmartPointer<vtkPolyData> cloudPolyData(const CloudFields& fields, double time, const PolyDataOptions& options);

}  // namespace isph
