// MpiRanks: MPI_COMM_WORLD as the Ranks of a run, in the MPI plug-in.
#include "plugins/mpi_ranks.h"

#include <mpi.h>

#include <chrono>
#include <list>
#include <numeric>
#include <thread>

#include "core/error.h"

namespace maquette {
namespace {

// MPI_COMM_WORLD, initialized for the lifetime of the object. MPI calls keep the default error
// handler, MPI_ERRORS_ARE_FATAL: a failed collective ends the whole job.
class MpiRanks final : public Ranks {
 public:
  MpiRanks() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (provided < MPI_THREAD_FUNNELED) {
      MPI_Finalize();
      throw Error("the MPI library does not provide MPI_THREAD_FUNNELED");
    }
  }
  ~MpiRanks() override { MPI_Finalize(); }
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::string> all_gather(const std::string& bytes) override {
    const int length = int(bytes.size());
    const size_t n = size_t(size_);
    std::vector<int> lengths(n), offsets(n);
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Iallgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD, &request);
    wait(request);
    std::exclusive_scan(lengths.begin(), lengths.end(), offsets.begin(), 0);
    std::string all(size_t(offsets.back() + lengths.back()), '\0');
    MPI_Iallgatherv(bytes.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                    MPI_CHAR, MPI_COMM_WORLD, &request);
    wait(request);
    std::vector<std::string> parts;
    for (size_t r = 0; r < n; ++r)
      parts.push_back(all.substr(size_t(offsets[r]), size_t(lengths[r])));
    return parts;
  }

  void post(int to, std::string bytes) override {
    Posted& p = posted_.emplace_back(Posted{std::move(bytes), MPI_REQUEST_NULL});
    MPI_Isend(p.bytes.data(), int(p.bytes.size()), MPI_CHAR, to, kMessageTag, MPI_COMM_WORLD,
              &p.request);
  }

  std::optional<Message> poll() override {
    std::erase_if(posted_, [](Posted& p) {
      int done = 0;
      MPI_Test(&p.request, &done, MPI_STATUS_IGNORE);
      return done != 0;
    });
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kMessageTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    Message m{status.MPI_SOURCE, std::string(size_t(length), '\0')};
    MPI_Recv(m.bytes.data(), length, MPI_CHAR, status.MPI_SOURCE, kMessageTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return m;
  }

  bool posting() const override { return !posted_.empty(); }

 private:
  // Blocking MPI calls busy-poll: a rank done with its part would keep a core from the threads of
  // the ranks still computing when they share cores. Polling every millisecond costs nothing
  // next to a step.
  static void wait(MPI_Request& request) {
    for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }

  // A message being sent: its bytes must live until the request completes.
  struct Posted {
    std::string bytes;
    MPI_Request request;
  };
  static constexpr int kMessageTag = 1;

  int rank_ = 0, size_ = 1;
  std::list<Posted> posted_;  // a list: requests keep their address while others complete
};

}  // namespace
}  // namespace maquette

extern "C" maquette::Ranks* maquette_mpi_ranks() { return new maquette::MpiRanks(); }
