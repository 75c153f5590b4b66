#pragma once
// A sweep spread over MPI ranks (`mpirun -np N railjoint sweep ...`): rank 0
// reads the sweep file and base scene and sends their text to the others (no
// shared file system needed for the inputs), hands out chunks of cases as
// ranks ask for them (dynamic: a rank that draws dear cases asks less
// often), runs cases itself on its spare threads, and alone writes
// results.csv, in case order, exactly as a threaded run does. No MPI in
// this header: a build without MPI links mpi_runner_unavailable.cpp.

#include <string>

#include "scenes/sweeps/sweep_runner.h"

namespace railjoint {

/// This build has MPI (CMake found it and RAILJOINT_WITH_MPI is on).
bool mpi_built();

/// An MPI launcher (mpirun, mpiexec, srun) started this process: its
/// environment names a rank (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
bool started_by_mpi_launcher();

struct MpiSweepResult {
  bool is_writer = false;  ///< rank 0: summary is the sweep's
  SweepSummary summary;
};

/// Every rank calls it with the same arguments. Rank 0 throws InputError for
/// a bad sweep file, base scene or folder (the others then return quietly).
MpiSweepResult run_sweep_mpi(const std::string& sweep_path, const SweepRunOptions& options);

}  // namespace railjoint
