#include "parallel/CommPlan.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <zoltan_comm.h>
#include <zoltan_types.h>

#include <limits>

#include "core/Error.hpp"

namespace isph {

namespace {
constexpr int planTag = 32001;
constexpr int exchangeTag = 32002;
}  // namespace

CommPlan::CommPlan(const std::vector<int>& destination) : nSent_(destination.size()) {
  if (destination.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    fatalError("CommPlan: more items than an int counts");
  }
  std::vector<int> assign(destination);  // Zoltan takes a non-const list
  int received = 0;
  const int status = Zoltan_Comm_Create(&plan_, static_cast<int>(assign.size()), assign.data(), MPI_COMM_WORLD,
                                        planTag, &received);
  if (status != ZOLTAN_OK && status != ZOLTAN_WARN) fatalError(fmt::format("Zoltan_Comm_Create failed ({})", status));
  nReceived_ = static_cast<std::size_t>(received);
}

CommPlan::~CommPlan() {
  if (plan_) Zoltan_Comm_Destroy(&plan_);
}

void CommPlan::exchange(const std::byte* send, std::size_t itemBytes, std::byte* recv) const {
  if (itemBytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) fatalError("CommPlan: item too large");
  // Zoltan reads the send buffer only (its API takes it non-const), and wants buffers even
  // when there is nothing to send or receive.
  static std::byte none[8];
  char* from = reinterpret_cast<char*>(const_cast<std::byte*>(send ? send : none));
  char* to = reinterpret_cast<char*>(recv ? recv : none);
  const int status = Zoltan_Comm_Do(plan_, exchangeTag, from, static_cast<int>(itemBytes), to);
  if (status != ZOLTAN_OK && status != ZOLTAN_WARN) fatalError(fmt::format("Zoltan_Comm_Do failed ({})", status));
}

}  // namespace isph
