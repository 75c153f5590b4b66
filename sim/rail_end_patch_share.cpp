#include "sim/rail_end_patch_share.h"

#include "sim/spanning_contact_study.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace railjoint {

namespace {

// q(x) = c (1 - u^2), u = (x - x0) / a, c = 3 F / (4 a), on |u| <= 1.
struct LoadDensity {
  double x0, a, c;
  bool bears() const { return a > 0.0 && c > 0.0; }
  double at(double x) const {
    if (!bears()) return 0.0;
    const double u = (x - x0) / a;
    return std::abs(u) < 1.0 ? c * (1.0 - u * u) : 0.0;
  }
  // The load on (-inf, x]: 3F/4 (u - u^3/3 + 2/3), u clamped to [-1, 1].
  double load_to(double x) const {
    if (!bears()) return 0.0;
    const double u = std::clamp((x - x0) / a, -1.0, 1.0);
    return c * a * (u - u * u * u / 3.0 + 2.0 / 3.0);
  }
  double load() const { return bears() ? c * a * 4.0 / 3.0 : 0.0; }
};

LoadDensity density_of(const RailEndPatch& p) {
  if (!(p.force_N > 0.0) || !(p.semi_length_m > 0.0)) return {p.x_m, 0.0, 0.0};
  return {p.x_m, p.semi_length_m, 0.75 * p.force_N / p.semi_length_m};
}

// The real roots of q_0 - q_1 = A x^2 + B x + C (both written out over the
// whole line, not clamped to their patches).
void add_crossings(const LoadDensity& q0, const LoadDensity& q1, std::vector<double>& points) {
  // q = c - c (x - x0)^2 / a^2 = -k x^2 + 2 k x0 x + c - k x0^2, k = c / a^2.
  const double k0 = q0.c / (q0.a * q0.a), k1 = q1.c / (q1.a * q1.a);
  const double A = -k0 + k1;
  const double B = 2.0 * (k0 * q0.x0 - k1 * q1.x0);
  const double C = (q0.c - k0 * q0.x0 * q0.x0) - (q1.c - k1 * q1.x0 * q1.x0);
  const double scale = std::abs(A) + std::abs(B) / std::max(q0.a, q1.a);
  if (std::abs(A) <= 1e-14 * scale) {
    if (B != 0.0) points.push_back(-C / B);
    return;
  }
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return;
  // The stable form of the two roots.
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  points.push_back(q / A);
  if (q != 0.0) points.push_back(C / q);
}

}  // namespace

std::array<double, 2> merged_patch_shares(const RailEndPatch& rail_0, const RailEndPatch& rail_1) {
  const LoadDensity q0 = density_of(rail_0), q1 = density_of(rail_1);
  if (!q0.bears() || !q1.bears()) return {1.0, 1.0};
  const double lo = std::max(q0.x0 - q0.a, q1.x0 - q1.a);
  const double hi = std::min(q0.x0 + q0.a, q1.x0 + q1.a);
  if (!(lo < hi)) return {1.0, 1.0};  // disjoint (or touching) patches
  // Over the overlap [lo, hi] the larger density wins; it changes only where
  // q_0 = q_1, so integrate each piece between the crossings analytically.
  std::vector<double> points{lo, hi};
  add_crossings(q0, q1, points);
  std::sort(points.begin(), points.end());
  double lost_0 = 0.0, lost_1 = 0.0;  // each rail end's load where the other's is larger
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double a = std::max(points[k], lo), b = std::min(points[k + 1], hi);
    if (!(a < b)) continue;
    const double mid = 0.5 * (a + b);
    const double d = q0.at(mid) - q1.at(mid);
    const double piece_0 = q0.load_to(b) - q0.load_to(a), piece_1 = q1.load_to(b) - q1.load_to(a);
    if (d > 0.0) {
      lost_1 += piece_1;
    } else if (d < 0.0) {
      lost_0 += piece_0;
    } else {  // equal: each carries half of it
      lost_0 += 0.5 * piece_0;
      lost_1 += 0.5 * piece_1;
    }
  }
  return {std::clamp(1.0 - lost_0 / q0.load(), 0.0, 1.0), std::clamp(1.0 - lost_1 / q1.load(), 0.0, 1.0)};
}

double hertz_patch_approach_m_per_N(double distance_m, double semi_length_m, double combined_modulus_Pa) {
  const double r = std::abs(distance_m), a = semi_length_m;
  constexpr double kPi = 3.14159265358979323846;
  if (!(a > 0.0)) return 1.0 / (kPi * combined_modulus_Pa * std::max(r, 1e-12));
  const double p0_per_N = 1.5 / (kPi * a * a);  // 3 / (2 pi a^2)
  if (r <= a) return kPi * p0_per_N * (2.0 * a * a - r * r) / (4.0 * a * combined_modulus_Pa);
  return p0_per_N / (2.0 * a * combined_modulus_Pa) *
         ((2.0 * a * a - r * r) * std::asin(a / r) + r * a * std::sqrt(1.0 - a * a / (r * r)));
}

SpanningContact merged_spanning_contact(const std::array<double, 2>& penetration_m,
                                        const std::function<RailEndPatch(int, double)>& patch_at,
                                        double combined_modulus_Pa) {
  SpanningContact out;
  out.effective_penetration_m = penetration_m;
  if (!(penetration_m[0] > 0.0) || !(penetration_m[1] > 0.0)) return out;
  std::array<RailEndPatch, 2> patch{patch_at(0, penetration_m[0]), patch_at(1, penetration_m[1])};
  out.share = merged_patch_shares(patch[0], patch[1]);
  // The coupling is weak (the other's approach a few % of one's own): a
  // fixed point converges geometrically, ~10 rounds to 1e-12.
  for (int round = 0; round < 60; ++round) {
    std::array<double, 2> next{};
    for (int i = 0; i < 2; ++i) {
      const RailEndPatch& own = patch[i];
      const RailEndPatch& other = patch[1 - i];
      const LoadDensity q = density_of(other);
      const double inside_N =
          own.force_N > 0.0 ? q.load_to(own.x_m + own.semi_length_m) - q.load_to(own.x_m - own.semi_length_m) : 0.0;
      const double outside_N = out.share[1 - i] * std::max(0.0, q.load() - inside_N);
      next[i] = penetration_m[i] -
                outside_N * hertz_patch_approach_m_per_N(own.x_m - other.x_m, other.semi_length_m, combined_modulus_Pa);
    }
    const double change = std::max(std::abs(next[0] - out.effective_penetration_m[0]),
                                   std::abs(next[1] - out.effective_penetration_m[1]));
    out.effective_penetration_m = next;
    patch = {patch_at(0, next[0]), patch_at(1, next[1])};
    out.share = merged_patch_shares(patch[0], patch[1]);
    if (change <= 1e-12 * std::max(penetration_m[0], penetration_m[1])) break;
  }
  return out;
}

namespace {

thread_local const ScopedSpanningContactStudy* active_study = nullptr;

}  // namespace

struct SpanningContactStudyAccess {
  static SpanningLaw law(const ScopedSpanningContactStudy& s) { return s.law_; }
  static std::vector<SpanningTraceEntry>* trace(const ScopedSpanningContactStudy& s) { return s.trace_; }
};

ScopedSpanningContactStudy::ScopedSpanningContactStudy(SpanningLaw law, std::vector<SpanningTraceEntry>* trace)
    : law_(law), trace_(trace), previous_(active_study) {
  active_study = this;
}

ScopedSpanningContactStudy::~ScopedSpanningContactStudy() { active_study = previous_; }

SpanningContact spanning_contact(const std::array<double, 2>& penetration_m,
                                 const std::function<RailEndPatch(int, double)>& patch_at, double combined_modulus_Pa) {
  if (active_study == nullptr) return merged_spanning_contact(penetration_m, patch_at, combined_modulus_Pa);
  const SpanningContact out = SpanningContactStudyAccess::law(*active_study) == SpanningLaw::conservative
                                  ? conservative_spanning_contact(penetration_m, patch_at, combined_modulus_Pa)
                                  : merged_spanning_contact(penetration_m, patch_at, combined_modulus_Pa);
  if (std::vector<SpanningTraceEntry>* trace = SpanningContactStudyAccess::trace(*active_study)) {
    SpanningTraceEntry e{penetration_m, out.effective_penetration_m, out.share, {}};
    for (int i = 0; i < 2; ++i) e.hertz_force_N[i] = patch_at(i, std::max(0.0, out.effective_penetration_m[i])).force_N;
    trace->push_back(e);
  }
  return out;
}

double spanning_contact_energy_J(const std::array<double, 2>& penetration_m, const SpanningContact& contact,
                                 const std::function<RailEndPatch(int, double)>& patch_at) {
  double energy_J = 0.0;
  for (int i = 0; i < 2; ++i) {
    const double e = std::max(0.0, contact.effective_penetration_m[i]);
    if (!(penetration_m[i] > 0.0) || !(e > 0.0)) continue;
    const double hertz_N = patch_at(i, e).force_N;
    energy_J += contact.share[i] * hertz_N * (0.4 * e + 0.5 * (penetration_m[i] - e));
  }
  return energy_J;
}

SpanningContact conservative_spanning_contact(const std::array<double, 2>& penetration_m,
                                              const std::function<RailEndPatch(int, double)>& patch_at,
                                              double combined_modulus_Pa) {
  SpanningContact out = merged_spanning_contact(penetration_m, patch_at, combined_modulus_Pa);
  if (!(penetration_m[0] > 0.0) || !(penetration_m[1] > 0.0)) return out;
  const auto energy_at = [&](const std::array<double, 2>& d) {
    return spanning_contact_energy_J(d, merged_spanning_contact(d, patch_at, combined_modulus_Pa), patch_at);
  };
  for (int i = 0; i < 2; ++i) {
    // 1e-5 of the penetration: the fixed point's 1e-12 of it leaves 1e-7 of
    // the force, the central difference's error (d^3U h^2) about 1e-10.
    const double h = 1e-5 * penetration_m[i];
    std::array<double, 2> up = penetration_m, down = penetration_m;
    up[i] += h;
    down[i] -= h;
    const double force_N = std::max(0.0, (energy_at(up) - energy_at(down)) / (2.0 * h));
    const double hertz_N = patch_at(i, std::max(0.0, out.effective_penetration_m[i])).force_N;
    out.share[i] = hertz_N > 0.0 ? force_N / hertz_N : 0.0;
  }
  return out;
}

double rolling_semi_length_m(double wheel_radius_m, double penetration_m) {
  return penetration_m > 0.0 ? std::sqrt(wheel_radius_m * penetration_m) : 0.0;
}

}  // namespace railjoint
