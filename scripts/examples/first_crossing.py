import sys, railjoint, matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
scene = railjoint.load_scene("scenes/default.toml", overrides={"wheel.speed": 30.0})  # 30 m/s, y_w = 15 mm
model, run = railjoint.analytic(scene), railjoint.simulate(scene)
print(f"scenario {model.scenario}, y_t = {model.y_t_m * 1e3:.3f} mm, x_A = {model.x_A_m * 1e3:.3f} mm")
print(f"jump: exact {model.exact_Ns:.4f}, thesis {model.thesis_Ns:.4f}, Bullet {run.jump_Ns:.4f} N s ({run.verdict})")
print(f"Bullet against each form: {run.error_exact:+.1e} {run.error_thesis:+.1e} {run.error_small_angle:+.1e}")
curve, points = model.time_history(before_mm=10, after_mm=12), run.trajectory
plt.plot(curve["t_s"] * 1e3, curve["zdot_exact_m_per_s"], label="kinematic model (exact)")
plt.plot(points["t_s"] * 1e3, points["zdot_m_per_s"], "o", mfc="none", ms=4, label="Bullet, one point a step")
plt.xlim(curve["t_s"][0] * 1e3, curve["t_s"][-1] * 1e3); plt.xlabel("t [ms], 0 at the impact"); plt.ylabel("vertical velocity of the wheel centre [m/s]"); plt.legend(); plt.savefig(sys.argv[1] if len(sys.argv) > 1 else "first_crossing.png", dpi=80)
