#pragma once
// The force run on every case (`railjoint simulate` of a scene with
// contact.law = "hertz", sim/elastic_crossing_run.h): P1 and P2 and their
// times, the static load, Jenkins's P1 and P2 for the case's own track, the
// flights, and the rail-seat and ballast forces where the track records them.
// A case whose scene is no force run is refused by key.

#include "scenes/sweeps/case_model.h"

namespace railjoint {

CaseModel forces_case_model();

}  // namespace railjoint
