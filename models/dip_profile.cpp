#include "models/dip_profile.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace railjoint {

namespace {
// Incoming rail falls towards the V bottom, outgoing rises from it.
double side_sign(int rail) {
  assert(rail == 0 || rail == 1);
  return rail == 0 ? -1.0 : 1.0;
}

// Height and d(height)/ds of one rail end at distance s from the V (header).
struct DipPoint {
  double height_m;
  double slope;
};

// tan(beta / 2), the rail end's slope at the joint, remembered for the last
// beta: the narrow phase asks for the dip's height some thirty times a step
// with the same joint, and libm's tan was a tenth of a 60E1 force run.
double half_dip_slope(double beta_rad) {
  thread_local double last_beta_rad = 0.0;
  thread_local double last_slope = 0.0;  // tan(0)
  if (beta_rad != last_beta_rad) {
    last_slope = std::tan(beta_rad / 2.0);
    last_beta_rad = beta_rad;
  }
  return last_slope;
}

DipPoint droop(const JointParams& joint, double s_m) {
  const double t = half_dip_slope(joint.beta_rad);
  if (joint.dip_shape == DipShape::linear || s_m <= 0.0) return {t * s_m, t};
  const double D = joint.dip_length_m;
  const double s = std::min(s_m, D);
  const double level = s_m >= D ? 0.0 : 1.0;
  if (joint.dip_shape == DipShape::quadratic) return {t * s - t * s * s / (2.0 * D), level * t * (1.0 - s / D)};
  const double k = std::numbers::pi / (2.0 * D);
  return {t / k * std::sin(k * s), level * t * std::cos(k * s)};
}
}  // namespace

double dip_height_m(const JointParams& joint, int rail, double x_m) {
  if (joint.dip_shape == DipShape::linear) return side_sign(rail) * half_dip_slope(joint.beta_rad) * x_m;
  return droop(joint, side_sign(rail) * x_m).height_m;
}

double dip_slope(const JointParams& joint, int rail, double x_m) {
  if (joint.dip_shape == DipShape::linear) return side_sign(rail) * half_dip_slope(joint.beta_rad);
  return side_sign(rail) * droop(joint, side_sign(rail) * x_m).slope;
}

int dip_pieces_along_x(const JointParams& joint) {
  // A curved dip is drawn and exported with this many flat pieces per rail end;
  // the model and the checks read the exact curve.
  return joint.dip_shape == DipShape::linear ? 1 : 64;
}

const char* to_string(DipShape shape) {
  switch (shape) {
    case DipShape::linear: return "linear";
    case DipShape::quadratic: return "quadratic";
    case DipShape::cosine: return "cosine";
  }
  return "?";
}

double dip_depth_m(DipShape shape, double beta_rad, double dip_length_m) {
  const double t = std::tan(beta_rad / 2.0);
  switch (shape) {
    case DipShape::quadratic: return t * dip_length_m / 2.0;
    case DipShape::cosine: return 2.0 * t * dip_length_m / std::numbers::pi;
    case DipShape::linear: break;
  }
  return 0.0;
}

double dip_angle_from_depth_rad(DipShape shape, double depth_m, double dip_length_m) {
  switch (shape) {
    case DipShape::quadratic: return 2.0 * std::atan(2.0 * depth_m / dip_length_m);
    case DipShape::cosine: return 2.0 * std::atan(std::numbers::pi * depth_m / (2.0 * dip_length_m));
    case DipShape::linear: break;
  }
  return 0.0;
}

}  // namespace railjoint
