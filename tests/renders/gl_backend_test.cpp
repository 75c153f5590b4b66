// The two GL back ends (renders/gl_backend.h): the same frame through OSMesa
// and through EGL in one process, pixel by pixel, and RAILJOINT_GL's parsing.
// Both are Mesa's llvmpipe here, running the same GL code into the
// renderer's own framebuffers, so they agree to the byte (measured: 0
// differing pixels in every view). A GPU behind EGL would round differently:
// the bound below then allows a 2/255 difference on 0.1 % of the pixels.

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "models/impact_prediction.h"
#include "renders/crossing_renderer.h"
#include "renders/gl_backend.h"
#include "renders/wheel_tessellation.h"

namespace railjoint {
namespace {

// The scenario-2 impact state of the default joint, with its contact and impact recorded.
Trajectory impact_trajectory() {
  const JointParams joint;
  WheelParams wheel;
  wheel.width_m = 0.001;
  const ImpactPrediction impact = predict_impact(joint, wheel);
  Trajectory t;
  for (int i = 0; i <= 4; ++i) {
    WheelSample s;
    s.time_s = i * 1e-4;
    s.centre_m = {impact.impact_wheel_x_m + 0.005 * (i - 2), wheel.lateral_m, impact.impact_wheel_z_m};
    ContactSample c;
    c.point_on_rail_m = impact.contact_A_m;
    s.contacts.push_back(c);
    t.samples.push_back(s);
  }
  t.impacts.push_back({2e-4, impact.impact_wheel_x_m, impact.impulse.exact_Ns, impact.contact_A_m});
  return t;
}

struct Difference {
  long long pixels = 0;  ///< pixels with any channel different
  int largest = 0;       ///< largest channel difference
};

Difference compare(const RgbImage& a, const RgbImage& b) {
  Difference d;
  for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    int worst = 0;
    for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int{a.rgb[i + k]} - int{b.rgb[i + k]}));
    d.pixels += worst > 0 ? 1 : 0;
    d.largest = std::max(d.largest, worst);
  }
  return d;
}

class BothBackEnds : public testing::TestWithParam<RenderView> {};

TEST_P(BothBackEnds, DrawTheSameFrame) {
  if (!gl_backend_built(GlBackend::osmesa) || !gl_backend_built(GlBackend::egl)) {
    GTEST_SKIP() << "this build has only one GL back end";
  }
  RenderSettings s;
  s.view = GetParam();
  s.fps = 10000;
  s.ffmpeg = false;
  WheelParams wheel;
  wheel.width_m = 0.001;
  const RailJointMesh rails = build_rail_joint_mesh(JointParams{});
  const TriangleMesh wheel_mesh = build_wheel_mesh(wheel, wheel_render_segments(s, wheel.radius_m), 0.0);
  const Trajectory t = impact_trajectory();
  CrossingRenderer osmesa(s, rails, wheel_mesh, t, GlBackend::osmesa);
  CrossingRenderer egl(s, rails, wheel_mesh, t, GlBackend::egl);
  RgbImage a, b;
  osmesa.render_at(2e-4, a);  // the impact frame: border, ring, labels
  egl.render_at(2e-4, b);
  osmesa.render_at(2e-4, a);  // again after the other context drew: contexts must not leak into each other
  std::cout << to_string(s.view) << " view: osmesa " << osmesa.gl_version() << " (" << osmesa.gl_renderer()
            << "), egl " << egl.gl_version() << " (" << egl.gl_renderer() << ")\n";
  EXPECT_EQ(osmesa.gl_backend(), GlBackend::osmesa);
  EXPECT_EQ(egl.gl_backend(), GlBackend::egl);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  const Difference d = compare(a, b);
  std::cout << "  " << d.pixels << " of " << a.rgb.size() / 3 << " pixels differ, by at most " << d.largest
            << "/255\n";
  if (osmesa.gl_renderer() == egl.gl_renderer()) {
    EXPECT_EQ(d.pixels, 0) << "the same rasteriser must draw the same bytes";
  } else {
    EXPECT_LE(d.largest, 2);
    EXPECT_LT(static_cast<double>(d.pixels), 1e-3 * static_cast<double>(a.rgb.size() / 3));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryView, BothBackEnds,
                         testing::Values(RenderView::side, RenderView::top, RenderView::perspective),
                         [](const testing::TestParamInfo<RenderView>& view) { return std::string(to_string(view.param)); });

TEST(GlBackend, EnvironmentSelectsTheBackEnd) {
  const char* saved = std::getenv("RAILJOINT_GL");
  const std::string restore = saved != nullptr ? saved : "";
  unsetenv("RAILJOINT_GL");
  // Unset: OSMesa when built (the default the user asked for), else EGL.
  EXPECT_EQ(gl_backend_from_environment(), gl_backend_built(GlBackend::osmesa) ? GlBackend::osmesa : GlBackend::egl);
  for (const GlBackend backend : {GlBackend::osmesa, GlBackend::egl}) {
    setenv("RAILJOINT_GL", to_string(backend), 1);
    if (gl_backend_built(backend)) {
      EXPECT_EQ(gl_backend_from_environment(), backend);
    } else {
      EXPECT_THROW(gl_backend_from_environment(), std::runtime_error);
    }
  }
  setenv("RAILJOINT_GL", "vulkan", 1);
  try {
    gl_backend_from_environment();
    ADD_FAILURE() << "RAILJOINT_GL=vulkan accepted";
  } catch (const std::invalid_argument& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("\"osmesa\" or \"egl\""), std::string::npos);
  }
  if (saved != nullptr) {
    setenv("RAILJOINT_GL", restore.c_str(), 1);
  } else {
    unsetenv("RAILJOINT_GL");
  }
}

}  // namespace
}  // namespace railjoint
