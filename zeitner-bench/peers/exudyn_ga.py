"""Peer: Exudyn's implicit solvers with fixed steps, built from its native objects.

    generalized-alpha (index 3, spectral radius 0.9) -> method name given by --solver ga
    trapezoidal rule (index 2)                        -> --solver trapezoidal

Scenes:
    pendulum         a 2D mass point on a distance constraint;
    steam_generator  a 2D rigid body on a coordinate constraint q1 = h3 q3 and a distance
                     constraint about A, a coordinate damper, and the load through Python user
                     functions;
    knife_edge       a 2D rigid body (x, y, heading) on the incline, the blade's velocity-level
                     row -sin(th) x' + cos(th) y' = 0 as a velocityLevel coordinate-vector
                     constraint whose equation and Jacobian (d/dq') are Python user functions;
    spring_support   two mass points, the support held by a Cartesian spring-damper, the bob on a
                     distance constraint to it;
    chain_64, chain_256    32 / 128 mass points linked by distance constraints, the first to the
                     origin, released with every rod horizontal;
    ladder_64, ladder_256  2x16 / 2x64 mass points, distance constraints along both rails and as
                     every rung, the end nodes pinned by 8 coordinate constraints (3 rows
                     redundant), released from the sagging start. Exudyn resolves the redundant rows
                     as its solver hints advise: EigenDense with linearSolver.ignoreSingularJacobian
                     (Eigen's full-pivoting LU). Their sparse LU is used on the chains.
Andrews' mechanism is not modelled.

The multipliers are converted to this project's convention M q'' = F - G^T lambda (Exudyn's is
the same, M q'' + C_q^T lambda = f, but some of its rows are scaled differently):
Exudyn's distance constraint is |p - p0| - L = 0, ours |p - p0|^2 - L^2 = 0, so lambda = force / (2 L);
its coordinate constraint multiplies the second marker's value by factor1 and subtracts the
first, h3 q3 - q1 = 0, the negative of our g1 = q1 - h3 q3, so lambda1 = -force; the knife
edge's row is ours, lambda = force. On the ladders, whose redundant rows' multipliers are not
unique, the lambda slot holds instead the 4*nodes generalised constraint forces G^T lambda
(unique, and the same in either scaling). max_g is max |g(q)| over the position rows at the end
(none on the knife edge: 0).

Usage: python exudyn_ga.py SOLVER SCENE T_END STEPS [STEPS ...]
Prints once SETUP,<wall_seconds> (the first model built and assembled), then per step count
    ROW,<setting>,<steps>,<cpu_seconds>,<max_g>,<q...>,<v...>,<lambda...>
or  FAIL,<setting>,<message>
cpu_seconds is SolveDynamic's CPU time, the median of 5 runs after a warm-up; on the chains and
ladders a warm-up over 1 s is the only run and its time is reported.
"""
import math
import sys

from ladder_geometry import ladder_span, sagging_ladder
import time

import numpy as np

import exudyn as exu
from exudyn.itemInterface import (
    DistanceConstraint,
    LoadForceVector,
    LoadTorqueVector,
    MarkerBodyPosition,
    MarkerBodyRigid,
    MarkerNodeCoordinate,
    MarkerNodeCoordinates,
    MarkerNodePosition,
    MassPoint2D,
    NodePoint2D,
    NodeRigidBody2D,
    ObjectConnectorCartesianSpringDamper,
    ObjectConnectorCoordinate,
    ObjectConnectorCoordinateSpringDamper,
    ObjectConnectorCoordinateVector,
    ObjectGround,
    ObjectRigidBody2D,
    NodePointGround,
)


def scalar(value):
    return float(value) if not hasattr(value, "__len__") else float(value[0])


def pendulum(mbs):
    m, L, g = 1.0, 1.0, 9.81
    node = mbs.AddNode(NodePoint2D(referenceCoordinates=[L, 0.0]))
    mbs.AddObject(MassPoint2D(mass=m, nodeNumber=node))
    marker = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
    ground = mbs.AddObject(ObjectGround())
    anchor = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
    rod = mbs.AddObject(DistanceConstraint(markerNumbers=[anchor, marker], distance=L))
    mbs.AddLoad(LoadForceVector(markerNumber=marker, loadVector=[0.0, -m * g, 0.0]))

    def state():
        q = list(mbs.GetNodeOutput(node, exu.OutputVariableType.Position)[:2])
        v = list(mbs.GetNodeOutput(node, exu.OutputVariableType.Velocity)[:2])
        tension = scalar(mbs.GetObjectOutput(rod, exu.OutputVariableType.Force))
        return q, v, [tension / (2.0 * L)]

    def residual(q):
        return [q[0] ** 2 + q[1] ** 2 - L * L]

    return state, residual


def steam_generator(mbs):
    m, J, grav, h1, h2, h3, d, p0, rise = 4.0e5, 1.5e7, 9.81, 4.0, 6.0, 8.0, 2.0e6, 1.0e6, 0.01
    node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0.0, 0.0, 0.0]))
    body = mbs.AddObject(ObjectRigidBody2D(mass=m, inertia=J, nodeNumber=node))
    centre = mbs.AddMarker(MarkerBodyPosition(bodyNumber=body, localPosition=[0.0, 0.0, 0.0]))
    frame = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0.0, 0.0, 0.0]))
    x = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=0))
    phi = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=2))
    ground = mbs.AddObject(ObjectGround())
    pivot = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0.0, h2, 0.0]))
    groundNode = mbs.AddNode(NodePointGround(referenceCoordinates=[0.0, 0.0, 0.0]))
    groundCoordinate = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=groundNode, coordinate=0))
    column = mbs.AddObject(DistanceConstraint(markerNumbers=[pivot, centre], distance=h2))
    strut = mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[x, phi], factor1=h3))
    mbs.AddObject(ObjectConnectorCoordinateSpringDamper(markerNumbers=[groundCoordinate, x], stiffness=0.0, damping=d))
    load = lambda mbs_, t, vector: [p0 * min(t / rise, 1.0), 0.0, 0.0]
    moment = lambda mbs_, t, vector: [0.0, 0.0, p0 * min(t / rise, 1.0) * h1]
    mbs.AddLoad(LoadForceVector(markerNumber=centre, loadVector=[0.0, 0.0, 0.0], loadVectorUserFunction=load))
    mbs.AddLoad(LoadForceVector(markerNumber=centre, loadVector=[0.0, -m * grav, 0.0]))
    mbs.AddLoad(LoadTorqueVector(markerNumber=frame, loadVector=[0.0, 0.0, 0.0], loadVectorUserFunction=moment))

    def state():
        c = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates)
        cv = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates_t)
        q, v = [float(c[i]) for i in range(3)], [float(cv[i]) for i in range(3)]
        f1 = scalar(mbs.GetObjectOutput(strut, exu.OutputVariableType.Force))
        f2 = scalar(mbs.GetObjectOutput(column, exu.OutputVariableType.Force))
        return q, v, [-f1, f2 / (2.0 * h2)]

    def residual(q):
        return [q[0] - h3 * q[2], q[0] ** 2 + (q[1] - h2) ** 2 - h2 * h2]

    return state, residual


def knife_edge(mbs):
    m, J, g, alpha, omega = 2.0, 0.5, 9.81, 0.3, 2.0
    node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0.0, 0.0, 0.0], initialVelocities=[0.0, 0.0, omega]))
    body = mbs.AddObject(ObjectRigidBody2D(mass=m, inertia=J, nodeNumber=node))
    centre = mbs.AddMarker(MarkerBodyPosition(bodyNumber=body, localPosition=[0.0, 0.0, 0.0]))
    mbs.AddLoad(LoadForceVector(markerNumber=centre, loadVector=[m * g * math.sin(alpha), 0.0, 0.0]))
    # A ground marker contributes no coordinates: the user functions see the body's (x, y, th).
    groundNode = mbs.AddNode(NodePointGround(referenceCoordinates=[0.0, 0.0, 0.0]))
    ground = mbs.AddMarker(MarkerNodeCoordinates(nodeNumber=groundNode))
    coordinates = mbs.AddMarker(MarkerNodeCoordinates(nodeNumber=node))

    def sideways(mbs_, t, item, q, q_t, velocity_level):
        return [-math.sin(q[2]) * q_t[0] + math.cos(q[2]) * q_t[1]]

    def jacobian(mbs_, t, item, q, q_t, velocity_level):  # d/dq' (Exudyn drops the q part)
        return np.array([[-math.sin(q[2]), math.cos(q[2]), 0.0]])

    blade = mbs.AddObject(ObjectConnectorCoordinateVector(
        markerNumbers=[ground, coordinates], scalingMarker0=np.zeros((1, 1)), velocityLevel=True,
        constraintUserFunction=sideways, jacobianUserFunction=jacobian))

    def state():
        c = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates)
        cv = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates_t)
        q, v = [float(c[i]) for i in range(3)], [float(cv[i]) for i in range(3)]
        return q, v, [scalar(mbs.GetObjectOutput(blade, exu.OutputVariableType.Force))]

    def residual(q):
        return []  # no position rows

    return state, residual


def spring_support(mbs):
    support, m, L, k, c, g = 1e-3, 1.0, 1.0, 1e7, 200.0, 9.81
    ys = -support * g / k
    ground = mbs.AddObject(ObjectGround())
    origin = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
    nodes, markers = [], []
    for mass, start in [(support, [0.0, ys]), (m, [L, ys])]:
        node = mbs.AddNode(NodePoint2D(referenceCoordinates=start))
        mbs.AddObject(MassPoint2D(mass=mass, nodeNumber=node))
        marker = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
        mbs.AddLoad(LoadForceVector(markerNumber=marker, loadVector=[0.0, -mass * g, 0.0]))
        nodes.append(node)
        markers.append(marker)
    mbs.AddObject(ObjectConnectorCartesianSpringDamper(markerNumbers=[origin, markers[0]],
                                                        stiffness=[k, k, 0.0], damping=[c, c, 0.0]))
    rod = mbs.AddObject(DistanceConstraint(markerNumbers=[markers[0], markers[1]], distance=L))

    def state():
        q, v = points(mbs, nodes)
        return q, v, [scalar(mbs.GetObjectOutput(rod, exu.OutputVariableType.Force)) / (2.0 * L)]

    def residual(q):
        return [(q[2] - q[0]) ** 2 + (q[3] - q[1]) ** 2 - L * L]

    return state, residual


def points(mbs, nodes):
    """The mass points' positions and velocities, (x1, y1, x2, y2, ...)."""
    q, v = [], []
    for node in nodes:
        q += [float(x) for x in mbs.GetNodeOutput(node, exu.OutputVariableType.Position)[:2]]
        v += [float(x) for x in mbs.GetNodeOutput(node, exu.OutputVariableType.Velocity)[:2]]
    return q, v


def chain(links):
    """scaling/scenes.rs's chain: m = l = 1, g = 9.81, from horizontal_chain() (x_i = i + 1) at rest."""
    m, L, g = 1.0, 1.0, 9.81

    def build(mbs):
        ground = mbs.AddObject(ObjectGround())
        previous = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
        nodes, rods = [], []
        for i in range(links):
            node = mbs.AddNode(NodePoint2D(referenceCoordinates=[i + 1.0, 0.0]))
            mbs.AddObject(MassPoint2D(mass=m, nodeNumber=node))
            marker = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
            mbs.AddLoad(LoadForceVector(markerNumber=marker, loadVector=[0.0, -m * g, 0.0]))
            rods.append(mbs.AddObject(DistanceConstraint(markerNumbers=[previous, marker], distance=L)))
            nodes.append(node)
            previous = marker

        def state():
            q, v = points(mbs, nodes)
            lam = [scalar(mbs.GetObjectOutput(rod, exu.OutputVariableType.Force)) / (2.0 * L) for rod in rods]
            return q, v, lam

        def residual(q):
            x = [0.0, *q[0::2]]
            y = [0.0, *q[1::2]]
            return [(x[i + 1] - x[i]) ** 2 + (y[i + 1] - y[i]) ** 2 - L * L for i in range(links)]

        return state, residual

    return build


def ladder_rows(nodes, span, L=1.0):
    """Ours, in scaling/scenes.rs's order: the rods (a, b) as point indices (b_i = 2i, t_i = 2i + 1),
    then the 8 pins as (coordinate index, position)."""
    rods = [(2 * i + rail, 2 * i + 2 + rail) for i in range(nodes - 1) for rail in (0, 1)]
    rods += [(2 * i, 2 * i + 1) for i in range(nodes)]
    last = 4 * nodes - 4
    pins = [(0, 0.0), (1, 0.0), (2, 0.0), (3, L), (last, span), (last + 1, 0.0), (last + 2, span), (last + 3, L)]
    return rods, pins


def ladder(nodes):
    """scaling/scenes.rs's ladder: m = l = 1, g = 9.81, span = ladder_span(nodes), from sagging_ladder() at rest."""
    m, L, g = 1.0, 1.0, 9.81
    span = ladder_span(nodes)
    q0 = sagging_ladder(nodes)
    rods, pins = ladder_rows(nodes, span, L)

    def build(mbs):
        groundNode = mbs.AddNode(NodePointGround(referenceCoordinates=[0.0, 0.0, 0.0]))
        groundCoordinate = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=groundNode, coordinate=0))
        points_, markers = [], []
        for p in range(2 * nodes):
            node = mbs.AddNode(NodePoint2D(referenceCoordinates=q0[2 * p: 2 * p + 2]))
            mbs.AddObject(MassPoint2D(mass=m, nodeNumber=node))
            marker = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
            mbs.AddLoad(LoadForceVector(markerNumber=marker, loadVector=[0.0, -m * g, 0.0]))
            points_.append(node)
            markers.append(marker)
        rod_objects = [mbs.AddObject(DistanceConstraint(markerNumbers=[markers[a], markers[b]], distance=L))
                       for a, b in rods]
        # A coordinate constraint acts on the node's displacement from its reference, the start,
        # where every pinned node already is: 1 * displacement - 0 = 0.
        pin_objects = []
        for index, _ in pins:
            coordinate = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=points_[index // 2], coordinate=index % 2))
            pin_objects.append(mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[groundCoordinate, coordinate])))

        def state():
            q, v = points(mbs, points_)
            # G^T lambda = sum over rows of Exudyn's C_q^T force (the same forces in either scaling):
            # a rod |p_b - p_a| - L pulls with force * (p_b - p_a) / |p_b - p_a| on b, the opposite on a.
            forces = [0.0] * (4 * nodes)
            for (a, b), rod in zip(rods, rod_objects):
                f = scalar(mbs.GetObjectOutput(rod, exu.OutputVariableType.Force))
                dx, dy = q[2 * b] - q[2 * a], q[2 * b + 1] - q[2 * a + 1]
                length = math.hypot(dx, dy)
                for axis, d in enumerate((dx, dy)):
                    forces[2 * b + axis] += f * d / length
                    forces[2 * a + axis] -= f * d / length
            for (index, _), pin in zip(pins, pin_objects):
                forces[index] += scalar(mbs.GetObjectOutput(pin, exu.OutputVariableType.Force))
            return q, v, forces

        def residual(q):
            g_rods = [(q[2 * b] - q[2 * a]) ** 2 + (q[2 * b + 1] - q[2 * a + 1]) ** 2 - L * L for a, b in rods]
            return g_rods + [q[index] - position for index, position in pins]

        return state, residual

    return build


SCENES = {"pendulum": pendulum, "steam_generator": steam_generator, "knife_edge": knife_edge,
          "spring_support": spring_support, "chain_64": chain(32), "chain_256": chain(128),
          "ladder_64": ladder(16), "ladder_256": ladder(64)}
# Scenes whose runs take seconds: a warm-up over LONG_RUN CPU seconds is their only run.
LARGE = {"chain_64", "chain_256", "ladder_64", "ladder_256"}
LONG_RUN = 1.0


def linear_solver(scene, settings):
    if scene.startswith("ladder"):
        # Redundant rows: Eigen's full-pivoting LU, which resolves singular systems.
        settings.linearSolver.solverType = exu.LinearSolverType.EigenDense
        settings.linearSolver.ignoreSingularJacobian = True
    elif scene.startswith("chain"):
        settings.linearSolver.solverType = exu.LinearSolverType.EigenSparse


def build(scene):
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    state, residual = SCENES[scene](mbs)
    mbs.Assemble()
    return SC, mbs, state, residual


def main():
    solver, scene, t_end = sys.argv[1], sys.argv[2], float(sys.argv[3])
    steps_list = [int(float(s)) for s in sys.argv[4:]]
    setup_start = time.perf_counter()
    try:
        model = build(scene)  # the first run's
        print(f"SETUP,{time.perf_counter() - setup_start:.6e}", flush=True)
    except Exception:  # each setting will say why
        model = None
    for steps in steps_list:
        setting = f"steps={steps}"
        try:
            times = []
            for repeat in range(6):
                SC, mbs, state, residual = model or build(scene)
                model = None
                settings = exu.SimulationSettings()
                settings.timeIntegration.endTime = t_end
                settings.timeIntegration.numberOfSteps = steps
                settings.timeIntegration.verboseMode = 0
                settings.timeIntegration.newton.relativeTolerance = 1e-12
                settings.timeIntegration.newton.absoluteTolerance = 1e-12
                settings.solution.file.write = False
                settings.show.statistics = False
                linear_solver(scene, settings)
                if solver == "ga":
                    settings.timeIntegration.generalizedAlpha.spectralRadius = 0.9
                    solver_type = exu.DynamicSolverType.GeneralizedAlpha
                else:
                    solver_type = exu.DynamicSolverType.TrapezoidalIndex2
                start = time.process_time()
                ok = exu.SolveDynamic(mbs, settings, solverType=solver_type)
                elapsed = time.process_time() - start
                if not ok:
                    raise RuntimeError("SolveDynamic returned false")
                if repeat > 0:  # the first run is the warm-up
                    times.append(elapsed)
                elif scene in LARGE and elapsed > LONG_RUN:
                    times.append(elapsed)
                    break
            q, v, lam = state()
            max_g = max((abs(x) for x in residual(q)), default=0.0)
            times.sort()
            values = ",".join(f"{float(x):.17e}" for x in [*q, *v, *lam])
            print(f"ROW,{setting},{steps},{times[len(times) // 2]:.6e},{max_g:.6e},{values}", flush=True)
        except Exception as error:
            message = str(error).replace("\n", " ").replace(",", ";")[:200]
            print(f"FAIL,{setting},{message}", flush=True)


if __name__ == "__main__":
    main()
