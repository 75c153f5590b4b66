// Bad sweep files are refused with the file, the key and what is allowed;
// an axis over a key no scene has is the sweep file's error, not a row per case.

#include "scenes/sweeps/sweep_file.h"

#include <gtest/gtest.h>

#include "scenes/sweeps/case_evaluator.h"
#include "scenes/sweeps/case_models.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

std::string error_of(const std::string& text) {
  try {
    const SweepFile s = parse_sweep_file(text, "bad.toml", "", case_model_names());
    const CaseEvaluator evaluator(s, case_models(s.models));
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    return std::string(error.key()) + " | " + error.what();
  }
  return "accepted";
}

TEST(SweepFile, RefusesWithTheKey) {
  const std::string ok_head = "base = \"default.toml\"\nrun = [\"analytic\"]\n";
  EXPECT_NE(error_of("run = [\"analytic\"]\n[axes]\n\"wheel.y\" = [0.0]\n").find("base |"), std::string::npos);
  EXPECT_NE(error_of("base = \"x.toml\"\n[axes]\n\"wheel.y\" = [0.0]\n").find("run |"), std::string::npos);
  EXPECT_NE(error_of("base = \"x.toml\"\nrun = [\"analytics\"]\n[axes]\n\"wheel.y\" = [0.0]\n").find("\"analytics\""),
            std::string::npos);
  EXPECT_NE(error_of(ok_head).find("axes |"), std::string::npos);
  EXPECT_NE(error_of(ok_head + "[axes]\n\"wheel.y\" = { from = 0.0, to = 0.01 }\n").find("axes.wheel.y.count |"),
            std::string::npos);
  EXPECT_NE(error_of(ok_head + "[axes]\n\"joint.beta\" = { from = 0.0, to = 0.01, count = 3, scale = \"log\" }\n")
                .find("from > 0"),
            std::string::npos);
  EXPECT_NE(error_of(ok_head + "[axes]\n\"wheel.y\" = [0.0]\n[sample]\ncount = 10\n").find("sample |"),
            std::string::npos);
  EXPECT_NE(error_of(ok_head + "[axes]\n\"wheel.y\" = []\n").find("axes.wheel.y |"), std::string::npos);
  EXPECT_NE(error_of(ok_head + "colour = 3\n[axes]\n\"wheel.y\" = [0.0]\n").find("colour |"), std::string::npos);
  // Typos in a scene key: the key, or its section.
  EXPECT_NE(error_of(ok_head + "[axes]\n\"wheel.sped\" = [10.0]\n").find("axes.wheel.sped | bad.toml"),
            std::string::npos);
  EXPECT_NE(error_of(ok_head + "[axes]\n\"whel.speed\" = [10.0]\n").find("axes.whel.speed |"), std::string::npos);
  // A value out of range is one case's problem, not the file's.
  EXPECT_EQ(error_of(ok_head + "[axes]\n\"wheel.y\" = [0.5, 0.01]\n"), "accepted");
  // Unquoted dotted keys and [axes.section] tables name the same axes.
  EXPECT_EQ(error_of(ok_head + "[axes]\nwheel.y = [0.0, 0.01]\n[axes.joint]\nbeta = { from = 0.01, to = 0.02, count = 2 }\n"),
            "accepted");
}

TEST(SweepFile, BaseSceneRelativeToTheSweepFile) {
  const SweepFile s = parse_sweep_file("base = \"../default.toml\"\nrun = [\"analytic\"]\n[axes]\n\"wheel.y\" = [0.0]\n",
                                       "scenes/sweeps/x.toml", "", case_model_names());
  EXPECT_EQ(s.base_scene, "scenes/default.toml");
  EXPECT_EQ(s.name, "x");
}

}  // namespace
}  // namespace railjoint
