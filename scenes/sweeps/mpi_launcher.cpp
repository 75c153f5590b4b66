// Whether an MPI launcher started this process: in every build, so a build
// without MPI can say so instead of running N copies of the whole sweep.

#include <cstdlib>

#include "scenes/sweeps/mpi_runner.h"

namespace railjoint {

bool started_by_mpi_launcher() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

}  // namespace railjoint
