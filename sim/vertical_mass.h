#pragma once
// One body of the force run (elastic_crossing_run.h) as a plain state: it
// moves along z only (the wheel's horizontal speed is held by the carrier).
// The run steps it by velocity Verlet (kick, drift, kick), the velocity-
// dependent forces taken at a predicted velocity:
//   advance(dt)        v_half = v + a dt/2, z += v_half dt, and v predicted
//                      at the step's end as v_half + a dt/2;
//   accelerate(F, dt/2) a = F / m from the forces at the new z (dampers at
//                      the predicted v), v = v_half + a dt/2.
// Second order in the step: the predicted v is off the final one by
// O(dt^2) (the change of a over the step times dt/2), so a damper's force
// is too and the step's velocity by O(dt^3). Bullet integrated these bodies
// before and added nothing there but bookkeeping: its step was
// v += F / m dt, z += v dt bit for bit (5,250 steps, no mismatch), first order.

namespace railjoint {

struct VerticalMass {
  double mass_kg = 1.0;
  double z_m = 0.0;
  double zdot_m_per_s = 0.0;  ///< the step's end (between advance and accelerate: predicted)
  double zddot_m_per_s2 = 0.0;
  double half_step_zdot_m_per_s = 0.0;

  VerticalMass(double mass, double z, double zdot)
      : mass_kg(mass), z_m(z), zdot_m_per_s(zdot), half_step_zdot_m_per_s(zdot) {}

  void advance(double dt_s) {
    half_step_zdot_m_per_s = zdot_m_per_s + 0.5 * dt_s * zddot_m_per_s2;
    z_m += half_step_zdot_m_per_s * dt_s;
    zdot_m_per_s = half_step_zdot_m_per_s + 0.5 * dt_s * zddot_m_per_s2;
  }
  /// `force_N` up; `half_step_s` 0 at the start of a run (the start's accelerations alone).
  void accelerate(double force_N, double half_step_s) {
    zddot_m_per_s2 = force_N / mass_kg;
    zdot_m_per_s = half_step_zdot_m_per_s + half_step_s * zddot_m_per_s2;
  }
};

/// A spring and damper between a body above and one below (or the ground):
/// the force it pushes them apart with [N], from its compression [m] and the
/// compression's rate [m/s].
inline double spring_damper_N(double stiffness_N_per_m, double damping_N_s_per_m, double compression_m,
                              double compression_rate_m_per_s) {
  return stiffness_N_per_m * compression_m + damping_N_s_per_m * compression_rate_m_per_s;
}

}  // namespace railjoint
