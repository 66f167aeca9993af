// The processor directories of a decomposed case: decomposeTime writes each part's particles
// with every field (the cloud's and the solver's others), reconstructTime merges them back
// into exactly the undecomposed time, ordered material, wall, dummy by origId, and
// DecomposedTime gives a utility that merge in a folder of its own, removed afterwards.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "ParallelTestHelpers.hpp"
#include "core/Error.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/io/AtomicFile.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/DecompositionRecord.hpp"
#include "parallel/Reduce.hpp"
#include "particles/CloudIO.hpp"

namespace {

using namespace isph;
namespace fs = std::filesystem;

// A case with time 0.5 holding a lattice cloud, a symmTensor field and a label field beside it.
struct Case {
  fs::path dir;
  ParticleCloud cloud;
  std::vector<SymmTensor> tau;
  std::vector<label> flags;
  Case() : dir(fs::temp_directory_path() / ("isphDecomposedCase-" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    cloud = test::latticeCloud(12, 9, 1, 0.01);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      SymmTensor t;
      t << 1.0 * i, 2.0, 3.0, 4.0, 5.0, -1.0 * i;
      tau.push_back(t);
      flags.push_back(static_cast<label>(i % 3));
    }
    const fs::path time = dir / "0.5";
    const FieldWriteOptions binary{WriteFormat::binary, 8, "0.5/lagrangian/particles"};
    writeCloud(time, "0.5", cloud, {WriteFormat::ascii, 8, ""});
    writeField(time / "lagrangian/particles/tau", tau, binary);
    writeField(time / "lagrangian/particles/freeSurface", flags, binary);
    fs::create_directories(time / "uniform");
    writeFileAtomic(time / "uniform/time", "FoamFile { class dictionary; object time; }\nvalue 0.5;\n");
    cloud = readCloud(time, "particles");  // as written: 8 digits
  }
  ~Case() { fs::remove_all(dir); }
};

TEST(DecomposedCase, DecomposeThenReconstructGivesBackEveryFieldExactly) {
  if (thisRank() != 0) GTEST_SKIP() << "files only: rank 0 does it";
  Case c;
  const int nParts = 3;
  std::vector<int> part(c.cloud.size());
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = static_cast<int>((i * 7) % nParts);
  decomposeTime(c.dir, "0.5", "particles", part, nParts);
  for (int p = 0; p < nParts; ++p) {  // (as decomposePar records it)
    writeDecompositionRecord(c.dir / processorName(p), nParts, static_cast<long>(c.cloud.size()));
  }
  ASSERT_EQ(nProcessorDirectories(c.dir), nParts);
  for (int p = 0; p < nParts; ++p) {
    const fs::path time = c.dir / processorName(p) / "0.5";
    const ParticleCloud mine = readCloud(time, "particles");
    const auto tau = readField<SymmTensor>(time / "lagrangian/particles/tau", mine.size());
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const auto i = static_cast<std::size_t>(mine.origId[k]);
      EXPECT_EQ(part[i], p);
      EXPECT_EQ(mine.positions[k], c.cloud.positions[i]);
      EXPECT_EQ(tau[k], c.tau[i]);
    }
    EXPECT_TRUE(fs::exists(time / "uniform/time"));
    EXPECT_EQ(readFieldInfo(time / "lagrangian/particles/tau").format, WriteFormat::binary);
  }
  EXPECT_EQ(decomposedTimes(c.dir).size(), 1u);

  const fs::path merged = c.dir / "merged";
  fs::create_directories(merged);
  EXPECT_EQ(reconstructTime(c.dir, nParts, "0.5", merged), c.cloud.size());
  const ParticleCloud back = readCloud(merged, "particles");
  const auto tau = readField<SymmTensor>(merged / "lagrangian/particles/tau", back.size());
  const auto flags = readField<label>(merged / "lagrangian/particles/freeSurface", back.size());
  ASSERT_EQ(back.size(), c.cloud.size());
  for (std::size_t k = 0; k < back.size(); ++k) {
    if (k > 0) {
      EXPECT_TRUE(back.kind[k - 1] < back.kind[k] || (back.kind[k - 1] == back.kind[k] && back.origId[k - 1] < back.origId[k]))
          << "ordered by kind, then origId";
    }
    const auto i = static_cast<std::size_t>(back.origId[k]);
    EXPECT_EQ(back.positions[k], c.cloud.positions[i]);  // ascii written to 17 digits: exact
    EXPECT_EQ(back.U[k], c.cloud.U[i]);
    EXPECT_EQ(back.p[k], c.cloud.p[i]);
    EXPECT_EQ(back.mass[k], c.cloud.mass[i]);
    EXPECT_EQ(back.normal[k], c.cloud.normal[i]);
    EXPECT_EQ(back.kind[k], c.cloud.kind[i]);
    EXPECT_EQ(tau[k], c.tau[i]);
    EXPECT_EQ(flags[k], c.flags[i]);
  }
  EXPECT_TRUE(fs::exists(merged / "uniform/time"));

  {
    const DecomposedTime view(c.dir, "0.5", true);
    EXPECT_EQ(readCloud(view.path(), "particles").size(), c.cloud.size());
    EXPECT_EQ(listTimes(c.dir).size(), 1u) << "the merge is hidden from the time list";
    EXPECT_TRUE(fs::exists(view.path()));
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(c.dir), fs::directory_iterator()), 1 + nParts + 1)
      << "0.5, the processor folders and merged: the view's folder is gone";
  EXPECT_EQ(DecomposedTime(c.dir, "0.5", false).path(), c.dir / "0.5");
}

TEST(DecomposedCase, AViewOfLessThanTheWholeDecompositionIsRefused) {
  if (thisRank() != 0) GTEST_SKIP() << "files only: rank 0 does it";
  Case c;  // issue 54: processor1 of 3 gone, the utilities merged the other two and said nothing
  const int nParts = 3;
  std::vector<int> part(c.cloud.size());
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = static_cast<int>(i % nParts);
  decomposeTime(c.dir, "0.5", "particles", part, nParts);
  for (int p = 0; p < nParts; ++p) {
    writeDecompositionRecord(c.dir / processorName(p), nParts, static_cast<long>(c.cloud.size()));
  }
  fs::remove_all(c.dir / processorName(2));
  try {
    const DecomposedTime view(c.dir, "0.5", true);
    FAIL() << "two of three processor folders were merged";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("processor2 is missing"), std::string::npos) << e.what();
  }
  EXPECT_EQ(wholeDecomposition(c.dir, true).numberOfSubdomains, 2) << "-force: what is there";
  EXPECT_EQ(wholeDecomposition(c.dir, true).particles, 0) << "-force: no count held against the times";
}

// The solver's arrays by origId in uniform/ (StepState.hpp: wall friction states, slip
// directions), each processor's with its own particles' entries and others that are not (zero,
// or a stale copy): the merged time has each particle's entries from the processor holding it.
TEST(DecomposedCase, ReconstructTakesEachEntryOfTheSolverStateFromTheProcessorHoldingTheParticle) {
  if (thisRank() != 0) GTEST_SKIP() << "files only: rank 0 does it";
  Case c;
  const int nParts = 3;
  std::vector<int> part(c.cloud.size());
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = static_cast<int>((i * 5) % nParts);
  decomposeTime(c.dir, "0.5", "particles", part, nParts);
  auto stateOf = [](std::size_t id) { return static_cast<label>(1 + id % 2); };
  auto directionOf = [](std::size_t id) { return Vec3(0.1 * static_cast<double>(id), -1.0 / 3.0, 2.0); };
  const FieldWriteOptions options{WriteFormat::binary, 17, "uniform"};
  for (int p = 0; p < nParts - 1; ++p) {  // the last processor had no entries: no files
    // processor0's as long as the cloud with stale entries, processor1's as its largest origId needs
    std::size_t size = c.cloud.size();
    if (p == 1) {
      while (part[size - 1] != p) --size;
    }
    std::vector<label> states(size, p == 0 ? 2 : 0);
    std::vector<Vec3> directions(states.size(), Vec3(9, 9, 9));
    for (std::size_t id = 0; id < states.size(); ++id) {
      if (part[id] != p) continue;
      states[id] = stateOf(id);
      directions[id] = directionOf(id);
    }
    const fs::path uniform = c.dir / processorName(p) / "0.5" / "uniform";
    writeField(uniform / "frictionStates", states, options);
    writeField(uniform / "slipDirections", directions, options);
  }
  const fs::path merged = c.dir / "merged";
  fs::create_directories(merged);
  reconstructTime(c.dir, nParts, "0.5", merged);
  const auto states = readField<label>(merged / "uniform/frictionStates");
  const auto directions = readField<Vec3>(merged / "uniform/slipDirections");
  ASSERT_EQ(states.size(), c.cloud.size()) << "as long as the longest processor's";
  ASSERT_EQ(directions.size(), c.cloud.size());
  EXPECT_EQ(readFieldInfo(merged / "uniform/frictionStates").format, WriteFormat::binary);
  for (std::size_t id = 0; id < states.size(); ++id) {
    const bool written = part[id] < nParts - 1;
    EXPECT_EQ(states[id], written ? stateOf(id) : 0) << "origId " << id << " of processor" << part[id];
    EXPECT_EQ(directions[id], written ? directionOf(id) : Vec3(Vec3::Zero())) << "origId " << id;
  }
  EXPECT_TRUE(fs::exists(merged / "uniform/time")) << "the other files of uniform/ are processor0's";
}

TEST(DecomposedCase, AMissingProcessorTimeOrAGapIsAnError) {
  if (thisRank() != 0) GTEST_SKIP() << "files only: rank 0 does it";
  Case c;
  decomposeTime(c.dir, "0.5", "particles", std::vector<int>(c.cloud.size(), 0), 2);
  fs::remove_all(c.dir / "processor1" / "0.5");
  const fs::path merged = c.dir / "merged";
  EXPECT_THROW(reconstructTime(c.dir, 2, "0.5", merged), FatalError);
  EXPECT_THROW(DecomposedTime(c.dir, "0.5", true), FatalError);
  EXPECT_EQ(std::distance(fs::directory_iterator(c.dir), fs::directory_iterator()), 3)
      << "0.5 and the processor folders: the failed view's hidden folder is gone";
  fs::rename(c.dir / "processor1", c.dir / "processor2");
  EXPECT_THROW(nProcessorDirectories(c.dir), FatalError);
}

}  // namespace
