#pragma once
// hypre's error codes as isph errors. hypre keeps a global error flag that later calls
// return too, so each check clears what it has seen.
#include <HYPRE_utilities.h>

#include <string>

namespace isph {

// The text hypre gives for an error flag ("[Generic error] ...").
std::string hypreErrorText(HYPRE_Int ierr);

// FatalError naming `call` unless ierr is 0 or only HYPRE_ERROR_CONV ("did not converge",
// which our own residual check reports instead).
void hypreCheck(HYPRE_Int ierr, const char* call);

}  // namespace isph
