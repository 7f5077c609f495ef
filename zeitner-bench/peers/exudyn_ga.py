"""Peer: Exudyn's implicit solvers with fixed steps, built from its native objects.

    generalized-alpha (index 3, spectral radius 0.9) -> method name given by --solver ga
    trapezoidal rule (index 2)                        -> --solver trapezoidal

Scenes: the pendulum (a 2D mass point on a distance constraint) and the steam generator (a 2D
rigid body on a coordinate constraint q1 = h3 q3 and a distance constraint about A, a
coordinate damper, and the load through Python user functions). Andrews' mechanism is not
modelled. The multipliers are converted to this project's convention M q'' = F - G^T lambda:
Exudyn's distance constraint is |p - p0| - L = 0, ours |p - p0|^2 - L^2 = 0, so lambda = force / (2 L);
its coordinate constraint multiplies the second marker's value by factor1 and subtracts the
first, h3 q3 - q1 = 0, the negative of our g1 = q1 - h3 q3, so lambda1 = -force.

Usage: python exudyn_ga.py SOLVER SCENE T_END STEPS [STEPS ...]
Prints ROW,<setting>,<steps>,<cpu_seconds>,<max_g>,<q...>,<v...>,<lambda...> or FAIL,<setting>,<message>.
"""
import math
import sys
import time

import exudyn as exu
from exudyn.itemInterface import (
    DistanceConstraint,
    LoadForceVector,
    LoadTorqueVector,
    MarkerBodyPosition,
    MarkerBodyRigid,
    MarkerNodeCoordinate,
    MarkerNodePosition,
    MassPoint2D,
    NodePoint2D,
    NodeRigidBody2D,
    ObjectConnectorCoordinate,
    ObjectConnectorCoordinateSpringDamper,
    ObjectGround,
    ObjectRigidBody2D,
    NodePointGround,
)


def pendulum(mbs):
    m, L, g = 1.0, 1.0, 9.81
    node = mbs.AddNode(NodePoint2D(referenceCoordinates=[L, 0.0]))
    mbs.AddObject(MassPoint2D(physicsMass=m, nodeNumber=node))
    marker = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
    ground = mbs.AddObject(ObjectGround())
    anchor = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
    rod = mbs.AddObject(DistanceConstraint(markerNumbers=[anchor, marker], distance=L))
    mbs.AddLoad(LoadForceVector(markerNumber=marker, loadVector=[0.0, -m * g, 0.0]))

    def state():
        q = list(mbs.GetNodeOutput(node, exu.OutputVariableType.Position)[:2])
        v = list(mbs.GetNodeOutput(node, exu.OutputVariableType.Velocity)[:2])
        force = mbs.GetObjectOutput(rod, exu.OutputVariableType.Force)
        tension = float(force) if not hasattr(force, "__len__") else float(force[0])
        return q, v, [tension / (2.0 * L)]

    def residual(q):
        return [q[0] ** 2 + q[1] ** 2 - L * L]

    return state, residual


def steam_generator(mbs):
    m, J, grav, h1, h2, h3, d, p0, rise = 4.0e5, 1.5e7, 9.81, 4.0, 6.0, 8.0, 2.0e6, 1.0e6, 0.01
    node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0.0, 0.0, 0.0]))
    body = mbs.AddObject(ObjectRigidBody2D(physicsMass=m, inertia=J, nodeNumber=node))
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
        strut_force = mbs.GetObjectOutput(strut, exu.OutputVariableType.Force)
        column_force = mbs.GetObjectOutput(column, exu.OutputVariableType.Force)
        f1 = float(strut_force) if not hasattr(strut_force, "__len__") else float(strut_force[0])
        f2 = float(column_force) if not hasattr(column_force, "__len__") else float(column_force[0])
        return q, v, [-f1, f2 / (2.0 * h2)]

    def residual(q):
        return [q[0] - h3 * q[2], q[0] ** 2 + (q[1] - h2) ** 2 - h2 * h2]

    return state, residual


SCENES = {"pendulum": pendulum, "steam_generator": steam_generator}


def main():
    solver, scene, t_end = sys.argv[1], sys.argv[2], float(sys.argv[3])
    steps_list = [int(float(s)) for s in sys.argv[4:]]
    for steps in steps_list:
        setting = f"steps={steps}"
        try:
            times = []
            for repeat in range(6):
                SC = exu.SystemContainer()
                mbs = SC.AddSystem()
                state, residual = SCENES[scene](mbs)
                mbs.Assemble()
                settings = exu.SimulationSettings()
                settings.timeIntegration.endTime = t_end
                settings.timeIntegration.numberOfSteps = steps
                settings.timeIntegration.verboseMode = 0
                settings.timeIntegration.newton.relativeTolerance = 1e-12
                settings.timeIntegration.newton.absoluteTolerance = 1e-12
                settings.solutionSettings.writeSolutionToFile = False
                settings.displayStatistics = False
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
            q, v, lam = state()
            max_g = max(abs(x) for x in residual(q))
            times.sort()
            values = ",".join(f"{float(x):.17e}" for x in [*q, *v, *lam])
            print(f"ROW,{setting},{steps},{times[len(times) // 2]:.6e},{max_g:.6e},{values}", flush=True)
        except Exception as error:
            message = str(error).replace("\n", " ").replace(",", ";")[:200]
            print(f"FAIL,{setting},{message}", flush=True)


if __name__ == "__main__":
    main()
