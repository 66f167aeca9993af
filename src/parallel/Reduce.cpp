#include "parallel/Reduce.hpp"

#include <mpi.h>

namespace isph {

namespace {

bool mpiActive() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

template <class T>
T reduce(T value, MPI_Datatype type, MPI_Op op) {
  if (!distributedRun()) return value;
  T out{};
  MPI_Allreduce(&value, &out, 1, type, op, MPI_COMM_WORLD);
  return out;
}

Vec3 reduce(const Vec3& value, MPI_Op op) {
  if (!distributedRun()) return value;
  Vec3 out;
  MPI_Allreduce(value.data(), out.data(), 3, MPI_DOUBLE, op, MPI_COMM_WORLD);
  return out;
}

template <class T>
std::vector<T> gather(T value, MPI_Datatype type) {
  if (!distributedRun()) return {value};
  std::vector<T> out(static_cast<std::size_t>(nRanks()));
  MPI_Allgather(&value, 1, type, out.data(), 1, type, MPI_COMM_WORLD);
  return out;
}

}  // namespace

int nRanks() {
  if (!mpiActive()) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

int thisRank() {
  if (!mpiActive()) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

bool distributedRun() { return nRanks() > 1; }

double sumOverRanks(double value) { return reduce(value, MPI_DOUBLE, MPI_SUM); }
long sumOverRanks(long value) { return reduce(value, MPI_LONG, MPI_SUM); }
std::size_t sumOverRanks(std::size_t value) { return reduce(value, MPI_UNSIGNED_LONG, MPI_SUM); }
Vec3 sumOverRanks(const Vec3& value) { return reduce(value, MPI_SUM); }

void sumOverRanks(std::span<double> values) {
  if (distributedRun() && !values.empty()) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  }
}

void sumOverRanks(std::span<long> values) {
  if (distributedRun() && !values.empty()) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  }
}

double maxOverRanks(double value) { return reduce(value, MPI_DOUBLE, MPI_MAX); }
long maxOverRanks(long value) { return reduce(value, MPI_LONG, MPI_MAX); }
std::size_t maxOverRanks(std::size_t value) { return reduce(value, MPI_UNSIGNED_LONG, MPI_MAX); }
double minOverRanks(double value) { return reduce(value, MPI_DOUBLE, MPI_MIN); }
Vec3 maxOverRanks(const Vec3& value) { return reduce(value, MPI_MAX); }
Vec3 minOverRanks(const Vec3& value) { return reduce(value, MPI_MIN); }

bool anyRank(bool value) { return reduce(static_cast<int>(value), MPI_INT, MPI_LOR) != 0; }
bool allRanks(bool value) { return reduce(static_cast<int>(value), MPI_INT, MPI_LAND) != 0; }

std::vector<double> gatherOverRanks(double value) { return gather(value, MPI_DOUBLE); }
std::vector<long> gatherOverRanks(long value) { return gather(value, MPI_LONG); }

std::vector<double> gatherOverRanks(std::span<const double> values) {
  if (!distributedRun()) return {values.begin(), values.end()};
  const std::vector<long> sizes = gatherOverRanks(static_cast<long>(values.size()));
  std::vector<int> counts(sizes.size()), offsets(sizes.size());
  int total = 0;
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    counts[r] = static_cast<int>(sizes[r]);
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<double> out(static_cast<std::size_t>(total));
  MPI_Allgatherv(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, out.data(), counts.data(),
                 offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  return out;
}

long sumOverLowerRanks(long value) {
  if (!distributedRun()) return 0;
  long out = 0;
  MPI_Exscan(&value, &out, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  return thisRank() == 0 ? 0 : out;
}

}  // namespace isph
