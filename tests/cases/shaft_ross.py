"""The shaft model against ROSS (ross-rotordynamics 2.3.0, a test-only dependency; Timbó et al. 2020, "ROSS -
Rotordynamic Open Source Software", J. Open Source Softw. 5(48), 2120): the same shafts built from the same shaft
file with ROSS's ShaftElement (Timoshenko: shear with Cowper's coefficient, rotary inertia, gyroscopic effect; 6 dof
per node, its torsion left out of the comparison), DiskElement and BearingElement (kxx, kyy, kxy, kyx and kzz: the
seat K's radial block and axial entry). ROSS's bearings carry no moment, so the model's seats get zero moment
stiffness here.

Compared, with the product's default reduction (12 fixed-interface modes plus the seats and the tool tip):
- the first six natural frequencies (Hz) at rest, 10 000 and 20 000 rpm, each against ROSS's nearest (a pair at
  rest: one ROSS mode each), within 0.5 %: the two discretise the same Timoshenko theory with the same elements, so
  they agree to the reduction's error (measured at most 0.04 %, the third bending pair; without reduction 2e-6);
  the 0.5 % is a shaft model's budget, far above that, far below a missing effect (the gyroscopic split at
  20 000 rpm is 2.4 % of the first pair's frequency). tests/validation/test_shaft_ross.py also checks the whirl;
- the first two forward synchronous critical speeds against ROSS's run_critical_speed (an iteration on run_modal,
  to rtol 1e-8) whose mode at that speed does not whirl backward, within 1 %: the model solves the synchronous
  eigenproblem directly; measured at most 0.013 % (reduction; without it 1e-9, or 0.004 % with cross-coupled seats,
  where the synchronous roots have a real part and the two definitions of a damped critical speed part slightly).
The reference's own uncertainty: ROSS's dense eigen-solution in double precision (taken as 1e-9 relative) and, for
the critical speeds, its iteration's rtol of 1e-8.
Cases: the Rabreau rig's shaft (spindle/shaft/params/rabreau_b7214c.toml) on isotropic seats; the same on
anisotropic seats with cross-coupling (kxx != kyy, kxy = -kyx: an oil film's follower terms); a hollow shaft
(a bored spindle) with two disks, overhung.
"""

import math
import tempfile
import warnings
from pathlib import Path

import numpy as np

from spindle.shaft import ShaftModel
from spindle.shaft.params import read_shaft

from . import shaft_beams as sb
from .comparison import Comparison, ReferenceCase

SPEEDS_RPM = (0.0, 10000.0, 20000.0)
K_AXIAL = 5.0e7  # N/m
FREQUENCY_TOLERANCE, CRITICAL_TOLERANCE = 5e-3, 1e-2  # relative: grounds in the module docstring
EIGEN_UNCERTAINTY, CRITICAL_RTOL = 1e-9, 1e-8  # relative


def seat(kxx, kyy, kxy):
    K = np.diag([kxx, kyy, K_AXIAL, 0.0, 0.0])
    K[0, 1], K[1, 0] = kxy, -kxy
    return K


def hollow_shaft(directory):
    sections = [(0.05, 0.09, 0.04, 5), (0.30, 0.08, 0.04, 24), (0.10, 0.06, 0.03, 8)]
    disks = [(0.0, 4.0, 0.012, 0.009), (0.45, 2.0, 0.002, 0.0015)]
    return sb.shaft_file(Path(directory) / "hollow.toml", sections, disks, seats=(0.05, 0.35), tip=0.0)


SHAFTS = {
    "rabreau_isotropic": (lambda directory: "rabreau_b7214c", seat(2e8, 2e8, 0.0), seat(2e8, 2e8, 0.0)),
    "rabreau_cross_coupled": (lambda directory: "rabreau_b7214c", seat(2e8, 1.5e8, 2e7), seat(1.5e8, 1.2e8, -1e7)),
    "hollow_overhung": (hollow_shaft, seat(3e8, 3e8, 0.0), seat(1e8, 1e8, 0.0)),
}


def ross_rotor(path, K_seats):
    """The ROSS rotor of a shaft file with the seats' radial and axial stiffness."""
    import ross as rs  # the reference, a test-only dependency: imported when a case runs

    sf = read_shaft(path)
    steel = rs.Material(name="steel_shaft_model", rho=sb.RHO, E=sb.E, Poisson=sb.NU)
    shaft = [
        rs.ShaftElement(L=r[4], idl=r[6], odl=r[5], material=steel, shear_effects=True, rotary_inertia=True)
        for r in sf.elements
    ]
    disks = [rs.DiskElement(n=int(d[0]), m=d[1], Id=d[3], Ip=d[2]) for d in sf.disks]
    bearings = [
        rs.BearingElement(n=n, kxx=K[0, 0], kyy=K[1, 1], kxy=K[0, 1], kyx=K[1, 0], kzz=K[2, 2], cxx=0.0)
        for n, K in zip(sf.seat_nodes, K_seats)
    ]
    return rs.Rotor(shaft, disks, bearings)


def build(name):
    """(the model with the default reduction, the ROSS rotor, the seats' K) of a shaft of SHAFTS."""
    make, K1, K2 = SHAFTS[name]
    K_seats = np.array([K1, K2])
    with tempfile.TemporaryDirectory() as directory, warnings.catch_warnings():
        warnings.simplefilter("ignore")  # ROSS's deprecation and unit notes
        path = make(directory)
        return ShaftModel(path), ross_rotor(path, K_seats), K_seats


def matched_modes(name):
    """Per speed (rpm) and mode of the model: (rpm, f Hz, whirl code, ROSS's nearest f Hz, its whirl direction),
    each ROSS mode matched once."""
    model, rotor, K_seats = build(name)
    rows = []
    for rpm in SPEEDS_RPM:
        omega = rpm * math.pi / 30.0
        out = model.evaluate(omega, K_seats, critical_speeds=False)
        modal = rotor.run_modal(omega, num_modes=40, sparse=False)
        f_ross, whirl_ross = modal.wd / (2.0 * math.pi), modal.whirl_direction()
        used = set()
        for f, whirl in zip(out["frequencies"], out["whirl"]):
            distance = np.abs(f_ross - f)
            distance[list(used)] = np.inf
            k = int(np.argmin(distance))
            used.add(k)
            rows.append((rpm, float(f), int(whirl), float(f_ross[k]), whirl_ross[k]))
    return rows


def matched_critical_speeds(name):
    """Per forward critical speed of the model: (its speed rad/s, ROSS's nearest rad/s, ROSS's whirl there)."""
    model, rotor, K_seats = build(name)
    ross = rotor.run_critical_speed(num_modes=40, rtol=1e-8).wd()
    rows = []
    for speed in model.critical_speeds(K_seats):
        k = int(np.argmin(np.abs(ross - speed)))
        modal = rotor.run_modal(ross[k], num_modes=40, sparse=False)
        j = int(np.argmin(np.abs(modal.wd - ross[k])))
        rows.append((float(speed), float(ross[k]), modal.whirl_direction()[j]))
    return rows


def compare_frequencies():
    return [
        Comparison(f"{name} {rpm:g} rpm, {f_ross:.1f} Hz mode", f, f_ross, EIGEN_UNCERTAINTY, FREQUENCY_TOLERANCE)
        for name in SHAFTS
        for rpm, f, _, f_ross, _ in matched_modes(name)
    ]


def compare_critical_speeds():
    out = []
    for name in SHAFTS:
        for k, (speed, ross, _) in enumerate(matched_critical_speeds(name)):
            out.append(Comparison(f"{name} critical speed {k + 1} (rad/s)", speed, ross, CRITICAL_RTOL,
                                  CRITICAL_TOLERANCE))  # fmt: skip
    return out


def evaluation():
    """One evaluation of the rig's shaft at 10 000 rpm on isotropic seats, critical speeds included (a step of
    SpindleShaft.fmu whose seats changed)."""
    with tempfile.TemporaryDirectory() as directory:
        make, K1, K2 = SHAFTS["rabreau_isotropic"]
        model = ShaftModel(make(directory))
    K_seats = np.array([K1, K2])
    return lambda: model.evaluate(10000.0 * math.pi / 30.0, K_seats)


SOURCE = "ROSS 2.3.0 (Timbó et al. 2020, J. Open Source Softw. 5, 2120) on the same shafts"
CASES = (
    ReferenceCase(
        "shaft_ross_frequencies",
        "spindle shaft",
        "first six natural frequencies at 0, 10 000, 20 000 rpm; three shafts",
        SOURCE,
        compare_frequencies,
        evaluation,
    ),
    ReferenceCase(
        "shaft_ross_critical_speeds",
        "spindle shaft",
        "first two forward critical speeds; three shafts",
        SOURCE,
        compare_critical_speeds,
        evaluation,
    ),
)
