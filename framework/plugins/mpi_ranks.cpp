// MpiRanks: MPI_COMM_WORLD as the Ranks of a run, in the MPI plug-in.
#include "plugins/mpi_ranks.h"

#include <mpi.h>
#include <spdlog/fmt/fmt.h>

#include <chrono>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <list>
#include <numeric>
#include <thread>

#include "core/error.h"
#include "runtime/message_pieces.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace maquette {
namespace {

// OpenMPI keeps what its initialization allocates until the process ends: not leaks of ours.
// MPI_Finalize then unloads the components that made it, so LeakSanitizer could neither tell
// their memory from ours nor name them at the end of the process; the leak check runs before it
// instead (what is still in use is reachable then, as at the end), and no check follows it.
#if defined(__SANITIZE_ADDRESS__)
using NotOurLeaks = __lsan::ScopedDisabler;
void check_leaks_now() { __lsan_do_leak_check(); }
#else
struct NotOurLeaks {};
void check_leaks_now() {}
#endif

void init_mpi(int& provided) {
  [[maybe_unused]] const NotOurLeaks scope;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
}

void finalize_mpi() {
  check_leaks_now();
  MPI_Finalize();
}

// MPI_COMM_WORLD, initialized for the lifetime of the object. MPI calls keep the default error
// handler, MPI_ERRORS_ARE_FATAL: a failed collective ends the whole job.
class MpiRanks final : public Ranks {
 public:
  MpiRanks() {
    int provided = 0;
    init_mpi(provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (provided < MPI_THREAD_FUNNELED) {
      finalize_mpi();
      throw Error("the MPI library does not provide MPI_THREAD_FUNNELED");
    }
    // A message's sender and receiver must cut it into the same pieces: a rank given another
    // size (mpirun passes a variable to other nodes only with -x) is refused here, by every
    // rank alike, not by MPI's truncation error in the middle of a run.
    const std::vector<std::string> limits = all_gather(std::to_string(piece_limit_));
    for (size_t r = 1; r < limits.size(); ++r)
      if (limits[r] != limits[0]) {
        finalize_mpi();
        throw Error(
            fmt::format("{} differs between the ranks: {} on rank 0, {} on rank {}: give "
                        "every rank the same (mpirun -x {})",
                        kPieceLimitVariable, limits[0], limits[r], r, kPieceLimitVariable));
      }
  }
  ~MpiRanks() override { finalize_mpi(); }
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::string> all_gather(const std::string& bytes) override {
    // MPI_Allgatherv's counts and offsets are int: the lengths are gathered as 64-bit numbers,
    // so that every rank refuses the same too large total.
    const int64_t length = int64_t(bytes.size());
    const size_t n = size_t(size_);
    std::vector<int64_t> lengths(n);
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Iallgather(&length, 1, MPI_INT64_T, lengths.data(), 1, MPI_INT64_T, MPI_COMM_WORLD,
                   &request);
    wait(request);
    const int64_t total = std::reduce(lengths.begin(), lengths.end());
    if (total > INT_MAX)
      throw Error(
          fmt::format("the ranks' results to exchange add up to {} bytes, more than MPI's "
                      "limit of {} bytes for one collective",
                      total, INT_MAX));
    std::vector<int> counts(lengths.begin(), lengths.end()), offsets(n);
    std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
    std::string all(size_t(total), '\0');
    MPI_Iallgatherv(bytes.data(), int(length), MPI_CHAR, all.data(), counts.data(), offsets.data(),
                    MPI_CHAR, MPI_COMM_WORLD, &request);
    wait(request);
    std::vector<std::string> parts;
    for (size_t r = 0; r < n; ++r)
      parts.push_back(all.substr(size_t(offsets[r]), size_t(counts[r])));
    return parts;
  }

  // A message: its size (64 bits), then its bytes in pieces (message_pieces.h), all with the
  // same tag, so that they arrive in order.
  void post(const std::vector<int>& to, std::string bytes) override {
    Posted& p = posted_.emplace_back(Posted{std::move(bytes), 0, {}});
    p.size = uint64_t(p.bytes.size());
    const std::vector<MessagePiece> pieces = message_pieces(p.bytes.size(), piece_limit_);
    for (const int rank : to) {
      send(&p.size, 1, MPI_UINT64_T, rank, p.requests);
      for (const MessagePiece& piece : pieces)
        send(p.bytes.data() + piece.offset, piece.bytes, MPI_CHAR, rank, p.requests);
    }
  }

  std::optional<Message> poll() override {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kMessageTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    const int from = status.MPI_SOURCE;
    uint64_t size = 0;
    MPI_Recv(&size, 1, MPI_UINT64_T, from, kMessageTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    // The sender posted every piece with the size: they follow it.
    Message m{from, std::string(size_t(size), '\0')};
    for (const MessagePiece& piece : message_pieces(m.bytes.size(), piece_limit_))
      MPI_Recv(m.bytes.data() + piece.offset, piece.bytes, MPI_CHAR, from, kMessageTag,
               MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return m;
  }

  size_t sending() override {
    std::erase_if(posted_, [](Posted& p) {
      int done = 0;
      MPI_Testall(int(p.requests.size()), p.requests.data(), &done, MPI_STATUSES_IGNORE);
      return done != 0;
    });
    return posted_.size();
  }

  [[noreturn]] void abort(const std::string& message) override {
    std::fprintf(stderr, "%s\n", message.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, EXIT_FAILURE);
    std::_Exit(EXIT_FAILURE);  // MPI_Abort does not return; the compiler cannot know
  }

 private:
  // Blocking MPI calls busy-poll: a rank done with its part would keep a core from the threads of
  // the ranks still computing when they share cores. Polling every millisecond costs nothing
  // next to a step.
  static void wait(MPI_Request& request) {
    for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }

  // A message being sent: its size and bytes must live until its requests complete.
  struct Posted {
    std::string bytes;
    uint64_t size;
    std::vector<MPI_Request> requests;
  };
  static constexpr int kMessageTag = 1;

  static void send(const void* data, int count, MPI_Datatype type, int to,
                   std::vector<MPI_Request>& requests) {
    MPI_Isend(data, count, type, to, kMessageTag, MPI_COMM_WORLD, &requests.emplace_back());
  }

  int rank_ = 0, size_ = 1;
  // The sender's and the receiver's must be the same: checked when the ranks start.
  size_t piece_limit_ = piece_limit(std::getenv(kPieceLimitVariable));
  std::list<Posted> posted_;  // a list: requests keep their address while others complete
};

}  // namespace
}  // namespace maquette

extern "C" maquette::Ranks* maquette_mpi_ranks() { return new maquette::MpiRanks(); }
