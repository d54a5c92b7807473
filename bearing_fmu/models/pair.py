r"""Duplex bearing pairs (X or O arrangement) from two quasi-static single-bearing models (docs/quasistatic.md).

Units: SI throughout (m, rad, N, N.m, rad/s, K).

Set-up. Two QuasiStaticModel bearings A and B (the same or different bearings) sit on one rigid
shaft (their inner rings) in one rigid housing (their outer rings), bearing centres `spacing` = s
apart (m). Global frame: z along the shaft, origin at the pair centre (midway between the bearing
centres). The shaft displacement relative to the housing is D = (x, y, z, theta_x, theta_y)
(m, m, m, rad, rad) at the pair centre; the external loads on the shaft there are
F_ext = (F_x, F_y, F_z, M_x, M_y) (N, N, N, N.m, N.m). D = 0 is the assembled pair at rest under
no external load (the preload alone).

Bearings. Each bearing's local frame is that of kernels.jones_harris: d = inner ring relative to
outer ring, and the bearing carries thrust for local z > 0. Bearing A is oriented with local z =
global z (it takes shaft thrust towards +z); bearing B is its axial mirror image (local z = -global
z, it takes thrust towards -z). The mirror about the x-y plane maps displacements (x, y, z, tx, ty)
-> (x, y, -z, -tx, -ty) and loads (F_x, F_y, F_z, M_x, M_y) likewise (M = diag(1, 1, -1, -1, -1)).
Bearing k sits at axial position a_k; the rigid shaft gives it (x + ty a_k, y - tx a_k, z, tx, ty),
so its local displacements are d_k = T_k D + offset, with T_A = T(a_A), T_B = M T(a_B),
T(a) = identity + a (e_x e_ty^T - e_y e_tx^T). The shaft needs F_ext = sum_k T_k^T F_k(d_k), F_k the
local loads of kernels.jones_harris (the load holding the inner ring at d_k).

Arrangement: the only thing `arrangement` changes is which bearing sits on which side. A bearing's
contact lines run from the inner contact (radially in, towards its local -z) to the outer contact
(out, towards local +z), so they meet the shaft axis ~ (d_m/2) tan(alpha) on the local -z side of
its centre (its load centre). Upper half of the axial section (contact lines, * = load centres):

        O (back-to-back)                  X (face-to-face)
     A (-s/2)      B (+s/2)            B (-s/2)      A (+s/2)
        /              \                   \            /
       /                \                   \          /
  ----*------------------*----  z     -------*--------*-------  z

- 'O' (back-to-back): A at a_A = -s/2, B at a_B = +s/2; the contact lines diverge towards the axis,
  the load centres lie outside the bearings, effective spread ~ s + d_m tan(alpha).
- 'X' (face-to-face): A at a_A = +s/2, B at a_B = -s/2; the load centres lie between the bearings,
  effective spread ~ s - d_m tan(alpha).
Nothing else is imposed: the load-centre offset is in each bearing's own stiffness (at rest its
coupling K[x, theta_y] ~ -K_xx (d_m/2) tan(alpha) about the bearing centre), so O gets the larger
tilting stiffness by itself.

Preload (F_preload = F_p > 0, N; assembled at rest, omega = 0, no thermal change):
- 'spring' (constant axial force): a spring pushes bearing B's outer ring axially with F_p. B's
  local axial displacement is free (load-controlled at F_z = F_p); its other four DOFs follow the
  shaft. A is fully tied to the shaft. B always carries F_p; A carries F_p + F_ext_z.
  dz_thermal has no effect (the spring takes up any length change).
- 'fixed' (fixed axial position, e.g. ground spacers): both bearings' axial positions are tied to
  the shaft. Each local axial offset is the axial approach z_k0 (m) at which bearing k alone carries
  F_p at rest; it is computed once, at construction, and kept: at speed (centrifugal and gyroscopic
  loads) and with dPd_thermal or dz_thermal the preload changes. dz_thermal (m) is the change of the
  pair's axial interference (> 0 tightens): each bearing's local axial approach grows by dz_thermal/2.
dPd_thermal = (dPd_A, dPd_B) (m): change of each bearing's diametral clearance (added to P_d,
negative = tighter), as the single-bearing input.

Solution: damped Newton on the shaft's five DOFs with the analytic pair stiffness
K_pair = dF_ext/dD = sum_k T_k^T K_k T_k (5x5, global; N/m, N, N.m per rad), each bearing solved by
kernels.jones_harris.solve_quasistatic (displacement-controlled, or the spring-loaded B with mixed
control (0, 0, 1, 0, 0)). For the spring-loaded B the free axial DOF is condensed (Schur
complement K_rr - K_rz K_zr / K_zz on r = x, y, tx, ty). The quasi-static mechanics have no
temperature dependence: T_oil (K) only sets the lubricant state of the film outputs (Lambda,
h_min) reported per bearing. The models themselves are not modified (the pair keeps its own
warm-start state). Warnings (PairResult.warnings): p_max above the ISO 76 limit, and balls of an
angular-contact bearing loaded at a negative contact angle (the kernel's full groove then stands in
for the bearing's low shoulder).
"""

import math
from dataclasses import dataclass, field

import numpy as np

from ..kernels import contact_outputs as ck
from ..kernels import jones_harris
from ..kernels.torque import TL_SIZE
from .input_checks import check_oil_temperature, check_speed
from .limits import InputError, pressure_warnings
from .quasi_static import QuasiStaticModel, SolverError

ARRANGEMENTS = ("X", "O")
PRELOADS = ("spring", "fixed")
MIRROR = np.diag([1.0, 1.0, -1.0, -1.0, -1.0])
_AXIAL = np.array([0.0, 0.0, 1.0, 0.0, 0.0])  # control vector: only the local axial DOF load-controlled
_NONE = np.zeros(5)  # control vector: displacement-controlled
_RADIAL = [0, 1, 3, 4]  # DOFs kept by the condensation of the free axial DOF
_BACKTRACK = 40


def transfer(a, mirrored=False):
    """5x5 map T from the shaft's D (at the pair centre) to the local d of a bearing at axial position a (m)."""
    T = np.eye(5)
    T[0, 4] = a
    T[1, 3] = -a
    return MIRROR @ T if mirrored else T


def condense_axial(K):
    """K (5x5) with the axial DOF free (zero axial load change): Schur complement, axial row/column zero."""
    Kc = np.zeros((5, 5))
    r = np.ix_(_RADIAL, _RADIAL)
    Kc[r] = K[r] - np.outer(K[_RADIAL, 2], K[2, _RADIAL]) / K[2, 2]
    return Kc


@dataclass
class BearingState:
    """One bearing of the pair at the solution (local frame, see the module docstring)."""

    name: str  # 'A' or 'B'
    position: float  # axial position of the bearing centre a_k (m)
    d: np.ndarray  # local displacements (x, y, z, theta_x, theta_y) (m, rad)
    F: np.ndarray  # local loads (F_x, F_y, F_z, M_x, M_y) (N, N.m)
    K: np.ndarray  # local stiffness dF/dd (5x5), axial DOF not condensed
    balls: np.ndarray  # per-ball rows (kernels.jones_harris BQ_*), a copy
    X: np.ndarray  # ball positions (2, Z) (m), a copy
    contacts: dict  # film/contact outputs at T_oil: Lambda_*, h_min_* (m), Q_max_* (N), p_max (Pa)

    @property
    def axial_load(self):
        """Axial load carried by the bearing (N), > 0 when its balls are in thrust."""
        return float(self.F[2])


@dataclass
class PairResult:
    """Solution of a pair: shaft displacement D (global), both bearings and K_pair (global, 5x5)."""

    D: np.ndarray
    F_ext: np.ndarray
    bearings: tuple  # (BearingState A, BearingState B)
    K_pair: np.ndarray
    iterations: int
    residual: float  # largest load error, moments / length scale (N)
    state: dict  # warm start for the next solve (PairAssembly.set_state)
    warnings: list = field(default_factory=list)

    @property
    def axial_loads(self):
        """(axial load of A, axial load of B) (N)."""
        return tuple(b.axial_load for b in self.bearings)


class PairAssembly:
    """Two bearings mounted as a duplex pair (module docstring); the fixed-preload offsets are set here.

    model_a, model_b: QuasiStaticModel (the same instance may be passed twice); arrangement 'X' | 'O';
    preload 'spring' | 'fixed'; F_preload (N) > 0; spacing (m) > 0, distance between the bearing
    centres.
    """

    def __init__(self, model_a, model_b, arrangement="X", preload="spring", F_preload=800.0, spacing=0.1):
        for m in (model_a, model_b):
            if not isinstance(m, QuasiStaticModel):
                raise InputError(f"pair bearings must be QuasiStaticModel instances, got {type(m).__name__}")
        if arrangement not in ARRANGEMENTS:
            raise InputError(f"arrangement = {arrangement!r}: allowed {list(ARRANGEMENTS)}")
        if preload not in PRELOADS:
            raise InputError(f"preload = {preload!r}: allowed {list(PRELOADS)}")
        F_preload = float(F_preload)
        if not (math.isfinite(F_preload) and F_preload > 0.0):
            raise InputError(
                f"F_preload = {F_preload} N must be a finite number > 0 (an unpreloaded pair has "
                f"no stiffness at zero load)"
            )
        spacing = float(spacing)
        if not (math.isfinite(spacing) and spacing > 0.0):
            raise InputError(f"spacing = {spacing} m must be a finite number > 0")
        self.models = (model_a, model_b)
        self.qs = tuple(m.qs.copy() for m in self.models)
        for qs in self.qs:
            qs[jones_harris.QS_STIFFNESS] = (
                1.0  # the pair's Newton needs each bearing's stiffness, whatever its scene exposes
            )
        self.arrangement = arrangement
        self.preload = preload
        self.F_preload = F_preload
        self.spacing = spacing
        a_A = 0.5 * spacing if arrangement == "X" else -0.5 * spacing
        self.positions = (a_A, -a_A)
        self.T = (transfer(a_A), transfer(-a_A, mirrored=True))
        self.scale = np.array([1.0, 1.0, 1.0, 0.5 * spacing, 0.5 * spacing])  # rotations as arc lengths
        self.groove = min(m.groove for m in self.models)
        self.tol = min(m.scene.tolerance for m in self.models)
        self.max_iterations = max(m.scene.max_iterations for m in self.models)
        for m in self.models:
            if m.load_limit <= F_preload:
                raise InputError(
                    f"F_preload = {F_preload} N is beyond the material limit of bearing "
                    f"'{m.bearing.name}' (allowed F_preload < {m.load_limit:.4g} N)"
                )
        # axial approach z_k0 (m) of each bearing alone carrying F_p at rest (the assembly offsets)
        self.z0 = tuple(m.axial_approach(self.F_preload) for m in self.models)
        self.set_state(None)

    # -- warm-start state ----------------------------------------------------------------------
    def get_state(self):
        """Warm-start state as plain lists: shaft D, B's free axial displacement, ball positions."""
        return {"D": self.D.tolist(), "z_B": self.z_B, "X": [x.tolist() for x in self.X]}

    def set_state(self, state):
        """Restore get_state(); None = cold start (assembled position)."""
        if state is None:
            self.D = np.zeros(5)
            self.z_B = self.z0[1]
            self.X = [np.zeros((2, m.bearing.Z)) for m in self.models]
        else:
            self.D = np.array(state["D"], dtype=float)
            self.z_B = float(state["z_B"])
            self.X = [np.array(x, dtype=float) for x in state["X"]]

    # -- one evaluation of both bearings -------------------------------------------------------
    def _bearing(self, k, D, omega, dPd, dz, X, z_guess):
        """Solve bearing k for shaft displacement D; X (warm start) updated in place.

        Returns (status, d, F, K, balls)."""
        model = self.models[k]
        d = self.T[k] @ D
        spring = k == 1 and self.preload == "spring"
        if spring:
            d[2] = z_guess
            control, applied = _AXIAL, self.F_preload * _AXIAL
        else:
            d[2] += self.z0[k] + (0.5 * dz if self.preload == "fixed" else 0.0)
            control, applied = _NONE, _NONE
        Z = model.bearing.Z
        F = np.zeros(5)
        K = np.zeros((5, 5))
        balls = np.zeros((jones_harris.BQ_SIZE, Z))
        d_start = d.copy()
        status = jones_harris.solve_quasistatic(applied, control, d, self.qs[k], dPd, omega, X, F, K, balls)[0]
        if status != jones_harris.QS_OK:  # the warm start can be far off: retry cold
            d[:] = d_start
            if spring:
                d[2] = self.z0[1]
            X[:] = 0.0
            status = jones_harris.solve_quasistatic(applied, control, d, self.qs[k], dPd, omega, X, F, K, balls)[0]
        return status, d, F, K, balls

    def _evaluate(self, D, omega, dPd, dz, X, z_B):
        """Both bearings at D: (ok, loads sum T^T F (5), K_pair (5x5), [(d, F, K, balls)] * 2)."""
        total = np.zeros(5)
        K_pair = np.zeros((5, 5))
        parts = []
        for k in range(2):
            status, d, F, K, balls = self._bearing(k, D, omega, dPd[k], dz, X[k], z_B)
            if status != jones_harris.QS_OK or not (np.all(np.isfinite(F)) and np.all(np.isfinite(K))):
                return False, None, None, None
            Kk = condense_axial(K) if (k == 1 and self.preload == "spring") else K
            T = self.T[k]
            total += T.T @ F
            K_pair += T.T @ Kk @ T
            parts.append((d, F, K, balls))
        return True, total, K_pair, parts

    def shaft_loads(self, D, omega=0.0, dPd_thermal=(0.0, 0.0), dz_thermal=0.0):
        """Loads (5, N and N.m) the shaft needs to be held at D, and K_pair there (state not touched)."""
        X = [x.copy() for x in self.X]
        ok, total, K_pair, _ = self._evaluate(
            np.asarray(D, float), float(omega), tuple(map(float, dPd_thermal)), float(dz_thermal), X, self.z_B
        )
        if not ok:
            raise SolverError(f"bearing equilibrium not found at D = {np.asarray(D).tolist()}")
        return total, K_pair

    # -- pair equilibrium ----------------------------------------------------------------------
    def _check(self, F_ext, omega, T_oil, dPd, dz):
        if F_ext.shape != (5,) or not np.all(np.isfinite(F_ext)):
            raise InputError(f"F_ext = {F_ext.tolist()} must be 5 finite numbers (F_x, F_y, F_z in N, M_x, M_y in N.m)")
        check_speed(omega, min(m.omega_max for m in self.models))
        check_oil_temperature(T_oil)
        if len(dPd) != 2:
            raise InputError(f"dPd_thermal = {dPd} must be a pair (dPd_A, dPd_B) in m")
        for name, v, m in (
            ("dPd_thermal[A]", dPd[0], self.models[0]),
            ("dPd_thermal[B]", dPd[1], self.models[1]),
            ("dz_thermal", dz, self.models[0]),
        ):
            limit = 0.02 * m.bearing.D
            if not (math.isfinite(v) and abs(v) <= limit):
                raise InputError(f"{name} = {v} m is outside the allowed range [{-limit:.4g}, {limit:.4g}] m")

    def solve(self, F_ext=(0.0,) * 5, omega=0.0, T_oil=313.15, dPd_thermal=(0.0, 0.0), dz_thermal=0.0):
        """Pair equilibrium under F_ext (N, N.m at the pair centre) at shaft speed omega (rad/s): PairResult.

        Raises InputError for inputs out of range or contact pressures beyond the material limit,
        SolverError when no equilibrium is found (the warm-start state is then left unchanged)."""
        F_ext = np.array(F_ext, dtype=float).reshape(-1)
        omega, T_oil, dz = float(omega), float(T_oil), float(dz_thermal)
        dPd = tuple(float(v) for v in dPd_thermal)
        self._check(F_ext, omega, T_oil, dPd, dz)
        result = self._newton(F_ext, omega, dPd, dz, self.D.copy(), [x.copy() for x in self.X], self.z_B)
        if not isinstance(result, tuple):  # the warm start can be far off: retry from the assembled position
            result = self._newton(F_ext, omega, dPd, dz, np.zeros(5), [np.zeros_like(x) for x in self.X], self.z0[1])
        if not isinstance(result, tuple):
            reason = result or "no equilibrium found"
            raise SolverError(
                f"pair equilibrium not found ({reason}) for F_ext = {F_ext.tolist()}, omega = {omega} "
                f"rad/s, {self.arrangement} arrangement, {self.preload} preload {self.F_preload} N"
            )
        D, X, parts, K_pair, iters, res = result
        self.D, self.X = D, X
        if self.preload == "spring":
            self.z_B = float(parts[1][0][2])
        return self._collect(F_ext, omega, T_oil, D, X, parts, K_pair, iters, res)

    def _newton(self, F_ext, omega, dPd, dz, D, X, z_B):
        """Damped Newton on D (scaled: rotations x s/2, moments / (s/2)); None if it failed."""
        s = self.scale
        ok, total, K_pair, parts = self._evaluate(D, omega, dPd, dz, X, z_B)
        if not ok:
            return None
        f_ref = max(self.F_preload, float(np.max(np.abs(F_ext / s))))
        step_cap = 0.05 * self.groove
        res = float(np.max(np.abs((F_ext - total) / s)))
        for it in range(self.max_iterations + 1):
            if not math.isfinite(res):
                return None
            if res <= self.tol * f_ref:
                return D, X, parts, K_pair, it, res
            if it == self.max_iterations:
                return f"no convergence in {self.max_iterations} iterations, load residual {res:.3g} N"
            Ks = K_pair * np.outer(1.0 / s, 1.0 / s)
            try:
                u = np.linalg.solve(Ks, (F_ext - total) / s)
            except np.linalg.LinAlgError:
                hint = ""
                if self.preload == "spring" and F_ext[2] <= -self.F_preload:
                    hint = (
                        ": with spring preload B always carries F_preload, so an axial load F_z <= -F_preload "
                        "lifts bearing A off its raceways"
                    )
                return "singular pair stiffness" + hint
            big = float(np.max(np.abs(u)))
            if big < 1e-15 * self.groove:  # at rounding level: nothing left to gain
                return D, X, parts, K_pair, it, res
            step = (u if big <= step_cap else u * (step_cap / big)) / s
            lam = 1.0
            accepted = None
            z_guess = parts[1][0][2]
            for _ in range(_BACKTRACK):
                X_try = [x.copy() for x in X]
                trial = self._evaluate(D + lam * step, omega, dPd, dz, X_try, z_guess)
                if trial[0]:
                    r_try = float(np.max(np.abs((F_ext - trial[1]) / s)))
                    if r_try < res:
                        accepted = (D + lam * step, X_try, trial, r_try)
                        break
                lam *= 0.5
            if accepted is None:
                return None
            D, X, (_, total, K_pair, parts), res = accepted
        return None

    def _collect(self, F_ext, omega, T_oil, D, X, parts, K_pair, iters, res):
        bearings = []
        warnings = []
        for k, (d, F, K, balls) in enumerate(parts):
            model = self.models[k]
            name = "AB"[k]
            out = np.zeros(ck.CO_SIZE)
            ck.contact_outputs(
                omega,
                T_oil,
                model.cp,
                model.lubricant.array,
                balls,
                out,
                np.zeros((ck.PC_SIZE, model.bearing.Z)),
                np.zeros(TL_SIZE),
            )
            p_max = float(out[ck.CO_PMAX])
            warnings += [
                f"bearing {name}: {w}"
                for w in pressure_warnings(p_max, f"bearing {name} ('{model.bearing.name}'): the loads")
            ]
            loaded = balls[jones_harris.BQ_Q_I] > 0.0
            if model.qs[jones_harris.QS_ANGULAR] > 0.5 and np.any(balls[jones_harris.BQ_A_I][loaded] < 0.0):
                warnings.append(
                    f"bearing {name}: balls loaded at a negative contact angle (axial load "
                    f"{F[2]:.4g} N against its thrust direction): the model's full groove stands in for "
                    f"the low shoulder of a real angular-contact bearing"
                )
            contacts = {
                "Lambda_inner": float(out[ck.CO_LAMBDA_I]),
                "Lambda_outer": float(out[ck.CO_LAMBDA_O]),
                "h_min_inner": float(out[ck.CO_HMIN_I]),
                "h_min_outer": float(out[ck.CO_HMIN_O]),
                "Q_max_inner": float(out[ck.CO_QMAX_I]),
                "Q_max_outer": float(out[ck.CO_QMAX_O]),
                "p_max": p_max,
                "n_loaded": int(out[ck.CO_N_LOADED]),
            }
            bearings.append(
                BearingState(name, self.positions[k], d.copy(), F.copy(), K.copy(), balls.copy(), X[k].copy(), contacts)
            )
        return PairResult(D.copy(), F_ext.copy(), tuple(bearings), K_pair, iters, res, self.get_state(), warnings)


def solve_pair(
    model_a,
    model_b,
    F_ext=(0.0,) * 5,
    omega=0.0,
    T_oil=313.15,
    arrangement="X",
    preload="spring",
    F_preload=800.0,
    spacing=0.1,
    dPd_thermal=(0.0, 0.0),
    dz_thermal=0.0,
    state=None,
):
    """One-shot pair solution (builds a PairAssembly, so the fixed-preload offsets come from the
    assembly at rest): PairResult. state: a previous PairResult.state for a warm start."""
    pair = PairAssembly(model_a, model_b, arrangement, preload, F_preload, spacing)
    if state is not None:
        pair.set_state(state)
    return pair.solve(F_ext, omega, T_oil, dPd_thermal, dz_thermal)
