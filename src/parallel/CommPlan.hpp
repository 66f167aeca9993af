#pragma once
// An exchange of items between ranks through Zoltan's communication package
// (Zoltan_Comm_Create / Zoltan_Comm_Do, the engine of Zoltan_Migrate): item k of this rank's
// send list goes to rank destination[k] (this rank included). Received items come ordered by
// source rank, each source's in its send order, so every exchange over one plan fills the
// same slots, and runs repeat exactly. One plan serves items of any size (a particle's
// fields, one field's values). Creating a plan and exchanging are collective calls.
#include <cstddef>
#include <vector>

struct Zoltan_Comm_Obj;

namespace isph {

class CommPlan {
 public:
  explicit CommPlan(const std::vector<int>& destination);
  ~CommPlan();
  CommPlan(const CommPlan&) = delete;
  CommPlan& operator=(const CommPlan&) = delete;

  std::size_t nSent() const { return nSent_; }
  std::size_t nReceived() const { return nReceived_; }

  // send: nSent() items of itemBytes each, in send-list order; recv: room for nReceived().
  void exchange(const std::byte* send, std::size_t itemBytes, std::byte* recv) const;

  template <class T>
  std::vector<T> exchange(const std::vector<T>& send) const {
    std::vector<T> recv(nReceived_);
    exchange(reinterpret_cast<const std::byte*>(send.data()), sizeof(T), reinterpret_cast<std::byte*>(recv.data()));
    return recv;
  }

 private:
  Zoltan_Comm_Obj* plan_ = nullptr;
  std::size_t nSent_ = 0;
  std::size_t nReceived_ = 0;
};

}  // namespace isph
