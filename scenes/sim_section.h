#pragma once
// The [sim] section of a scene file: numerical and physical switches of the
// Bullet crossing scene (sim/sim_settings.h). Absent section: the defaults,
// which meet the accuracy target. Range-checked key by key here; the
// combinations (e.g. margin below the disc half width) are checked by
// sim/simulate_crossing.h when the run starts.

#include "scenes/section_reader.h"
#include "sim/sim_settings.h"

namespace railjoint {

SimSettings read_sim_section(SectionReader& in);

}  // namespace railjoint
