#include "scenes/contact_patch_section.h"

#include <string>

#include "scenes/scene.h"
#include "scenes/switched_keys.h"
#include "support/input_error.h"

namespace railjoint {

ContactPatchSettings read_contact_patch_section(SectionReader& in, const KeyOrigins& origins) {
  ContactPatchSettings s;
  const std::string shape = in.choice("shape", "ellipse", {"ellipse", "polygon", "rectangle", "solved"});
  s.patch.shape = shape == "polygon" ? PatchShape::polygon : shape == "rectangle" ? PatchShape::rectangle : PatchShape::ellipse;
  s.solved = shape == "solved";
  refuse_keys_unless(in, origins, !s.solved, {"size", "length", "width"}, "shape",
                     "does not apply to shape = \"solved\" (the solver finds the patch from the surfaces)");
  refuse_keys_unless(in, origins, s.solved,
                     {"yield_pressure", "height_mismatch", "cells_x", "cells_y", "window_over_axes",
                      "edge_average_length"},
                     "shape",
                     "only applies to shape = \"solved\" (the boundary-element contact)");
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
  refuse_keys_unless(in, origins, !given && !s.solved, {"crown_radius"}, "size",
                     "only applies to size = \"hertz\" (size = \"given\" takes contact_patch.length and width; "
                     "shape = \"solved\" the head of [joint])");

  // Bounds far beyond any wheel-rail contact (patches of 1-2 cm^2, axle loads
  // of some 10^5 N) that keep the arithmetic finite and catch exponent typos.
  s.patch.length_m = in.number("length", s.patch.length_m, Range::open_closed(0.0, 1.0, "m"));
  s.patch.width_m = in.number("width", s.patch.width_m, Range::open_closed(0.0, 1.0, "m"));
  // The thesis refuses fewer than 4 vertices; 10^6 is far past where the n-gon's area stops changing (1e-11).
  s.patch.vertices = static_cast<int>(in.integer("vertices", s.patch.vertices, 4, 1000000));
  s.load_from_force_run = !in.number_or_word("normal_force", s.normal_force_N, Range::open_closed(0.0, 1e8, "N"),
                                              {"forces"}, s.normal_force_N)
                               .empty();
  if (s.load_from_force_run && !s.solved) {
    throw InputError(in.file(), in.qualified("normal_force"),
                     "= \"forces\" only applies to shape = \"solved\" (a prescribed patch takes a number [N] in "
                     "(0, 1e8])");
  }
  // A solved step is a boundary-element solve (some 0.1 s on 128 x 96 cells): fewer steps by default.
  s.steps = static_cast<int>(in.integer("steps", s.solved ? 100 : s.steps, 3, s.solved ? 100000 : 10000000));
  // A run's work budget, as a simulation's 1e6 steps: a polygon's every step
  // clips all its vertices.
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
  // The elastic-perfectly-plastic cap [Pa]; absent: elastic. Below 100 MPa
  // is no rail steel (a typo); R260's shakedown limit is some 1.15 GPa
  // (docs/rail-end-contact.md, "The contact at the rail end, solved").
  if (in.has("yield_pressure")) {
    s.solved_contact.yield_pressure_Pa = in.number("yield_pressure", 1.15e9, Range::closed(1e8, 1e11, "Pa"));
  }
  s.solved_contact.height_mismatch_m =
      in.number("height_mismatch", 0.0, Range::closed(-0.005, 0.005, "m"));
  // The edge pressure's length (models/rail_end_edge_load.h): the elastic
  // edge's measure; under a cap the pressure is bounded and has its own.
  refuse_keys_unless(in, origins, !s.solved_contact.yield_pressure_Pa, {"edge_average_length"}, "yield_pressure",
                     "only applies to an elastic solve (the edge pressure stands in for an elastic edge's singular "
                     "peak; under a cap the peak is the cap)");
  // Read (and so listed in the scene's JSON) only where it applies.
  if (s.solved && !s.solved_contact.yield_pressure_Pa) {
    s.solved_contact.edge_average_length_m = in.number("edge_average_length", s.solved_contact.edge_average_length_m,
                                                        Range::closed(1e-5, 5e-3, "m"));
  }
  s.solved_contact.cells_x = static_cast<int>(in.integer("cells_x", s.solved_contact.cells_x, 16, 1024));
  s.solved_contact.cells_y = static_cast<int>(in.integer("cells_y", s.solved_contact.cells_y, 16, 1024));
  // The grid's sides over Hertz's full axes at the static load: below 1.5 a
  // patch's elastic fringe meets the border. Read (and so listed in the
  // scene's JSON) only where it applies.
  s.grow_window = !in.has("window_over_axes");
  if (s.solved) {
    s.solved_contact.window_over_axes =
        in.number("window_over_axes", s.solved_contact.window_over_axes, Range::closed(1.5, kMaxWindowOverAxes, ""));
  }
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
