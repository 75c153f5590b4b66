"""railjoint.solve_contact on a NumPy gap: Hertz's sphere (Johnson, Contact
Mechanics, 1985, eqs. 4.22-4.23, computed here), the no-surface mask, the cap,
and bad input as ValueError naming the argument."""

import math

import numpy as np
import pytest

E_STAR = 210e9 / (2 * (1 - 0.3**2))  # steel on steel


def sphere(n, cell_m, radius_m):
    x = (np.arange(n) - n // 2) * cell_m
    return (x[:, None] ** 2 + x[None, :] ** 2) / (2 * radius_m)


def test_hertz_sphere(railjoint):
    R, W = 0.475, 100e3
    a = (3 * W * R / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * W / (2 * math.pi * a * a)
    n = 64
    cell = 2.5 * a / n  # 51 cells across the patch, as the C++ tests' default grid
    out = railjoint.solve_contact(sphere(n, cell, R), cell, cell, W)
    p = out["pressure_Pa"]
    print(out["max_pressure_Pa"] / p0 - 1, out["contact_area_m2"] / (math.pi * a * a) - 1)
    assert isinstance(p, np.ndarray) and p.shape == (n, n)
    assert out["converged"]
    assert p.sum() * cell * cell == pytest.approx(W, rel=1e-10)
    assert out["max_pressure_Pa"] == pytest.approx(p0, rel=0.01)
    assert out["contact_area_m2"] == pytest.approx(math.pi * a * a, rel=0.02)
    # Symmetric in x and y: the transpose of the problem has the transposed answer
    # (the grid is centred on a cell, so mirror about it).
    assert np.allclose(p, p.T, rtol=1e-8, atol=1e-8 * p0)


def test_no_surface_and_cap(railjoint):
    R, W = 0.475, 100e3
    a = (3 * W * R / (4 * E_STAR)) ** (1 / 3)
    n = 64
    cell = 3.0 * a / n
    mask = np.zeros((n, n), dtype=bool)
    mask[n // 2 - 2 : n // 2 + 2, :] = True
    cap = 1.0e9
    out = railjoint.solve_contact(sphere(n, cell, R), cell, cell, W, no_surface=mask, yield_pressure_Pa=cap)
    p = out["pressure_Pa"]
    assert np.all(p[mask] == 0.0)
    assert p.max() <= cap
    assert out["plastic_area_m2"] > 0
    assert p.sum() * cell * cell == pytest.approx(W, rel=1e-8)


def test_bad_input_names_the_argument(railjoint):
    gap = sphere(32, 1e-3, 0.475)
    with pytest.raises(ValueError, match="yield_pressure_Pa"):
        railjoint.solve_contact(gap, 1e-3, 1e-3, 100e3, yield_pressure_Pa=1e6)
    with pytest.raises(ValueError, match="load_N"):
        railjoint.solve_contact(gap, 1e-3, 1e-3, -1.0)
