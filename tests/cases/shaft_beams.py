"""Shafts for the rotor model's validation (tests/validation/test_shaft_*.py): shaft files written from a few
numbers, the closed forms of uniform beams, and seat matrices. Steel: E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3."""

import math

import numpy as np

from spindle.shaft import beam
from spindle.shaft.params import DEFAULT_SHAFT, shaft_path

E, NU, RHO = 210.0e9, 0.3, 7850.0
G = E / (2.0 * (1.0 + NU))
# Euler-Bernoulli free-free beam: roots of cos(bL) cosh(bL) = 1 (Blevins 1979, Formulas for Natural Frequency and
# Mode Shape, Table 8-1, case 1), to the printed digits
FREE_FREE_BETA_L = (4.73004074, 7.85320462, 10.9956078)


def _value(x, unit, source="validation case"):
    return f'{{ value = {x!r}, unit = "{unit}", source = "{source}" }}'


def shaft_file(path, sections, disks=(), seats=(), tip=0.0):
    """Write a steel shaft file: sections (length m, outer diameter m, inner diameter m, elements), disks (position
    m, mass kg, polar and diametral inertia kg m^2), seat positions (m) and the tool-tip position (m)."""
    lines = ['[meta]\nname = "validation"\n', '[[material]]\nname = "steel"']
    lines += [f"youngs_modulus = {_value(E, 'Pa')}", f"poisson_ratio = {_value(NU, '-')}"]
    lines += [f"density = {_value(RHO, 'kg/m^3')}\n"]
    for length, d_o, d_i, n in sections:
        lines += ["[[section]]", f"length = {_value(length, 'm')}", f"outer_diameter = {_value(d_o, 'm')}"]
        lines += [f"inner_diameter = {_value(d_i, 'm')}", 'material = "steel"', f"elements = {n}\n"]
    for z, m, ip, id_ in disks:
        lines += ["[[disk]]", f"position = {_value(z, 'm')}", f"mass = {_value(m, 'kg')}"]
        lines += [f"polar_inertia = {_value(ip, 'kg.m^2')}", f"diametral_inertia = {_value(id_, 'kg.m^2')}\n"]
    for z in seats:
        lines += ["[[seat]]", f"position = {_value(z, 'm')}\n"]
    lines += ["[tool_tip]", f"position = {_value(tip, 'm')}\n"]
    path.write_text("\n".join(lines))
    return path


def section_properties(d_o, d_i=0.0):
    """(A m^2, I m^4, kappa) of a hollow circular section (kappa: Cowper 1966, as the model)."""
    A = math.pi * (d_o**2 - d_i**2) / 4.0
    I = math.pi * (d_o**4 - d_i**4) / 64.0
    return A, I, beam.shear_coefficient(NU, d_o, d_i)


def euler_bernoulli_pinned(n, L, d_o, d_i=0.0):
    """n-th bending frequency (Hz) of a pinned-pinned Euler-Bernoulli beam: (n pi / L)^2 sqrt(E I / (rho A))."""
    A, I, _ = section_properties(d_o, d_i)
    return (n * math.pi / L) ** 2 * math.sqrt(E * I / (RHO * A)) / (2.0 * math.pi)


def euler_bernoulli_free(n, L, d_o, d_i=0.0):
    """n-th elastic bending frequency (Hz) of a free-free Euler-Bernoulli beam: (beta_n L / L)^2 sqrt(E I / rho A)."""
    A, I, _ = section_properties(d_o, d_i)
    return (FREE_FREE_BETA_L[n - 1] / L) ** 2 * math.sqrt(E * I / (RHO * A)) / (2.0 * math.pi)


def timoshenko_pinned(n, L, d_o, d_i=0.0):
    """n-th bending frequency (Hz) of a simply supported Timoshenko beam, the lower root of the frequency equation
    (Timoshenko 1921; Han, Benaroya & Wei 1999, J. Sound Vib. 225, 935-988, the hinged-hinged case, whose modes are
    sin(n pi z / L) for both fields): with k = n pi / L,
    (rho^2 I / (kappa G)) w^4 - (rho A + rho I k^2 (1 + E / (kappa G))) w^2 + E I k^4 = 0."""
    A, I, kappa = section_properties(d_o, d_i)
    k = n * math.pi / L
    a = RHO**2 * I / (kappa * G)
    b = RHO * A + RHO * I * k * k * (1.0 + E / (kappa * G))
    c = E * I * k**4
    w2 = (b - math.sqrt(b * b - 4.0 * a * c)) / (2.0 * a)
    return math.sqrt(w2) / (2.0 * math.pi)


def seat_matrix(k_radial, k_axial=0.0, k_moment=0.0, k_cross=0.0):
    """A bearing seat's 5x5 stiffness over (x, y, z, theta_x, theta_y): k_radial on x and y, k_cross as
    K[x, y] = -K[y, x] (a follower force, as an oil film's), k_axial on z, k_moment on both tilts."""
    K = np.diag([k_radial, k_radial, k_axial, k_moment, k_moment])
    K[0, 1], K[1, 0] = k_cross, -k_cross
    return K


def _spring_supported_determinant(lam, kappa):
    """The frequency determinant of a uniform Euler-Bernoulli beam on two translational springs at its ends (no
    moment stiffness), lam = beta L, kappa = k L^3 / (E I): w = A cos + B sin + C cosh + D sinh of beta x, with
    w'' = 0 at both ends, E I w''' = -k w at x = 0 and E I w''' = +k w at x = L (the boundary terms of the energy
    1/2 int E I w''^2 + 1/2 k w(0)^2 + 1/2 k w(L)^2), the spring rows divided by E I beta^3."""
    c, s, ch, sh = math.cos(lam), math.sin(lam), math.cosh(lam), math.sinh(lam)
    r = kappa / lam**3
    M = np.array(
        [
            [-1.0, 0.0, 1.0, 0.0],
            [r, -1.0, r, 1.0],
            [-c, -s, ch, sh],
            [s - r * c, -c - r * s, sh - r * ch, ch - r * sh],
        ]
    )
    return np.linalg.det(M)


def euler_bernoulli_spring_supported(count, L, d_o, k, lam_max=20.0):
    """The first `count` bending frequencies (Hz) of a uniform Euler-Bernoulli beam on two translational springs
    k (N/m) at its ends: the roots lam = beta L of its frequency determinant (_spring_supported_determinant; bracketed
    on a fine grid, then brentq to 1e-14), f = (lam / L)^2 sqrt(E I / (rho A)) / 2 pi. The first two are the rigid
    beam's bounce and rocking on the springs, bent by the beam's flexibility."""
    from scipy.optimize import brentq

    A, I, _ = section_properties(d_o)
    kappa = k * L**3 / (E * I)
    grid = np.linspace(1e-3, lam_max, 20001)
    values = [_spring_supported_determinant(x, kappa) for x in grid]
    roots = []
    for a, b, fa, fb in zip(grid[:-1], grid[1:], values[:-1], values[1:]):
        if fa * fb < 0.0 and len(roots) < count:
            roots.append(brentq(_spring_supported_determinant, a, b, args=(kappa,), xtol=1e-14, rtol=1e-15))
    return [(lam / L) ** 2 * math.sqrt(E * I / (RHO * A)) / (2.0 * math.pi) for lam in roots]


def default_shaft_with(path, old, new):
    """Write the default shaft file (spindle/shaft/params/rabreau_b7214c.toml) to `path` with the text `old`, found
    once in it, replaced by `new` (e.g. one value changed)."""
    text = shaft_path(DEFAULT_SHAFT).read_text()
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new))
    return path
