// The processes running one pipeline: this process alone, or the ranks of an MPI job launched by
// mpirun or srun. The runner only needs one collective, all_gather; only the thread that created
// the Ranks may call it (MPI_THREAD_FUNNELED: TBB worker threads compute, never communicate).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace maquette {

class Ranks {
 public:
  virtual ~Ranks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool root() const { return rank() == 0; }
  // Every rank's `bytes`, in rank order, on every rank. Also a barrier.
  virtual std::vector<std::string> all_gather(const std::string& bytes) = 0;

  // Point to point, for the writer rank of `maquette run --store-copies` (write_relay.h).
  // Messages from one rank to another arrive in the order posted, whatever their size (the MPI
  // plug-in sends them in pieces: message_pieces.h).
  struct Message {
    int from = 0;
    std::string bytes;
  };
  // Starts sending `bytes` to every rank of `to` (one buffer for all) and returns at once;
  // sending() moves it along.
  virtual void post(const std::vector<int>& to, std::string bytes) = 0;
  // A message received from any rank, if one has arrived.
  virtual std::optional<Message> poll() = 0;
  // Moves the posted messages along; how many are not yet sent to every rank they go to.
  virtual size_t sending() = 0;
  // Writes `message` to this rank's stderr and ends every rank of the job, non-zero. For a
  // failure the other ranks cannot hear of: they wait for messages this rank will never send,
  // so they would never reach a collective that reports it.
  [[noreturn]] virtual void abort(const std::string& message) = 0;
};

// This process alone.
std::unique_ptr<Ranks> single_process();

// The ranks of the MPI job when this process was started by an MPI launcher (mpirun, mpiexec,
// srun: it sets OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK), with MPI initialized until the
// Ranks is destroyed; otherwise this process alone. MPI lives in a plug-in
// (plugins/mpi_ranks.h) opened only then: a plain `maquette run` never loads nor initializes
// MPI. Throws maquette::Error, naming the file looked for, when the plug-in cannot be loaded, and
// when started by a launcher in a build without MPI.
std::unique_ptr<Ranks> launched_ranks();

// Runs `fn` on every rank, then gives every rank the payloads all ranks' `fn` returned, in rank
// order. When `fn` throws on some rank, every rank throws maquette::Error with the message of the
// lowest such rank, "rank R of N: what". With a single rank, exceptions pass through unchanged.
std::vector<std::string> exchange(Ranks& ranks, const std::function<std::string()>& fn);

}  // namespace maquette
