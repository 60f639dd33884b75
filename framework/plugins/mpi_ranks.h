// The MPI plug-in, libmaquette_mpi.so, built when MPI is found: launched_ranks() (runtime/ranks.h)
// opens it only when an MPI launcher started the process, so only then is MPI loaded.
#pragma once

#include "runtime/ranks.h"

namespace maquette {

inline constexpr const char* kMpiPlugin = "libmaquette_mpi.so";
inline constexpr const char* kMpiRanksEntry = "maquette_mpi_ranks";

}  // namespace maquette

// The ranks of MPI_COMM_WORLD, MPI initialized until the object is deleted. Throws
// maquette::Error when the MPI library lacks MPI_THREAD_FUNNELED.
extern "C" maquette::Ranks* maquette_mpi_ranks();
