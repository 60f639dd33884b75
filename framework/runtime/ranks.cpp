#include "runtime/ranks.h"

#include <spdlog/fmt/fmt.h>

#include <cstdio>
#include <cstdlib>

#include "core/error.h"
#include "plugins/mpi_ranks.h"
#include "runtime/plugin.h"

namespace maquette {
namespace {

class SingleProcess final : public Ranks {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::string> all_gather(const std::string& bytes) override { return {bytes}; }
  void post(const std::vector<int>& to, std::string) override {
    throw Error(fmt::format("cannot send to {} other rank(s): this process runs alone", to.size()));
  }
  std::optional<Message> poll() override { return std::nullopt; }
  size_t sending() override { return 0; }
  [[noreturn]] void abort(const std::string& message) override {
    std::fprintf(stderr, "%s\n", message.c_str());
    std::fflush(stderr);
    std::_Exit(EXIT_FAILURE);
  }
};

// Open MPI's mpirun, MPICH's and Intel's mpiexec (PMI), srun with PMI-2 or PMIx.
bool started_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

}  // namespace

std::unique_ptr<Ranks> single_process() { return std::make_unique<SingleProcess>(); }

std::unique_ptr<Ranks> launched_ranks() {
  if (!started_by_mpi_launcher()) return single_process();
#ifdef MAQUETTE_WITH_MPI
  return std::unique_ptr<Ranks>(
      plugin_function<decltype(maquette_mpi_ranks)>(kMpiPlugin, kMpiRanksEntry)());
#else
  // Each process would run the whole pipeline into the same store.
  throw Error("started by an MPI launcher, but this maquette was built without MPI");
#endif
}

std::vector<std::string> exchange(Ranks& ranks, const std::function<std::string()>& fn) {
  if (ranks.size() == 1) return {fn()};
  // A message is "+payload" or "!error".
  std::string message;
  try {
    message = "+" + fn();
  } catch (const std::exception& e) {
    message = std::string("!") + e.what();
  } catch (...) {
    message = "!unknown exception";
  }
  std::vector<std::string> all = ranks.all_gather(message);
  for (size_t r = 0; r < all.size(); ++r)
    if (all[r].front() == '!')
      throw Error(fmt::format("rank {} of {}: {}", r, all.size(), all[r].substr(1)));
  for (std::string& m : all) m.erase(0, 1);
  return all;
}

}  // namespace maquette
