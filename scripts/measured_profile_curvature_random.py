#!/usr/bin/env python3
"""Seeded random scenes of a measured profile read through its points (profile_tolerance = 0): the force
run's Hertz constant G against an independent Hertz solution on the arc the points sample.

usage: measured_profile_curvature_random.py BIN SEED N [TOLERANCE [NOISE_M]]

Three groups, N scenes each, on scenes/forces/lumped_track.toml (beta 0.03):
  cylinder  a head arc (radius 0.2-0.4 m: below the wheel's 0.475 m, where the ellipse is no circle) under a cylinder
  cone      a head arc under a cone (conicity 1:20-1:60, wheel.y +-3 mm)
  tread     a convex tread arc (radius 0.3-1.0 m) on a crowned head (0.2-0.4 m)
Points are exact (17 digits) every h (0.05-1 mm, log-uniform), the grid shifted by a random part of h so
the contact falls anywhere between knots. Reference: the second audit's own Hertz solution,
scripts/references/hertz_profiles.py (Johnson 1985 4.2; contact by antiparallel normals, curvatures from the
surfaces' second fundamental forms; needs python3-scipy). Prints each scene and, per group, the median, 90th percentile and max
of |G / G_ref - 1|, and those by spacing band, over the runs that vouch for their numbers (exit 0).
With NOISE_M > 0 every point gets a seeded normal error of sigma, log-uniform in NOISE_M * [0.01, 1]:
then the count of runs that say ok with G more than 1 % off must be 0 (the rest must say suspect).
"""
import json, math, os, subprocess, sys, tempfile
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'references'))  # the audit's hertz_profiles.py
import hertz_profiles as H

binary, seed, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
tolerance = sys.argv[4] if len(sys.argv) > 4 else '0'
noise_m = float(sys.argv[5]) if len(sys.argv) > 5 else 0.0
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, '..', 'scenes', 'forces', 'lumped_track.toml')
rng = np.random.default_rng(seed)
tmp = tempfile.mkdtemp()
noradius = os.path.join(tmp, 'noradius.toml')
with open(scene) as f, open(noradius, 'w') as g:
    g.write(''.join(line for line in f if not line.startswith('radius')))

def grid(lo, hi, h):
    start = lo - rng.uniform(0.0, 1.0) * h  # covers [lo, hi] whatever the shift
    return start + h * np.arange(int(math.ceil((hi - start) / h)) + 1)

def noisy(v):
    return v + rng.normal(0.0, noise_m * 10 ** rng.uniform(-2, 0), v.shape) if noise_m > 0 else v

rows = []
for group in ('cylinder', 'cone', 'tread'):
    for k in range(n):
        h = math.exp(rng.uniform(math.log(5e-5), math.log(1e-3)))
        rho = rng.uniform(0.2, 0.4)
        path = os.path.join(tmp, f'{group}_{k}.csv')
        args = ['--set', 'wheel.width=0.07', '--set', 'joint.half_width=0.036']
        if group in ('cylinder', 'cone'):
            y = grid(-0.036, 0.036, h)
            z = np.sqrt(rho * rho - y * y) - rho
            np.savetxt(path, np.c_[y, noisy(z)], delimiter=',', header='y_m,z_m', comments='', fmt='%.17g')
            kappa = rng.uniform(1 / 60, 1 / 20) if group == 'cone' else 0.0
            yw = rng.uniform(-0.003, 0.003) if group == 'cone' else 0.0
            cmd = [binary, 'simulate', scene, '--set', f'joint.rail_profile="{path}"',
                   '--set', f'joint.profile_tolerance={tolerance}', '--set', f'wheel.conicity={kappa!r}',
                   '--set', f'wheel.y={yw!r}'] + args
            ref = H.static(119857.5, 0.03, H.head_crown(rho), R=0.475, kappa=kappa, yw=yw)
            what = f'rho {rho:.3f} kappa {kappa:.4f} y_w {yw * 1e3:+.2f} mm'
        else:
            tread = rng.uniform(0.3, 1.0)
            y = grid(-0.035, 0.035, h)
            r = 0.475 - (tread - np.sqrt(tread * tread - y * y))
            np.savetxt(path, np.c_[y, noisy(r)], delimiter=',', header='y_m,r_m', comments='', fmt='%.17g')
            cmd = [binary, 'simulate', noradius, '--set', f'wheel.profile="{path}"',
                   '--set', f'wheel.profile_tolerance={tolerance}', '--set', 'joint.rail_profile="crowned"',
                   '--set', f'joint.crown_radius={rho!r}'] + args
            ref = H.static(119857.5, 0.03, H.head_crown(rho), R=0.475, tread_rho=tread)
            what = f'rho {rho:.3f} tread {tread:.3f}'
        out = subprocess.run(cmd + ['--json'], capture_output=True, text=True)
        if out.returncode not in (0, 1):
            print(f'{group} {k}: rc {out.returncode} {out.stderr.strip()[:200]}')
            continue
        j = json.loads(out.stdout)
        hz = j['sim']['forces']['hertz_at_p0']
        err = hz['hertz_constant_m_per_N2_3'] / ref['G'] - 1.0
        rows.append((group, h, err, out.returncode))
        print(f'{group:8s} {k:3d}  h {h * 1e3:.3f} mm  {what}: G {err:+.2e}  verdict {j["sim"]["verdict"]}, rc {out.returncode}')

print(f'\nseed {seed}, profile_tolerance {tolerance}, noise {noise_m:g} m: {sum(r[3] == 1 for r in rows)} of '
      f'{len(rows)} suspect; ok but G more than 1 % off: {sum(r[3] == 0 and abs(r[2]) > 0.01 for r in rows)}')
print(f'|G / G_ref - 1| of the runs that say ok:')
print(f'{"group":8s} {"h band":14s} {"n":>3s} {"median":>9s} {"p90":>9s} {"max":>9s}')
for group in ('cylinder', 'cone', 'tread'):
    for lo, hi in ((5e-5, 1e-3), (5e-5, 2e-4), (2e-4, 5e-4), (5e-4, 1e-3)):
        e = np.array([abs(r[2]) for r in rows if r[0] == group and r[3] == 0 and lo <= r[1] < hi + 1e-12])
        if len(e):
            print(f'{group:8s} {lo * 1e3:.2f}-{hi * 1e3:.2f} mm  {len(e):3d} {np.median(e):9.2e} '
                  f'{np.percentile(e, 90):9.2e} {e.max():9.2e}')
