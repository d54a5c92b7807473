"""ShaftModel: facade of the rotor finite-element model of a spindle shaft (docs/shaft.md).

Reads a shaft file (spindle.shaft.params), assembles the shaft's M, K and gyroscopic G once with the kernels of
spindle.shaft.beam and reduces them once (Craig & Bampton 1968, AIAA J. 6, 1313-1319): the seat nodes and the
tool-tip node keep their 5 physical degrees of freedom (the interface), the rest is represented by the lowest
`modes` modes of the shaft clamped at the interface plus the interface's static constraint modes. A bearing's
5x5 stiffness and damping then add to the reduced matrices directly, and a call (speed, seat matrices) solves
a state-space eigenproblem of 2 (5 n_interface + modes) unknowns with numpy.linalg.eig: no scipy on this path
(an FMU host may lack it). `modes=None` keeps every degree of freedom (no reduction).
"""

import math

import numpy as np

from bearing_fmu_common.blas_threads import single_blas_thread
from bearing_fmu_common.variables import InputError

from . import beam
from .params import DEFAULT_SHAFT, ShaftFile, read_shaft, shaft_path

N_FREQUENCIES = 6
MODES_DEFAULT = 12
OMEGA_MAX = 1.0e4  # rad/s (95 500 rpm): above any spindle's speed
SEAT_MATRIX_MAX = 1.0e13  # N/m, N/rad, N.m/rad or N.s/m: a bearing's entries are orders of magnitude below
RESIDUE_FLOOR = 1e-9  # share of the largest modal residue of H_xx below which a mode does not show in it
RIGID_RATIO = 1.0e-8  # a mode whose strain-energy frequency^2 is below this share of the model's largest is rigid
# |mean sense| below which a shape is planar: anisotropic seats make elliptic orbits, whose sense still counts
PLANAR = 1.0e-3
OSCILLATING = 1e-9  # Im lambda / |lambda| above which a root is an oscillating mode, not a real (overdamped) root
WHIRL_FORWARD, WHIRL_NONE, WHIRL_BACKWARD, WHIRL_AXIAL = 1, 0, -1, 2
# The synchronous problem projected on the undamped modes of the seated shaft (_projected_speeds): the modes up to
# SYNC_BAND times the frequency of mode 2 x count, and a root is trusted only below 1 / SYNC_BAND of the first mode
# left out (a mode basis represents the shapes well below its truncation)
SYNC_BAND = 3.0
SYNC_MOVE = 1e-3  # relative move of a projected root in its refinement above which the projection is not trusted
NEWTON_STEPS = 8  # refinement steps of a projected root; quadratic convergence needs three or four
NEWTON_TOLERANCE = 1e-12  # relative Newton step below which a root is converged (the next step is at rounding)

__all__ = ["ShaftInputError", "ShaftModel", "shaft_path", "DEFAULT_SHAFT"]


class ShaftInputError(InputError):
    """An input of the shaft model is outside its allowed range (the message names it and the range)."""


def full_matrices(shaft):
    """(K, M, G) of the whole shaft without seats (N = 5 n_nodes square; G per unit speed), shear coefficients
    filled in from each element's Poisson's ratio."""
    elements = shaft.elements.copy()
    for e in range(elements.shape[0]):
        elements[e, 3] = beam.shear_coefficient(shaft.poisson[e], elements[e, 5], elements[e, 6])
    n = beam.NDOF * shaft.z.size
    K, M, G = np.empty((n, n)), np.empty((n, n)), np.empty((n, n))
    beam.assemble_shaft(elements, K, M, G)
    beam.add_disks(shaft.disks, M, G)
    return K, M, G


def craig_bampton(K, M, boundary, modes):
    """Basis T (N x (n_b + modes)) of the Craig-Bampton reduction: the boundary dofs first (identity on them,
    their static constraint modes -K_ii^-1 K_ib inside), then the lowest `modes` fixed-interface modes
    (mass-normalised); modes=None: the identity, boundary first, then the other dofs in order."""
    n = K.shape[0]
    inner = np.setdiff1d(np.arange(n), boundary)
    if modes is None:
        order = np.concatenate([boundary, inner])
        return np.eye(n)[:, order]
    modes = min(modes, inner.size)
    Kii, Kib, Mii = K[np.ix_(inner, inner)], K[np.ix_(inner, boundary)], M[np.ix_(inner, inner)]
    Lc = np.linalg.cholesky(Mii)
    A = np.linalg.solve(Lc, np.linalg.solve(Lc, Kii).T).T  # L^-1 K L^-T, symmetric
    w2, Y = np.linalg.eigh(0.5 * (A + A.T))
    Phi = np.linalg.solve(Lc.T, Y[:, :modes])
    T = np.zeros((n, boundary.size + modes))
    T[boundary, np.arange(boundary.size)] = 1.0
    T[np.ix_(inner, np.arange(boundary.size))] = -np.linalg.solve(Kii, Kib)
    T[np.ix_(inner, boundary.size + np.arange(modes))] = Phi
    return T


def whirl_senses(shapes):
    """Whirl of complex mode shapes over the full dofs (one per column, e^{lambda t}, Im lambda > 0): +1 forward
    (the orbit of the translations turns with the spin, +z), -1 backward, 0 none (a planar shape of a degenerate pair
    at rest), 2 axial (the axial translations outweigh the radial ones); the mean of -2 Im(conj(x) y) / (|x|^2 +
    |y|^2) over the nodes, weighted by amplitude, decides (+1 for a circular forward orbit, -1 backward, 0 planar).
    At rest the facade reports no whirl: a pair of an axisymmetric shaft is degenerate, any combination of its
    shapes (planar, forward, backward) is a mode. All columns at once: a few array operations, not a few per mode."""
    nodes = shapes.reshape(-1, beam.NDOF, shapes.shape[1])
    x, y, z = nodes[:, 0], nodes[:, 1], nodes[:, 2]
    radial = np.sum(np.abs(x) ** 2 + np.abs(y) ** 2, axis=0)
    axial = np.sum(np.abs(z) ** 2, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):  # a shape without radial motion is axial: its s is unused
        s = -2.0 * np.sum(np.imag(np.conj(x) * y), axis=0) / radial
    sense = np.where(s > PLANAR, WHIRL_FORWARD, np.where(s < -PLANAR, WHIRL_BACKWARD, WHIRL_NONE))
    return np.where(radial <= axial, WHIRL_AXIAL, sense)


class ShaftModel:
    """Rotor finite-element model of a shaft file (catalogue name or path), reduced once to `modes` fixed-interface
    modes plus the seat and tool-tip nodes (None: no reduction). `evaluate(omega, K_seats, C_seats)` gives the
    modal outputs at speed omega (rad/s) with the bearings' 5x5 matrices at the seats, in the file's seat order and
    each in its bearing's frame (the seat's bearing_axis turns it into the shaft's); `floating` (one boolean per
    seat) marks the seats whose outer ring floats axially under a constant preload force (seat_stiffness). `shaft`
    may also be a ShaftFile already read (params.shaft_with_numbers: a file's numbers replaced)."""

    def __init__(self, shaft=DEFAULT_SHAFT, modes=MODES_DEFAULT, floating=None):
        self.shaft = shaft if isinstance(shaft, ShaftFile) else read_shaft(shaft)
        self.set_floating(floating)
        K, M, G = full_matrices(self.shaft)
        sf = self.shaft
        interface = list(sf.seat_nodes) + ([sf.tip_node] if sf.tip_node not in sf.seat_nodes else [])
        boundary = np.array([beam.NDOF * node + i for node in interface for i in range(beam.NDOF)])
        self._T = craig_bampton(K, M, boundary, modes)
        self._K, self._M, self._G = (self._T.T @ A @ self._T for A in (K, M, G))
        self._Minv = np.linalg.inv(self._M)
        self._Ms = self._M - 1j * self._G  # the synchronous problem's mass (critical_speeds)
        self._Ms_inv = np.linalg.inv(self._Ms)
        self._Linv = np.linalg.inv(np.linalg.cholesky(self._M))  # M = L L^T: the undamped modes of _projected_speeds
        seat_dofs = [[beam.NDOF * k + i for i in range(beam.NDOF)] for k in range(len(sf.seat_nodes))]
        self._seat_dofs = np.array(seat_dofs, dtype=np.int64).reshape(-1, beam.NDOF)
        self._tip = beam.NDOF * interface.index(sf.tip_node)
        self._scale = float(np.max(np.abs(np.diag(self._Minv @ self._K))))
        self.n_dofs = self._K.shape[0]

    # --------------------------------------------------------------------------------------- inputs
    def _seat_matrices(self, name, value):
        n = len(self.shaft.seat_nodes)
        if value is None:
            return np.zeros((n, beam.NDOF, beam.NDOF))
        A = np.asarray(value, dtype=float)
        if A.shape != (n, beam.NDOF, beam.NDOF):
            raise ShaftInputError(f"{name}: shape {A.shape}, expected ({n}, 5, 5) (seats {self.shaft.seat_names})")
        for s, i, j in zip(*np.nonzero(~(np.abs(A) <= SEAT_MATRIX_MAX)), strict=True):
            raise ShaftInputError(
                f"{name}[{s}][{i},{j}] = {A[s, i, j]} is outside the allowed range [-{SEAT_MATRIX_MAX:g}, "
                f"{SEAT_MATRIX_MAX:g}] (seat '{self.shaft.seat_names[s]}')"
            )
        for s, i in zip(*np.nonzero(np.diagonal(A, axis1=1, axis2=2) < 0.0), strict=True):
            raise ShaftInputError(
                f"{name}[{s}][{i},{i}] = {A[s, i, i]} is outside the allowed range [0, {SEAT_MATRIX_MAX:g}] "
                f"(a diagonal entry; seat '{self.shaft.seat_names[s]}')"
            )
        return A

    def set_floating(self, floating):
        """Per seat whether its bearing's outer ring floats axially (booleans, one per seat; None: none floats)."""
        n = len(self.shaft.seat_nodes)
        flags = (False,) * n if floating is None else tuple(bool(f) for f in floating)
        if len(flags) != n:
            raise ShaftInputError(f"floating: {len(flags)} values, expected one per seat ({self.shaft.seat_names})")
        self.floating = flags

    def seat_frame(self, A):
        """Seat matrices (n_seats, 5, 5) from the bearings' frames into the shaft's: a bearing whose z axis points
        against the shaft's (bearing_axis = "-z") is the mirror image of one along it, and the mirror z -> -z turns
        (x, y, z, theta_x, theta_y) into (x, y, -z, -theta_x, -theta_y) (a rotation vector is a pseudovector), so
        its matrix becomes T A T with T = diag(1, 1, -1, -1, -1)."""
        t = self.seat_signs()
        return A * t[:, :, None] * t[:, None, :]

    def seat_signs(self):
        """Per seat the diagonal of T (n_seats, 5) of seat_frame: (1, 1, s, s, s), s = +1 for a bearing along the
        shaft's z, -1 against it. T is its own inverse: a seat vector T v is in the other frame."""
        t = np.ones((len(self.shaft.seat_axes), beam.NDOF))
        t[:, 2:] = np.array(self.shaft.seat_axes, dtype=float)[:, None]
        return t

    def seat_stiffness(self, K_seats):
        """The seats' stiffness in the shaft's frame (seat_frame) with each floating seat's axial freedom condensed
        out. A floating outer ring (preload by springs or an actuator: a constant axial force) is free in z, so
        the bearing in series with it carries no axial stiffness: with the ring's axial balance
        K_zj d_j - K_zz u = 0 eliminated, K' = K - K[:, z] K[z, :] / K_zz (row and column z become 0)."""
        K = self.seat_frame(self._seat_matrices("K_seats", K_seats))
        for s, floats in enumerate(self.floating):
            k = K[s]
            if floats and k[2, 2] > 0.0:
                K[s] = k - np.outer(k[:, 2], k[2, :]) / k[2, 2]
        return K

    def _check_omega(self, omega):
        omega = float(omega)
        if not 0.0 <= omega <= OMEGA_MAX:
            raise ShaftInputError(f"omega = {omega} rad/s is outside the allowed range [0, {OMEGA_MAX:g}]")
        return omega

    def matrices(self, K_seats, C_seats=None):
        """(K, C) of the reduced model with the seats' stiffness and damping added."""
        K = self._K.copy()
        C = np.zeros_like(K)
        beam.add_seats(self._seat_dofs, self.seat_stiffness(K_seats), K)
        beam.add_seats(self._seat_dofs, self.seat_frame(self._seat_matrices("C_seats", C_seats)), C)
        return K, C

    # ---------------------------------------------------------------------------------------- modes
    def _state_eig(self, K, D):
        """Eigenvalues and vectors of the first-order form of M q'' + D q' + K q = 0."""
        n = K.shape[0]
        A = np.zeros((2 * n, 2 * n), dtype=np.result_type(D, K))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -self._Minv @ K
        A[n:, n:] = -self._Minv @ D
        return np.linalg.eig(A)

    def _elastic(self, lam, V, K, count, spinning):
        """Indices (by rising Im lambda) of the first `count` elastic modes with Im lambda > 0, their whirl, and
        the number of rigid-body modes among the oscillating ones (a shape without strain energy: the free rotor's
        translation, tilt and gyroscopic nutation), which are not reported."""
        n = K.shape[0]
        order = np.argsort(lam.imag)
        order = order[lam.imag[order] > OSCILLATING * np.abs(lam[order])]  # each pair once; overdamped ones out
        Q = V[:n, order]
        strain = np.real(np.sum(Q.conj() * (K @ Q), axis=0))
        kinetic = np.real(np.sum(Q.conj() * (self._M @ Q), axis=0))
        elastic = strain >= RIGID_RATIO * self._scale * kinetic
        kept = order[elastic][:count]
        whirls = [int(w) for w in whirl_senses(self._T @ V[:n, kept])]
        whirls = [w if spinning or w == WHIRL_AXIAL else WHIRL_NONE for w in whirls]
        return kept, whirls, int(np.count_nonzero(~elastic))

    # -------------------------------------------------------------------------------------- outputs
    def evaluate(self, omega, K_seats, C_seats=None, critical_speeds=True):
        """Outputs at speed omega (rad/s) with the seats' 5x5 stiffness K_seats (N/m, N/rad, N.m/m, N.m/rad) and
        damping C_seats (N.s/m, ...; None: undamped), in the seat order of the shaft file:
        - frequencies (Hz): the first six damped natural frequencies Im(lambda) / 2 pi of the elastic modes,
          whirl: +1 forward, -1 backward, 0 none (at rest, or a planar shape), 2 axial;
          damping_ratios -Re(lambda) / |lambda|;
          NaN where the model has fewer elastic modes; rigid_modes: rigid-body modes passed over;
        - compliance_radial, compliance_axial (m/N): static x and z deflection of the tool tip under a unit
          force there (NaN without supports against that motion);
        - peak_compliance (m/N), peak_frequency (Hz): the largest |H_xx(omega)| of the tool tip's receptance and
          where it is, searched about each reported mode (inf for an undamped mode);
        - critical_speeds (rad/s): the first two synchronous forward critical speeds (critical_speeds())."""
        omega = self._check_omega(omega)
        K, C = self.matrices(K_seats, C_seats)
        with single_blas_thread():  # tens of unknowns: BLAS threads cost more than they bring
            return self._outputs(omega, K, C, critical_speeds)

    def _outputs(self, omega, K, C, critical_speeds):
        lam, V = self._state_eig(K, C + omega * self._G)
        kept, whirls, rigid = self._elastic(lam, V, K, N_FREQUENCIES, omega > 0.0)
        out = {
            "frequencies": np.full(N_FREQUENCIES, math.nan),
            "whirl": np.zeros(N_FREQUENCIES, dtype=int),
            "damping_ratios": np.full(N_FREQUENCIES, math.nan),
            "rigid_modes": rigid,
        }
        out["frequencies"][: len(kept)] = lam[kept].imag / (2.0 * math.pi)
        out["whirl"][: len(kept)] = whirls
        out["damping_ratios"][: len(kept)] = -lam[kept].real / np.abs(lam[kept])
        out["compliance_radial"], out["compliance_axial"] = self._static_compliance(K, rigid)
        out["peak_compliance"], out["peak_frequency"] = self._peak_receptance(lam, V, kept)
        if critical_speeds:
            out["critical_speeds"] = self._critical_speeds(K, C, 2)
        return out

    def _static_compliance(self, K, rigid):
        if rigid:
            return math.nan, math.nan
        try:
            F = np.zeros((K.shape[0], 2))
            F[self._tip, 0] = 1.0
            F[self._tip + 2, 1] = 1.0
            u = np.linalg.solve(K, F)
        except np.linalg.LinAlgError:
            return math.nan, math.nan
        return float(u[self._tip, 0]), float(u[self._tip + 2, 1])

    def receptance(self, lam, V, frequencies, residues=None):
        """Tool tip's H_xx (m/N, complex) at the frequencies (rad/s) from the state-space modes (lam, V):
        H(w) = sum_r V[tip, r] c_r / (i w - lambda_r), c = V^-1 (0, M^-1 e_tip) (residues: these products, if known)."""
        residues = self._residues(V) if residues is None else residues
        w = np.asarray(frequencies, dtype=float)
        # in real arithmetic, the sums over the modes as matrix products: r / (a + i b) = r (a - i b) / (a^2 + b^2)
        # with a = -Re lambda, b = w - Im lambda; half the time of the complex divisions on the peak's grid
        a = -lam.real
        b = w[:, None] - lam.imag[None, :]
        inverse = 1.0 / (b * b + (a * a)[None, :])
        b *= inverse
        real = inverse @ (residues.real * a) + b @ residues.imag
        imag = inverse @ (residues.imag * a) - b @ residues.real
        return real + 1j * imag

    def _residues(self, V):
        n = self._K.shape[0]
        b = np.zeros(2 * n)
        b[n:] = self._Minv[:, self._tip]
        return V[self._tip, :] * np.linalg.solve(V, b.astype(V.dtype))

    def _peak_receptance(self, lam, V, kept):
        """(largest |H_xx|, its frequency in Hz) over +-3 half-power widths of each reported mode the tool tip's x
        force excites, on a grid of 121 points per mode and then of 41 points over +-1 step about the best."""
        residues = self._residues(V)
        size = np.abs(residues)
        modes = [r for r in kept if size[r] > RESIDUE_FLOOR * size.max()]  # not axial, not whirling in y only
        if not modes:
            return math.nan, math.nan
        wd, sigma = lam[modes].imag, np.abs(lam[modes].real)
        if np.any(sigma <= 1e-12 * wd):
            r = int(np.argmax(sigma <= 1e-12 * wd))
            return math.inf, wd[r] / (2.0 * math.pi)
        grid = wd[:, None] + np.linspace(-3.0, 3.0, 121)[None, :] * sigma[:, None]
        for _ in range(2):
            H = np.abs(self.receptance(lam, V, grid.ravel(), residues)).reshape(grid.shape)
            best = np.argmax(H, axis=1)
            step = grid[:, 1] - grid[:, 0]
            centre = grid[np.arange(len(modes)), best]
            grid = centre[:, None] + np.linspace(-1.0, 1.0, 41)[None, :] * step[:, None]
        m = int(np.argmax(H[np.arange(len(modes)), best]))
        return float(H[m, best[m]]), float(centre[m] / (2.0 * math.pi))

    def critical_speeds(self, K_seats, C_seats=None, count=2):
        """The first `count` synchronous forward critical speeds (rad/s): speeds Omega at which a forward whirl
        frequency equals Omega. With Omega = omega and q ~ e^{lambda t}, lambda = i omega, the gyroscopic term
        Omega G q' is -i lambda^2 G q, so the critical speeds are the eigenvalues of the quadratic problem
        (lambda^2 (M - i G) + lambda C + K) q = 0 with Im lambda > 0 and a forward whirling shape: one complex
        eigen-solution instead of an iteration on the speed (Friswell et al. 2010, ch. 3 and 5: the synchronous
        critical speed map)."""
        K, C = self.matrices(K_seats, C_seats)
        with single_blas_thread():
            return self._critical_speeds(K, C, count)

    def _critical_speeds(self, K, C, count):
        """The first `count` forward critical speeds: from the projected problem when it can be trusted, else from the
        whole synchronous eigen-solution."""
        speeds = self._projected_speeds(K, C, count)
        return self._synchronous_speeds(K, C, count) if speeds is None else speeds

    def _synchronous_speeds(self, K, C, count):
        n = K.shape[0]
        A = np.zeros((2 * n, 2 * n), dtype=complex)
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -self._Ms_inv @ K
        A[n:, n:] = -self._Ms_inv @ C
        # the eigenvalues alone (half the time of eig with its 2n vectors); the shape of the few roots examined
        # comes from one inverse-iteration solve each
        lam = np.linalg.eigvals(A)
        speeds = []
        for r in np.argsort(lam.imag):
            # a critical speed whirls (Im lambda > |Re lambda|); a real root e^{lambda t} of a disk with I_p > I_d
            # is a divergence of the synchronous problem, not a speed
            if lam[r].imag <= abs(lam[r].real):
                continue
            q = self._null_vector(lam[r] ** 2 * self._Ms + lam[r] * C + K)
            if self._forward_elastic(K, q[:, None])[0]:
                speeds.append(lam[r].imag)
                if len(speeds) == count:
                    break
        return np.array(speeds + [math.nan] * (count - len(speeds)))

    def _forward_elastic(self, K, Q):
        """Per column of Q, shapes of the synchronous problem, whether it has strain energy (not rigid) and whirls
        forward."""
        strain = np.real(np.sum(Q.conj() * (K @ Q), axis=0))
        kinetic = np.real(np.sum(Q.conj() * (self._M @ Q), axis=0))
        return (strain >= RIGID_RATIO * self._scale * kinetic) & (whirl_senses(self._T @ Q) == WHIRL_FORWARD)

    def _projected_speeds(self, K, C, count):
        """The critical speeds from the synchronous problem projected on the lowest undamped modes of the seated
        shaft (K's symmetric part), each forward root refined on the whole model (_refine_root) so that it is the
        whole problem's root to rounding. The basis holds the modes up to SYNC_BAND times a target frequency, first
        that of mode 2 x count, then, while a root needed lies above the trusted band, that root's. None where the
        projection is not trusted: the basis would be the whole model, a refinement moves a root by more than
        SYNC_MOVE or does not converge, fewer than `count` speeds are found (seats damped so heavily that they pin
        the shaft are such a case)."""
        n = K.shape[0]
        w2, Y = np.linalg.eigh(self._Linv @ (0.5 * (K + K.T)) @ self._Linv.T)
        w = np.sqrt(np.abs(w2))
        target = w[min(2 * count, n) - 1]
        while True:
            m = int(np.searchsorted(w, SYNC_BAND * target, side="right"))
            if 2 * m >= n:
                return None  # no smaller than the whole problem
            speeds = self._speeds_on_basis(K, C, count, self._Linv.T @ Y[:, :m], w[m] / SYNC_BAND)
            if not isinstance(speeds, float):
                return speeds
            target = speeds

    def _speeds_on_basis(self, K, C, count, P, trusted):
        """The critical speeds of the synchronous problem projected on the mass-normalised basis P (P^T M P = I),
        refined; a float, the root's Im lambda, where a root needed lies above `trusted` (rad/s); None where the
        projection is not trusted (_projected_speeds)."""
        m = P.shape[1]
        A = np.zeros((2 * m, 2 * m), dtype=complex)
        A[:m, m:] = np.eye(m)
        Ms_inv = np.linalg.inv(np.eye(m) - 1j * (P.T @ self._G @ P))
        A[m:, :m] = -Ms_inv @ (P.T @ K @ P)
        A[m:, m:] = -Ms_inv @ (P.T @ C @ P)
        lam, V = np.linalg.eig(A)
        order = np.argsort(lam.imag)
        order = order[lam.imag[order] > np.abs(lam.real[order])]  # whirling roots (_synchronous_speeds)
        Q = P @ V[:m, order]
        wanted = np.flatnonzero(self._forward_elastic(K, Q))[:count]
        last = wanted[-1] if wanted.size == count else order.size - 1  # the roots examined
        above = np.flatnonzero(lam.imag[order[: last + 1]] > trusted)
        if above.size:
            return float(lam[order[above[0]]].imag)
        if wanted.size < count:
            return None
        roots = self._refine_roots(K, C, lam[order[wanted]], Q[:, wanted])
        return None if roots is None else roots.imag

    def _refine_roots(self, K, C, lam, Q):
        """Newton's method on (lambda^2 M_s + lambda C + K) q = 0 with u^H q = 1 (nonlinear inverse iteration,
        Ruhe 1973, SIAM J. Numer. Anal. 10, 674-689) from approximate roots lam and shapes (the columns of Q), all
        at once: the roots, or None when one does not converge in NEWTON_STEPS, moves by more than SYNC_MOVE, or
        its shape is not forward and elastic."""
        u = Q.conj() / np.sum(np.abs(Q) ** 2, axis=0)
        q, root = Q.T, lam.copy()  # one shape per row
        for _ in range(NEWTON_STEPS):
            r = root[:, None, None]
            x = np.linalg.solve(r * r * self._Ms + r * C + K, (2.0 * r * self._Ms + C) @ q[:, :, None])[:, :, 0]
            s = np.sum(u.T * x, axis=1)
            root, q = root - 1.0 / s, x / s[:, None]
            if np.all(np.abs(1.0 / s) <= NEWTON_TOLERANCE * np.abs(root)):
                moved = np.any(np.abs(root - lam) > SYNC_MOVE * np.abs(root))
                return None if moved or not np.all(self._forward_elastic(K, q.T)) else root
        return None

    @staticmethod
    def _null_vector(Q):
        """The shape q with Q q = 0 of a matrix Q singular to rounding (the quadratic problem at one of its roots):
        inverse iteration, two solves from a vector with every component (the root's error is rounding, so the
        solves grow q's share along the null direction by about 1e15 each)."""
        q = np.ones(Q.shape[0], dtype=complex)
        for _ in range(2):
            try:
                q = np.linalg.solve(Q, q)
            except np.linalg.LinAlgError:  # exactly singular: that column's unit vector is not enough; take the SVD
                return np.linalg.svd(Q)[2][-1].conj()
            q /= np.linalg.norm(q)
        return q
