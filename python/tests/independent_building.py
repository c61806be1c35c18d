"""A shear building on a bilinear isolator, simulated in numpy from the equations alone.

The building-fit and building-diagnosis tests would otherwise fit data made by isolab's own
simulator, so a defect in isolab's building model (a mass in the wrong row, a damping matrix off
by a factor) would make the data and the fit wrong together and still agree. Nothing here reads
isolab's code: the model is written from the equations of motion and from what the docs state.

Units are isolab's kN, mm, s, so a mass is in kN s^2/mm (1 t = 1e-3 kN s^2/mm).

Degrees of freedom: 0 is the base slab, 1..n the floors, all displacements relative to the
ground. The equations of motion, with iota a vector of ones (every level moves with the ground):

    M u'' + C u' + K_stories u + e_0 f_iso(u_0) = -M iota a_g(t)
"""

import dataclasses
import pathlib

import numpy

TONNE = 1e-3  # kN s^2/mm
STANDARD_GRAVITY = 9806.65  # mm/s^2: the record's "units of g" (9.80665 m/s^2 by definition)


def read_peer_at2(path):
    """A PEER AT2 record: (dt in s, accelerations in g). Four header lines, the fourth giving
    NPTS and DT; then the samples, several to a line."""
    lines = pathlib.Path(path).read_text().splitlines()
    assert "UNITS OF G" in lines[2].upper(), f"{path}: expected a record in g"
    fields = lines[3].replace(",", " ").replace("=", " ").split()
    count = int(fields[fields.index("NPTS") + 1])
    dt = float(fields[fields.index("DT") + 1])
    samples = numpy.array(" ".join(lines[4:]).split(), dtype=float)
    assert samples.size == count, f"{path}: {samples.size} samples, its header says {count}"
    return dt, samples


@dataclasses.dataclass(frozen=True)
class BilinearIsolator:
    """BHM2 in its mathematical form (docs/models.md's table of laws): initial stiffness k0,
    post-yield stiffness k1, yield displacement uy, kinematic hardening. Written as a linear
    spring k1 in parallel with an elastic-perfectly-plastic element of stiffness k0 - k1 and
    strength (k0 - k1) uy: the hardening spring parallel to the slider, as docs/models.md says of
    BHM2 (and as its lead-rubber equivalence, fs = Qd = (k0 - k1) uy, implies).

    The slider's displacement s is the state. The elastoplastic element's elastic stretch is
    u - s, never beyond +-uy; its update to any end displacement is the projection of the trial
    stretch onto [-uy, uy], exact for any increment (the perfectly plastic element's return
    mapping in one dimension has no path dependence within a monotone increment)."""

    k0: float
    k1: float
    uy: float

    def branch(self, u, slider):
        """-1 or +1 on the plastic branch of that sign, 0 in the elastic range (affine pieces of
        the force as a function of u, for a fixed committed slider)."""
        stretch = u - slider
        return 0 if abs(stretch) < self.uy else (1 if stretch > 0 else -1)

    def update(self, u, slider):
        """(force, tangent, new slider) at displacement u from the committed slider."""
        stretch = numpy.clip(u - slider, -self.uy, self.uy)
        force = self.k1 * u + (self.k0 - self.k1) * stretch
        tangent = self.k0 if self.branch(u, slider) == 0 else self.k1
        return force, tangent, u - stretch


@dataclasses.dataclass(frozen=True)
class ShearBuilding:
    """A base slab on the isolator and linear stories above it, bottom up.

    damping_ratios: Rayleigh ratios at the first two modes, in isolab's sense: docs/models.md
    ("Superstructure damping is classical, built on the fixed-base superstructure's modes and
    acting on motion relative to the base, so it never damps the rigid-body motion on the
    isolators") and docs/bidirectional.md ("Rayleigh, a0 M + a1 K on the floors' motion relative
    to the base's rigid-body motion"). So M and K are the fixed-base superstructure's (floors
    only, story 1 clamped to the base), modes 1 and 2 are its fixed-base modes, and the matrix
    acts on the floors' velocities relative to the base's (rayleigh_damping below)."""

    base_mass: float
    story_masses: tuple
    story_stiffnesses: tuple
    damping_ratios: tuple
    isolator: BilinearIsolator

    @property
    def levels(self):
        return 1 + len(self.story_masses)

    def mass_matrix(self):
        return numpy.diag([self.base_mass, *self.story_masses])

    def story_stiffness_matrix(self):
        """The stories' stiffness on all levels: story k joins level k-1 and level k."""
        stiffness = numpy.zeros((self.levels, self.levels))
        for story, k in enumerate(self.story_stiffnesses, start=1):
            below, above = story - 1, story
            stiffness[below, below] += k
            stiffness[above, above] += k
            stiffness[below, above] -= k
            stiffness[above, below] -= k
        return stiffness

    def fixed_base_frequencies(self):
        """The superstructure's circular frequencies with the base held still, ascending."""
        stiffness = self.story_stiffness_matrix()[1:, 1:]  # the base row removed: clamped
        masses = numpy.array(self.story_masses)
        scaled = stiffness / numpy.sqrt(numpy.outer(masses, masses))  # M^-1/2 K M^-1/2
        return numpy.sqrt(numpy.linalg.eigvalsh(scaled))

    def rayleigh_coefficients(self):
        """(a0, a1) with zeta_i = a0 / (2 w_i) + a1 w_i / 2 at the first two fixed-base modes."""
        w1, w2 = self.fixed_base_frequencies()[:2]
        system = numpy.array([[1 / (2 * w1), w1 / 2], [1 / (2 * w2), w2 / 2]])
        return numpy.linalg.solve(system, numpy.array(self.damping_ratios, dtype=float))

    def rayleigh_damping(self):
        """C = T^T (a0 M_s + a1 K_s) T, T taking the levels' displacements to the floors' relative
        to the base (row i: floor i minus the base). The floors' damping forces act on relative
        velocities and the base takes their reaction, so a rigid-body velocity (all levels alike)
        is undamped."""
        a0, a1 = self.rayleigh_coefficients()
        superstructure = (a0 * numpy.diag(self.story_masses) +
                          a1 * self.story_stiffness_matrix()[1:, 1:])
        to_relative = numpy.hstack([-numpy.ones((self.levels - 1, 1)),
                                    numpy.eye(self.levels - 1)])
        return to_relative.T @ superstructure @ to_relative


def simulate(building, ground_acceleration, dt):
    """Newmark's average acceleration (beta 1/4, gamma 1/2) from rest under the ground
    acceleration sampled at dt (one analysis step a sample). Each step's equation is solved by
    Newton with the isolator's tangent; as the isolator force is piecewise linear in u_0, a
    Newton step taken on one affine piece lands on that piece's exact root, so the iteration
    stops, exact to round-off with no tolerance, when its new iterate lies on the piece it was
    linearised on. Returns the levels' displacement, velocity, relative and absolute
    acceleration histories (rows: samples; columns: base, floor 1, ...)."""
    mass = building.mass_matrix()
    damping = building.rayleigh_damping()
    stiffness = building.story_stiffness_matrix()
    iota = numpy.ones(building.levels)
    isolator = building.isolator
    samples, levels = len(ground_acceleration), building.levels
    u = numpy.zeros((samples, levels))
    v = numpy.zeros((samples, levels))
    a = numpy.zeros((samples, levels))
    a[0] = -iota * ground_acceleration[0]  # at rest: M a = -M iota a_g(0)
    slider = 0.0
    # The step equation's linear part in u_{n+1}: inertia, damping and stories together.
    linear_part = 4 / dt**2 * mass + 2 / dt * damping + stiffness
    for n in range(samples - 1):
        load = -mass @ iota * ground_acceleration[n + 1]
        # The inertia and damping forces' part known from step n, by the average acceleration's
        # a_{n+1} = 4/dt^2 (u - u_n) - 4/dt v_n - a_n and v_{n+1} = 2/dt (u - u_n) - v_n.
        history = (mass @ (4 / dt**2 * u[n] + 4 / dt * v[n] + a[n]) +
                   damping @ (2 / dt * u[n] + v[n]))
        trial = u[n].copy()
        for _ in range(50):
            force, tangent, _ = isolator.update(trial[0], slider)
            piece = isolator.branch(trial[0], slider)
            residual = linear_part @ trial - history - load
            residual[0] += force
            jacobian = linear_part.copy()
            jacobian[0, 0] += tangent
            trial = trial - numpy.linalg.solve(jacobian, residual)
            if isolator.branch(trial[0], slider) == piece:
                break
        else:
            raise RuntimeError(f"Newton found no consistent piece at step {n + 1}")
        _, _, slider = isolator.update(trial[0], slider)
        u[n + 1] = trial
        v[n + 1] = 2 / dt * (trial - u[n]) - v[n]
        a[n + 1] = 4 / dt**2 * (trial - u[n]) - 4 / dt * v[n] - a[n]
    return {"displacement": u, "velocity": v, "acceleration": a,
            "absolute_acceleration": a + ground_acceleration[:, None]}


def write_shake_table(path, time, ground_acceleration, response):
    """The shake-table CSV conftest.py's shake_table fixture writes (tests/cli's
    WriteShakeTable): time in s, the table's acceleration in m/s^2 and its displacement in m
    (zero: not used), then the levels roof first, accelerations in mm/s^2 named by brackets and
    displacements in metres named by their suffix."""
    levels = response["displacement"].shape[1]
    roof_first = range(levels - 1, -1, -1)
    columns = [time, ground_acceleration / 1000, numpy.zeros_like(time)]
    columns += [response["absolute_acceleration"][:, level] for level in roof_first]
    columns += [response["displacement"][:, level] / 1000 for level in roof_first]
    header = ("time_s,table_acceleration_m_s2,table_displacement_m," +
              ",".join(f"a{c} [mm/s^2]" for c in range(1, levels + 1)) + "," +
              ",".join(f"d{c}_m" for c in range(1, levels + 1)))
    numpy.savetxt(path, numpy.column_stack(columns), delimiter=",", header=header, comments="",
                  fmt="%.12g")
