#include "isph/parallel/StepStateOverRanks.hpp"

#include <fmt/format.h>

#include <span>
#include <type_traits>

#include "core/Error.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

// `values` (by origId) with the entries of the other ranks' particles set to zero, resized to
// the longest over the ranks and summed over them.
template <class T>
void sumOwnEntries(std::vector<T>& values, const std::vector<char>& mine, const T& zero) {
  for (std::size_t id = 0; id < values.size(); ++id) {
    if (id >= mine.size() || !mine[id]) values[id] = zero;
  }
  values.resize(maxOverRanks(values.size()), zero);
  if constexpr (std::is_same_v<T, Vec3>) {
    sumOverRanks(std::span<double>(values.empty() ? nullptr : values.front().data(), 3 * values.size()));
  } else {
    std::vector<long> wide(values.begin(), values.end());
    sumOverRanks(std::span<long>(wide));
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<T>(wide[i]);
  }
}

}  // namespace

void gatherStepStateArrays(StepState& state, const std::vector<label>& readIds) {
  std::vector<char> mine;
  for (const label id : readIds) {
    if (id < 0) continue;
    if (static_cast<std::size_t>(id) >= mine.size()) mine.resize(static_cast<std::size_t>(id) + 1, 0);
    mine[static_cast<std::size_t>(id)] = 1;
  }
  sumOwnEntries<label>(state.frictionStates, mine, 0);
  sumOwnEntries<Vec3>(state.slipDirections, mine, Vec3::Zero());
  sumOwnEntries<Vec3>(state.viscousIncrements, mine, Vec3::Zero());
}

std::optional<StepState> readStepStateOverRanks(const std::filesystem::path& startDir, bool decomposed,
                                                const std::vector<label>& readIds) {
  std::optional<StepState> state = readStepState(startDir);
  const bool everyRank = allRanks(state.has_value()), someRank = anyRank(state.has_value());
  if (!everyRank) {
    if (someRank) {
      warning(fmt::format("the solver state (uniform/isphState) of time {} is missing in some processor "
                          "directories: the run starts without it (not as the uninterrupted run would go on)",
                          startDir.filename().string()));
    }
    return std::nullopt;
  }
  if (decomposed) gatherStepStateArrays(*state, readIds);
  return state;
}

}  // namespace isph
