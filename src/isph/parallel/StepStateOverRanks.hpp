#pragma once
// The solver state (StepState.hpp) at the start of a parallel run (doc/parallel.md). Each rank
// of a parallel run writes processor<rank>/<time>/uniform/ with the state's scalars, which are
// the same on every rank, and the by-origId arrays (wall friction states, slip directions, the
// velocity solve's warm start) of its own particles. A restart partitions the particles anew,
// so a particle may start on another rank than the one that wrote its entries:
//  - from a decomposed case each rank keeps the entries of the particles it read (decomposePar
//    copies a serial time's whole arrays to every processor), and the ranks' entries are summed
//    (each particle's come from one rank): every rank then holds every particle's;
//  - from an undecomposed time every rank reads the case's own <time>/uniform, whole.
// A state on some ranks only (a processor's uniform/ lost) is used by none, with a warning:
// the run starts as from a time written without it. Collective.
#include <filesystem>
#include <optional>
#include <vector>

#include "core/Types.hpp"
#include "isph/timeStepping/StepState.hpp"

namespace isph {

// `startDir`: the start time's folder (Time::startPath); `decomposed`: it is processor<rank>'s;
// `readIds`: the origIds of the particles this rank read from it.
std::optional<StepState> readStepStateOverRanks(const std::filesystem::path& startDir, bool decomposed,
                                                const std::vector<label>& readIds);

// Each array of `state` with only the entries of `readIds` kept, summed over the ranks.
void gatherStepStateArrays(StepState& state, const std::vector<label>& readIds);

}  // namespace isph
