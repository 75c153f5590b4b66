#include "scenes/contact_patch_section.h"

#include <string>

#include "models/input_error.h"
#include "scenes/scene.h"
#include "scenes/switched_keys.h"

namespace railjoint {

ContactPatchSettings read_contact_patch_section(SectionReader& in, const KeyOrigins& origins) {
  ContactPatchSettings s;
  const std::string shape = in.choice("shape", "ellipse", {"ellipse", "polygon", "rectangle"});
  s.patch.shape = shape == "polygon" ? PatchShape::polygon : shape == "rectangle" ? PatchShape::rectangle : PatchShape::ellipse;
  s.size = in.choice("size", "given", {"given", "hertz"}) == "hertz" ? PatchSize::hertz : PatchSize::given;

  refuse_keys_unless(in, origins, s.patch.shape == PatchShape::polygon, {"vertices"}, "shape",
                     "only applies to shape = \"polygon\" (the thesis's n-gon; an ellipse and a rectangle have none)");
  const bool given = s.size == PatchSize::given;
  refuse_keys_unless(in, origins, given, {"length", "width"}, "size",
                     "only applies to size = \"given\" (size = \"hertz\" computes the patch from the radii)");
  // The steels are the whole program's (read_force_sections).
  for (const char* key : {"youngs_modulus", "poisson_ratio"}) {
    if (in.has(key)) {
      throw InputError(in.file(), in.qualified(key),
                       std::string("is now contact.") + key + " (one pair of steels for the whole program): move it to [contact]");
    }
  }
  refuse_keys_unless(in, origins, !given, {"crown_radius"}, "size",
                     "only applies to size = \"hertz\" (size = \"given\" takes contact_patch.length and width)");

  // Bounds far beyond any wheel-rail contact (patches of 1-2 cm^2, axle loads
  // of some 10^5 N) that keep the arithmetic finite and catch exponent typos.
  s.patch.length_m = in.number("length", s.patch.length_m, Range::open_closed(0.0, 1.0, "m"));
  s.patch.width_m = in.number("width", s.patch.width_m, Range::open_closed(0.0, 1.0, "m"));
  // The thesis refuses fewer than 4 vertices; 10^6 is far past where the n-gon's area stops changing (1e-11).
  s.patch.vertices = static_cast<int>(in.integer("vertices", s.patch.vertices, 4, 1000000));
  s.normal_force_N = in.number("normal_force", s.normal_force_N, Range::open_closed(0.0, 1e8, "N"));
  s.steps = static_cast<int>(in.integer("steps", s.steps, 3, 10000000));
  // A run's work budget, as a simulation's 1e6 steps: a polygon's every step
  // clips all its vertices (~0.15 us each measured, so 1e9 is some 3 minutes;
  // 1e6 vertices x 1e7 steps, both in range, would take weeks).
  if (s.patch.shape == PatchShape::polygon &&
      static_cast<double>(s.patch.vertices) * static_cast<double>(s.steps) > kMaxPolygonVertexSteps) {
    const bool steps_given = in.has("steps");
    const long long bound = static_cast<long long>(kMaxPolygonVertexSteps / (steps_given ? s.patch.vertices : s.steps));
    throw InputError(in.file(), in.qualified(steps_given ? "steps" : "vertices"),
                     "must be <= " + std::to_string(bound) + ": a polygon run may take at most 1e9 vertex-steps "
                     "(contact_patch.vertices x contact_patch.steps, some 3 minutes), here " +
                         std::to_string(s.patch.vertices) + " x " + std::to_string(s.steps));
  }
  s.hertz.crown_radius_m = in.number("crown_radius", s.hertz.crown_radius_m, Range::open_closed(0.0, 1000.0, "m"));
  in.finish();
  return s;
}

PressureInputs local_model_inputs_of(const Scene& scene) {
  try {
    return local_model_inputs(scene.contact_patch, scene.joint, scene.wheel);
  } catch (const InputError& error) {
    throw error.in_file(scene.file);
  }
}

}  // namespace railjoint
