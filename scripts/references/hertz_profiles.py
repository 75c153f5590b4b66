# An independent Hertz reference, written by the second outside audit (2026-11-29) from the docs and
# Johnson (1985), not from the code it checks; scripts/measured_profile_curvature_random.py compares with it.
# Needs python3-scipy (not in install_deps.sh: a study tool, not the test suite).
"""Own Hertz computation for a wheel cone (or a convex tread arc) on a crowned or 60E1 head, at the static
contact on the incoming slope z = -t x (t = tan(beta/2)). Geometry from the docs (real-geometry.md): 60E1 head =
300 mm arc for |y| <= 10.228 mm, 80 mm arc to 26.0265 mm, tangent arcs; cone r(y) = R - kappa (y - y_w).
Contact: the wheel's outward normal antiparallel to the rail's (solved for y and the angle phi round the axle).
Relative curvature: second fundamental forms of both surfaces as level sets (Hessian / |grad|) on a common
tangent basis, eigenvalues / 2 = A, B. Hertz (Johnson 1985, 4.2 / 3.61): B/A = ((a/b)^2 E(e) - K(e)) / (K(e) - E(e)),
a^3 = 3 P (K - E) / (2 pi E* e^2 A), b = a sqrt(1 - e^2), delta = 3 P K / (2 pi a E*), p0 = 3 P / (2 pi a b),
E* = E / (2 (1 - nu^2)). scipy's ellipk/ellipe (parameter m = e^2); e solved by brentq to 1e-15.
Own precision: ~1e-12 (the root solves); the curvature Hessians analytic."""
import math, numpy as np
from scipy.special import ellipk, ellipe
from scipy.optimize import brentq

def head_60e1():
    r1, r2, y1 = 0.3, 0.08, 0.010228
    c1 = np.array([0.0, -r1])
    p1 = np.array([y1, math.sqrt(r1*r1 - y1*y1) - r1])
    c2 = p1 - r2*(p1 - c1)/r1
    def h(y):
        ya = abs(y)
        if ya <= y1: z = math.sqrt(r1*r1 - ya*ya) - r1; d1 = -ya/math.sqrt(r1*r1 - ya*ya); d2 = -r1*r1/(r1*r1 - ya*ya)**1.5
        else:
            dy = ya - c2[0]; s = math.sqrt(r2*r2 - dy*dy); z = c2[1] + s; d1 = -dy/s; d2 = -r2*r2/s**3
        return z, (d1 if y >= 0 else -d1), d2
    return h

def head_crown(rho):
    def h(y):
        s = math.sqrt(rho*rho - y*y); return s - rho, -y/s, -rho*rho/s**3
    return h

def hertz_ellipse(A, B, P, Es):
    if A > B: A, B = B, A
    ratio = B/A
    if abs(ratio - 1) < 1e-12:
        a = (3*P/(4*Es*2*A))**(1/3)   # sphere: 1/R = 2A, a^3 = 3 P R / (4 E*)
        return a, a, 3*P/(2*math.pi*a*a), a*a*2*A
    f = lambda m: ((1/(1 - m))*ellipe(m) - ellipk(m))/(ellipk(m) - ellipe(m)) - ratio
    m = brentq(f, 1e-14, 1 - 1e-15, xtol=1e-16, rtol=1e-15)
    K, E = ellipk(m), ellipe(m)
    a = (3*P*(K - E)/(2*math.pi*Es*m*A))**(1/3); b = a*math.sqrt(1 - m)
    return a, b, 3*P/(2*math.pi*a*b), 3*P*K/(2*math.pi*a*Es)

def static(P0, beta, h, kappa=0.0, R=0.475, yw=0.0, E=210e9, nu=0.3, tread_rho=None):
    """wheel on the incoming slope: rail z = -t x + h(y); returns dict with contact y, N, A, B, a, b, p0, G."""
    t = math.tan(beta/2)
    if tread_rho is None:
        r = lambda y: R - kappa*(y - yw); dr = lambda y: -kappa; ddr = lambda y: 0.0
    else:  # convex tread arc across the track: r(y) = R - (rho - sqrt(rho^2 - (y - yw)^2))
        r = lambda y: R - (tread_rho - math.sqrt(tread_rho**2 - (y - yw)**2))
        dr = lambda y: -(y - yw)/math.sqrt(tread_rho**2 - (y - yw)**2)
        ddr = lambda y: -tread_rho**2/(tread_rho**2 - (y - yw)**2)**1.5
    # wheel outward grad at angle phi from the bottom (x = r sin phi, z = -r cos phi about the centre):
    # (sin phi, -r'(y), -cos phi); rail outward grad: (t, -h'(y), 1). Antiparallel:
    # wheel grad = -lambda rail grad: lambda = cos phi, sin phi = -t cos phi;
    # -r'(y) / (-cos phi) = -h'(y) / 1  -> h'(y) = -r'(y) / cos phi
    phi = -math.atan(t)   # sin phi = -t cos phi (the wheel grad = -cos(phi) x the rail grad)
    g = lambda y: h(y)[1] + dr(y)/math.cos(phi)
    yc = brentq(g, -0.035, 0.035, xtol=1e-15)
    # Hessians. Wheel: F = sqrt(dx^2 + dz^2) - r(y); at the point rho = r, grad = (s, -r', -c) with s = sin phi, c = cos phi
    s, c = math.sin(phi), math.cos(phi); rr = r(yc)
    gw = np.array([s, -dr(yc), -c])
    # Hessian of sqrt(dx^2+dz^2): (I - u u^T)/rho in the x-z block, u = (s, -c); minus r'' in yy
    Hw = np.zeros((3, 3))
    u = np.array([s, 0, -c]); P = np.diag([1.0, 0, 1.0]) - np.outer(u, u)
    Hw += P/rr; Hw[1, 1] -= ddr(yc)
    # Rail: Fr = z + t x - h(y), outward grad (t, -h', 1); Hessian: -h'' in yy
    hz, h1, h2 = h(yc)
    gr = np.array([t, -h1, 1.0]); Hr = np.zeros((3, 3)); Hr[1, 1] = -h2
    n = gr/np.linalg.norm(gr)
    # tangent basis
    e1 = np.array([1.0, 0, 0]); e1 -= n*np.dot(n, e1); e1 /= np.linalg.norm(e1); e2 = np.cross(n, e1)
    T = np.stack([e1, e2], 1)
    IIw = T.T @ Hw @ T / np.linalg.norm(gw); IIr = T.T @ Hr @ T / np.linalg.norm(gr)
    k = np.linalg.eigvalsh(IIw + IIr)
    A, B = k[0]/2, k[1]/2
    N = P0/n[2]
    Es = E/(2*(1 - nu*nu))
    a, b, p0, d = hertz_ellipse(A, B, N, Es)
    # a along the smaller relative curvature; report along / across track: which eigvec is closer to x
    w, V = np.linalg.eigh(IIw + IIr)
    along_is_A = abs(np.dot(T @ V[:, 0], [1, 0, 0])) > 0.5
    a_x, b_y = (a, b) if along_is_A else (b, a)
    return dict(y=yc, N=N, A=A, B=B, a_x=a_x, b_y=b_y, p0=p0, delta=d, G=d/N**(2/3), nz=n[2])

if __name__ == '__main__':
    print(static(119857.5, 0.03, head_60e1(), kappa=0.025))
