// A build without MPI (RAILJOINT_WITH_MPI off, or no MPI found): a sweep
// started by an MPI launcher is refused with what to do instead.

#include "models/input_error.h"
#include "scenes/sweeps/mpi_runner.h"

namespace railjoint {

bool mpi_built() { return false; }

MpiSweepResult run_sweep_mpi(const std::string&, const SweepRunOptions&) {
  throw InputError("", "mpirun",
                   "this railjoint was built without MPI (install libopenmpi-dev and rebuild); without MPI use "
                   "--jobs N on one machine, or --shard i/N in N separate processes");
}

}  // namespace railjoint
