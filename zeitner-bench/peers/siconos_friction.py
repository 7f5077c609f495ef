"""Peer: Siconos' event-capturing time stepping (Moreau-Jean) on two 2-D Coulomb friction scenes.

Run with the system Python that has Siconos 4.5 (siconos.kernel, siconos.numerics):
    /usr/bin/python3 siconos_friction.py SCENE T_END STEPS [STEPS ...]

The scheme, as Siconos' own examples set it up (BouncingBall and the like):
    LagrangianLinearTIDS(q0, v0, M) with the stiffness K and the external force FExt;
    LagrangianLinearTIR(C): the local coordinates y = C q, row 0 the normal gap, row 1 the tangent;
    NewtonImpactFrictionNSL(e_n = 0, e_t = 0, mu, 2) on one Interaction;
    MoreauJeanOSI(theta = 0.5): M (v1 - v0) + h K q_theta - h F_theta = C^T P1,
        q1 = q0 + h v_theta, v_theta = (1 - theta) v0 + theta v1, with the contact at velocity level
        (0 <= U_n1 perp P_n1 >= 0 and Coulomb's law on (U_t1, P_t1), one impulse P1 per step);
    FrictionContact(2, SICONOS_FRICTION_2D_NSGS): the one-step problem, a 2-D friction-contact
        problem; NSGS is what FrictionContact(2) picks by default. Its tolerance
        (SICONOS_DPARAM_TOL) is set to 1e-14 (default 1e-4) with at most 1000 sweeps
        (SICONOS_IPARAM_MAX_ITER), so the error is the scheme's, not the solver's: with one contact
        whose Delassus matrix is diagonal (C has orthonormal rows, M and K are diagonal) NSGS is
        exact in one sweep and reports a residual of 0 on every step;
    TimeStepping(nsds, TimeDiscretisation(STEPS, 0, T_END), osi, osnspb), advanced by
        computeOneStep() / nextStep() from Python. The Newton loop is left at Siconos' default
        (SICONOS_TS_NONLINEAR); the system and relation are linear, so it stops after 1 iteration.
theta = 0.5 is the MoreauJeanOSI constructor's default and the value in Siconos' examples;
Siconos' mechanics_run (3-D rigid bodies) defaults to 0.50001 for a touch of dissipation, which
these linear point-mass scenes do not need.

One setting departs from the defaults: the constraint activation threshold. Moreau-Jean takes a
contact into the step's problem when its predicted gap y + h/2 y' is <= threshold (0 by
default). On a persistent contact the gap is 0 only up to round-off, and a gap of +1e-18 drops it
for a step: the point then falls freely for that step (the incline at 10 steps sinks 0.085 m
into the plane and stays there, as the velocity-level law never restores positions). The
threshold (MoreauJeanOSI.setConstraintActivationThreshold, the constraint_activation_threshold of
Siconos' mechanics_run) is set to 1e-12 m, far above the round-off and far below anything the
scenes resolve (neither scene ever lifts off).

Scenes (SI units, a point mass, world x right, y up, g = 9.81 down):
    incline  m = 1 on a plane through the origin rising at 30 deg, mu = 0.3; q = (x, y) world,
             gap y cos(th) - x sin(th), tangent (cos th, sin th) (up the slope); starts at the
             origin moving up the slope at 2 m/s, stops, then slides down.
    belt     m = 1 on the floor y >= 0, a belt under it moving at vb = 0.3 in +x, a spring k = 50
             pulling to x = 0, mu = 0.4; starts at x = y = 0 riding the belt (vx = 0.3). Siconos'
             linear relation has only a constant offset, and a rheonomous relation
             (LagrangianRheonomousR) needs compiled C plugins for h(q, t) and its time derivative,
             so the contact is stated in the frame moving with the belt (inertial: constant
             speed): q = (u, y), u = x - vb t, C = [[0, 1], [1, 0]] so the tangential velocity is
             the slip u' = x' - vb. The spring -k x = -k u - k vb t becomes K = diag(k, 0) and
             FExt = (-k vb t, -m g). Before each step FExt is set to its value at t_k + theta h:
             Moreau-Jean weighs FExt(t_k) and FExt(t_k+1) by 1 - theta and theta, and a force
             affine in t gives exactly that (checked against a hand-written theta step to the
             last bit). x = u + vb t and vx = u' + vb are reported.

Reported: x, y, vx, vy (world) at T_END, then N and T: the last step's contact impulse P1 in the
local frame (inter.lambda_(1)) divided by h, N its normal part (>= 0), T its tangential part, the
friction on the block along the scene's tangent (up the slope; +x on the belt), printed as
Zeitner's multipliers of the gap's and the slip's rows (both of unit gradient): -N and -T. max_g = |gap(q)| at
the end. Siconos prints its solver warnings ("Non smooth solver warning") on the C++ stdout; the
integration runs with file descriptor 1 sent to a temporary file, and any such warning makes the
setting FAIL.

Prints once SETUP,<wall_seconds> (the first model built and its simulation initialised), then per
step count
    ROW,<setting>,<steps>,<cpu_seconds>,<max_g>,x,y,vx,vy,-N,-T
or  FAIL,<setting>,<message>
with setting the step count as given. cpu_seconds is the CPU time (time.process_time) of the
integration loop (each run builds a fresh model first, outside the timing): the median of 3 runs
after a warm-up, or the warm-up's time alone when it took over 1 s. OpenBLAS, which Siconos'
algebra calls, is held to one thread (OPENBLAS_NUM_THREADS=1 unless the caller sets it): its idle
workers otherwise spin and triple the process CPU time on these tiny systems.
"""
import ctypes
import math
import os
import sys
import tempfile
import time

# Siconos' dense algebra goes through OpenBLAS (the pthread build here). On these 2x2 systems its
# worker threads only spin: with them, process_time (which counts every thread) came out about 3x
# larger, mostly system time (1e5 incline steps: 1.29 s against 0.44 s). One thread, unless the
# caller says otherwise; it must be set before numpy or Siconos loads the library.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np

import siconos.kernel as sk
import siconos.numerics as sn

G = 9.81
THETA = 0.5
SOLVER_TOL = 1e-14
SOLVER_MAX_ITER = 1000
ACTIVATION_THRESHOLD = 1e-12
LONG_RUN = 1.0


class Scene:
    """A built model: the simulation, its dynamical system and interaction, and the per-step hook."""

    def __init__(self, ds, relation_rows, mu, t_end, steps):
        self.ds, self.t_end, self.steps = ds, t_end, steps
        self.h = t_end / steps
        self.C = np.array(relation_rows, dtype=float)
        self.inter = sk.Interaction(sk.NewtonImpactFrictionNSL(0.0, 0.0, mu, 2), sk.LagrangianLinearTIR(self.C))
        nsds = sk.NonSmoothDynamicalSystem(0.0, t_end)
        nsds.insertDynamicalSystem(ds)
        nsds.link(self.inter, ds)
        osi = sk.MoreauJeanOSI(THETA)
        osi.setConstraintActivationThreshold(ACTIVATION_THRESHOLD)
        osnspb = sk.FrictionContact(2, sn.SICONOS_FRICTION_2D_NSGS)
        options = osnspb.numericsSolverOptions()
        options.iparam[sn.SICONOS_IPARAM_MAX_ITER] = SOLVER_MAX_ITER
        options.dparam[sn.SICONOS_DPARAM_TOL] = SOLVER_TOL
        self.sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(steps, 0.0, t_end), osi, osnspb)
        self.sim.initialize()
        # Keep the Python wrappers alive with the simulation.
        self._keep = (nsds, osi, osnspb)

    def contact(self):
        """(N, T): the last step's local impulse over h."""
        p = self.inter.lambda_(1)
        return float(p[0]) / self.h, float(p[1]) / self.h


def incline(t_end, steps):
    m, mu, th = 1.0, 0.3, math.radians(30.0)
    c, s = math.cos(th), math.sin(th)
    ds = sk.LagrangianLinearTIDS([0.0, 0.0], [2.0 * c, 2.0 * s], np.diag([m, m]))
    ds.setFExtPtr(np.array([0.0, -m * G]))
    scene = Scene(ds, [[-s, c], [c, s]], mu, t_end, steps)

    def run():
        sim = scene.sim
        for i in range(steps):
            sim.computeOneStep()
            if i < steps - 1:
                sim.nextStep()

    def state():
        q, v = ds.q(), ds.velocity()
        x, y, vx, vy = float(q[0]), float(q[1]), float(v[0]), float(v[1])
        return [x, y, vx, vy], abs(y * c - x * s)

    return scene, run, state


def belt(t_end, steps):
    m, mu, k, vb = 1.0, 0.4, 50.0, 0.3
    # Belt frame: u = x - vb t, u' = x' - vb; starting on the belt, u = 0, u' = 0.
    ds = sk.LagrangianLinearTIDS([0.0, 0.0], [0.0, 0.0], np.diag([m, m]))
    ds.setKPtr(np.diag([k, 0.0]))
    ds.setFExtPtr(np.array([0.0, -m * G]))
    scene = Scene(ds, [[0.0, 1.0], [1.0, 0.0]], mu, t_end, steps)
    fext = ds.fExt()  # a view on Siconos' vector: writing it sets the force
    h = scene.h

    def run():
        sim = scene.sim
        for i in range(steps):
            # -k vb t at t_k + theta h: the theta-weighted mean of the step's ends.
            fext[0] = -k * vb * (t_end * i / steps + THETA * h)
            sim.computeOneStep()
            if i < steps - 1:
                sim.nextStep()

    def state():
        q, v = ds.q(), ds.velocity()
        u, y, du, vy = float(q[0]), float(q[1]), float(v[0]), float(v[1])
        return [u + vb * t_end, y, du + vb, vy], abs(y)

    return scene, run, state


SCENES = {"incline": incline, "belt": belt}


class CaptureFd1:
    """Sends file descriptor 1 (where Siconos' C++ prints its warnings) to a temporary file."""

    libc = ctypes.CDLL(None)

    def __enter__(self):
        sys.stdout.flush()
        self.libc.fflush(None)
        self.file = tempfile.TemporaryFile()
        self.saved = os.dup(1)
        os.dup2(self.file.fileno(), 1)
        return self

    def __exit__(self, *exc):
        self.libc.fflush(None)
        os.dup2(self.saved, 1)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read().decode(errors="replace")
        self.file.close()
        return False


def timed_run(scene_name, t_end, steps):
    """Builds a fresh model and integrates it; returns (cpu seconds, scene, state)."""
    scene, run, state = SCENES[scene_name](t_end, steps)
    with CaptureFd1() as captured:
        start = time.process_time()
        run()
        elapsed = time.process_time() - start
    if "warning" in captured.text.lower() or "error" in captured.text.lower():
        raise RuntimeError("Siconos: " + " ".join(captured.text.split())[:160])
    return elapsed, scene, state


def main():
    scene_name, t_end = sys.argv[1], float(sys.argv[2])
    settings = sys.argv[3:]
    if scene_name not in SCENES:
        raise SystemExit(f"unknown scene {scene_name}; one of {', '.join(SCENES)}")
    setup_start = time.perf_counter()
    SCENES[scene_name](t_end, int(float(settings[0])) if settings else 1)
    print(f"SETUP,{time.perf_counter() - setup_start:.17g}", flush=True)
    for setting in settings:
        try:
            steps = int(float(setting))
            if steps < 1:
                raise ValueError("steps must be >= 1")
            warm, scene, state = timed_run(scene_name, t_end, steps)
            if warm > LONG_RUN:
                cpu = warm
            else:
                times = []
                for _ in range(3):
                    elapsed, scene, state = timed_run(scene_name, t_end, steps)
                    times.append(elapsed)
                cpu = sorted(times)[1]
            values, max_g = state()
            normal, tangential = scene.contact()
            # In Zeitner's convention M q'' = F - G^T lambda, the rows of unit gradient: the
            # plane's push N along the normal is lambda_N = -N, the friction T along the tangent
            # lambda_T = -T.
            row = ",".join(f"{float(x):.17g}" for x in [*values, -normal, -tangential])
            print(f"ROW,{setting},{steps},{cpu:.17g},{max_g:.17g},{row}", flush=True)
        except Exception as error:
            message = str(error).replace("\n", " ").replace(",", ";")[:200]
            print(f"FAIL,{setting},{message}", flush=True)


if __name__ == "__main__":
    main()
