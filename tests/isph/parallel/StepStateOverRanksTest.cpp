// The solver state of a parallel restart (StepStateOverRanks.hpp): each rank keeps the by-origId
// entries of the particles it read and the ranks' entries are summed, so that every rank holds
// every particle's, whichever rank wrote them and whatever else its processor's file held.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "isph/parallel/StepStateOverRanks.hpp"
#include "parallel/Reduce.hpp"

namespace {

using namespace isph;

constexpr label nParticles = 10;

// What a particle's entries are: a function of its origId (0 for free, stick or slide: 1 + id % 2).
label stateOf(label id) { return 1 + id % 2; }
Vec3 directionOf(label id) { return Vec3(0.1 * id, -0.25, 1.0 / (id + 3.0)); }
Vec3 incrementOf(label id) { return Vec3(1e-3 * id, 2e-7 / (id + 1.0), -0.5 * id); }

// The state as a rank wrote it: the entries of `ids` by origId, the others zero, arrays as long
// as the largest of `ids` needs; `garbage` fills the others (decomposePar copies the whole).
StepState writtenState(const std::vector<label>& ids, bool garbage) {
  StepState s;
  label size = 0;
  for (const label id : ids) size = std::max(size, id + 1);
  if (garbage) size = nParticles;
  s.frictionStates.assign(static_cast<std::size_t>(size), garbage ? 2 : 0);
  s.slipDirections.assign(static_cast<std::size_t>(size), garbage ? Vec3(9, 9, 9) : Vec3(Vec3::Zero()));
  s.viscousIncrements.assign(static_cast<std::size_t>(size), garbage ? Vec3(7, 7, 7) : Vec3(Vec3::Zero()));
  for (const label id : ids) {
    const auto i = static_cast<std::size_t>(id);
    s.frictionStates[i] = stateOf(id);
    s.slipDirections[i] = directionOf(id);
    s.viscousIncrements[i] = incrementOf(id);
  }
  return s;
}

// Rank r of n read every n-th particle from r (so the ranks' arrays differ in length).
std::vector<label> readIds() {
  std::vector<label> ids;
  for (label id = thisRank(); id < nParticles; id += nRanks()) ids.push_back(id);
  return ids;
}

void expectEveryParticlesEntries(const StepState& s) {
  ASSERT_EQ(s.frictionStates.size(), static_cast<std::size_t>(nParticles));
  ASSERT_EQ(s.slipDirections.size(), static_cast<std::size_t>(nParticles));
  ASSERT_EQ(s.viscousIncrements.size(), static_cast<std::size_t>(nParticles));
  for (label id = 0; id < nParticles; ++id) {
    const auto i = static_cast<std::size_t>(id);
    EXPECT_EQ(s.frictionStates[i], stateOf(id)) << "origId " << id;
    EXPECT_EQ(s.slipDirections[i], directionOf(id)) << "origId " << id;  // exactly: x + 0 = x
    EXPECT_EQ(s.viscousIncrements[i], incrementOf(id)) << "origId " << id;
  }
}

TEST(StepStateOverRanks, EveryRankGetsEveryParticlesEntriesFromTheRankThatReadIt) {
  StepState s = writtenState(readIds(), false);
  gatherStepStateArrays(s, readIds());
  expectEveryParticlesEntries(s);
}

TEST(StepStateOverRanks, TheEntriesOfParticlesARankDidNotReadAreDropped) {
  StepState s = writtenState(readIds(), true);  // a processor folder from decomposePar: the whole arrays
  gatherStepStateArrays(s, readIds());
  expectEveryParticlesEntries(s);
}

TEST(StepStateOverRanks, AStateMissingOnSomeRankIsUsedByNone) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("isphStepStateOverRanks-" + std::to_string(sumOverRanks(static_cast<long>(::getpid()))) + "-" +
                    std::to_string(thisRank()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const bool withState = thisRank() != nRanks() - 1 || nRanks() == 1;
  if (withState) writeStepState(dir, writtenState(readIds(), false), WriteFormat::ascii);
  const auto state = readStepStateOverRanks(dir, true, readIds());
  EXPECT_EQ(state.has_value(), nRanks() == 1);
  if (state) expectEveryParticlesEntries(*state);
  std::filesystem::remove_all(dir);
}

}  // namespace
