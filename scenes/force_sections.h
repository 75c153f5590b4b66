#pragma once
// The [contact], [track] and [vehicle] sections: the force model of an
// inertial run (sim/elastic_track_settings.h). [contact] law = "linear" is
// the linear contact spring (SimSettings::contact_stiffness_N_per_m, which
// used to be sim.contact_stiffness); "hertz" makes the run a force run,
// which [track] and [vehicle] extend.

#include "models/hertz_contact.h"
#include "scenes/section_reader.h"
#include "sim/setting_checks.h"
#include "sim/sim_settings.h"

namespace railjoint {

/// Reads the three sections into `sim` (read_sim_section first: the mode and
/// the [sim] keys a force run refuses are checked here). Throws InputError
/// naming the file and the key (of two that conflict, the one the user
/// typed last: `origins`). Returns the steels (contact.youngs_modulus,
/// contact.poisson_ratio), which the local model's Hertz patch takes too.
HertzMaterial read_force_sections(SectionReader& contact, SectionReader& track, SectionReader& vehicle,
                                  SectionReader& sim_in, SimSettings& sim, const KeyOrigins& origins);

}  // namespace railjoint
