// `railjoint` itself links no MPI: under an MPI launcher it hands a sweep
// to railjoint-mpi beside it (cli/main.cpp). Without one (a build without
// MPI: RAILJOINT_WITH_MPI off, or no MPI found) the sweep is refused with
// what to do instead.

#include "scenes/sweeps/mpi_runner.h"
#include "support/input_error.h"

namespace railjoint {

bool mpi_built() { return false; }

MpiSweepResult run_sweep_mpi(const std::string&, const SweepRunOptions&) {
  throw InputError("", "mpirun",
                   "this railjoint was built without MPI (no railjoint-mpi beside it: install libopenmpi-dev and "
                   "rebuild); without MPI use "
                   "--jobs N on one machine, or --shard i/N in N separate processes");
}

}  // namespace railjoint
