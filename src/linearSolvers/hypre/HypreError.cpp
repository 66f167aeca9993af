#include "linearSolvers/hypre/HypreError.hpp"

#include <fmt/format.h>

#include <array>

#include "core/Error.hpp"

namespace isph {

std::string hypreErrorText(HYPRE_Int ierr) {
  std::array<char, 1024> text{};
  HYPRE_DescribeError(ierr, text.data());
  return text.data();
}

void hypreCheck(HYPRE_Int ierr, const char* call) {
  if (ierr == 0) return;
  if (ierr == HYPRE_ERROR_CONV) {
    HYPRE_ClearAllErrors();
    return;
  }
  const std::string text = hypreErrorText(ierr);
  HYPRE_ClearAllErrors();
  fatalError(fmt::format("hypre: {} failed (error {}: {})", call, ierr, text));
}

}  // namespace isph
