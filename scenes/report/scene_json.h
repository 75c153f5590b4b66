#pragma once
// The "scene" block of every JSON report (analytic, simulate, pressure): the
// file and name, and every key the scene reader read with the value the run
// used, defaults included, in the file's units (theta_deg in degrees), so an
// output carries its inputs. Keys derived from others (joint.length when the
// file gives none) are listed under "derived".

#include <nlohmann/json.hpp>

#include "scenes/scene.h"

namespace railjoint {

nlohmann::json scene_json(const Scene& scene);

}  // namespace railjoint
