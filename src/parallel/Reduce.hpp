#pragma once
// The global decisions of a parallel run (time step, counts, forces, samples): sums,
// extremes and gathers over the ranks of MPI_COMM_WORLD. Each is a collective call, made by
// every rank in the same order; without MPI, or on one rank, each returns its argument.
#include <cstddef>
#include <span>
#include <vector>

#include "core/Types.hpp"

namespace isph {

// MPI is active and MPI_COMM_WORLD has more than one rank.
bool distributedRun();
int thisRank();   // 0 without MPI
int nRanks();     // 1 without MPI

double sumOverRanks(double value);
long sumOverRanks(long value);
std::size_t sumOverRanks(std::size_t value);
Vec3 sumOverRanks(const Vec3& value);
void sumOverRanks(std::span<double> values);  // element by element, in place
void sumOverRanks(std::span<long> values);

double maxOverRanks(double value);
long maxOverRanks(long value);
std::size_t maxOverRanks(std::size_t value);
double minOverRanks(double value);
Vec3 maxOverRanks(const Vec3& value);  // component by component
Vec3 minOverRanks(const Vec3& value);

bool anyRank(bool value);
bool allRanks(bool value);

// Every rank's value, by rank.
std::vector<double> gatherOverRanks(double value);
std::vector<long> gatherOverRanks(long value);
// Every rank's values, one after the other by rank (the ranks may give different counts).
std::vector<double> gatherOverRanks(std::span<const double> values);

// The sum of `value` over the ranks below this one (MPI_Exscan; 0 on rank 0).
long sumOverLowerRanks(long value);

}  // namespace isph
