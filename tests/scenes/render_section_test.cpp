// The [render] section of a scene file: keys, defaults and the errors a user sees.

#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "render.toml");
  } catch (const InputError& error) {
    std::cout << "  " << error.what() << "\n";
    return error.key();
  }
  return "no error";
}

TEST(RenderSection, AbsentSectionMeansNoRendering) {
  const Scene scene = parse_scene("[wheel]\nspeed = 30\n", "plain.toml");
  EXPECT_FALSE(scene.render.has_value());
}

TEST(RenderSection, EmptySectionTakesTheDefaults) {
  const Scene scene = parse_scene("[render]\n", "r.toml");
  ASSERT_TRUE(scene.render.has_value());
  const RenderSettings defaults;
  EXPECT_EQ(scene.render->width_px, defaults.width_px);
  EXPECT_EQ(scene.render->fps, defaults.fps);
  EXPECT_FALSE(scene.render->t_start_s.has_value());
  EXPECT_FALSE(scene.render->t_end_s.has_value());
  EXPECT_EQ(scene.render->view, RenderView::side);
}

TEST(RenderSection, EveryKeyIsRead) {
  const Scene scene = parse_scene(
      "[render]\nwidth = 800\nheight = 600\nfps = 5000\nt_start = 0.001\nt_end = 0.004\nexaggeration = 50\n"
      "reference_z = 0.001\nview = \"top\"\nfollow = false\nview_width = 0.3\nffmpeg = false\nvideo_fps = 30\n"
      "antialias = \"msaa\"\ngltf = false\n",
      "r.toml");
  const RenderSettings& r = *scene.render;
  EXPECT_EQ(r.width_px, 800);
  EXPECT_EQ(r.height_px, 600);
  EXPECT_EQ(r.fps, 5000.0);
  EXPECT_EQ(*r.t_start_s, 0.001);
  EXPECT_EQ(*r.t_end_s, 0.004);
  EXPECT_EQ(r.exaggeration, 50.0);
  EXPECT_EQ(r.reference_z_m, 0.001);
  EXPECT_EQ(r.view, RenderView::top);
  EXPECT_FALSE(r.follow_wheel);
  EXPECT_EQ(*r.view_width_m, 0.3);
  EXPECT_FALSE(r.ffmpeg);
  EXPECT_EQ(r.video_fps, 30.0);
  EXPECT_EQ(r.antialiasing, Antialiasing::msaa);
  EXPECT_FALSE(r.gltf);
  // The defaults of the two newest keys: FXAA, and a glTF beside the frames.
  const Scene plain = parse_scene("[render]\n", "r.toml");
  EXPECT_EQ(plain.render->antialiasing, Antialiasing::fxaa);
  EXPECT_TRUE(plain.render->gltf);
}

TEST(RenderSection, OutOfRangeValuesNameTheirKey) {
  EXPECT_EQ(error_of("[render]\nwidth = 0\n"), "render.width");
  EXPECT_EQ(error_of("[render]\nheight = 9000\n"), "render.height");
  EXPECT_EQ(error_of("[render]\nfps = -5\n"), "render.fps");
  EXPECT_EQ(error_of("[render]\nfps = 0\n"), "render.fps");
  EXPECT_EQ(error_of("[render]\nexaggeration = 0.5\n"), "render.exaggeration");
  EXPECT_EQ(error_of("[render]\nt_start = 0.004\nt_end = 0.001\n"), "render.t_end");
  EXPECT_EQ(error_of("[render]\nview = \"front\"\n"), "render.view");
  EXPECT_EQ(error_of("[render]\nantialias = \"ssaa\"\n"), "render.antialias");
  EXPECT_EQ(error_of("[render]\nwidht = 100\n"), "render.widht");  // a typo is not silently ignored
}

}  // namespace
}  // namespace railjoint
