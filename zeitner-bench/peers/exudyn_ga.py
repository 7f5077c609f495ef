"""Peer: Exudyn's implicit solvers with fixed steps, built from its native objects.

    generalized-alpha (index 3, spectral radius 0.9) -> method name given by --solver ga
    trapezoidal rule (index 2)                        -> --solver trapezoidal

Scenes:
    pendulum         a 2D mass point on a distance constraint;
    steam_generator  a 2D rigid body on a coordinate constraint q1 = h3 q3 and a distance
                     constraint about A, a coordinate damper, and the load through Python user
                     functions;
    andrews          Andrews' squeezing mechanism: one generic ODE2 object on a 7-coordinate node,
                     the configuration-dependent mass matrix and the forces as Python user
                     functions, the 6 loop-closure rows as one position-level coordinate-vector
                     constraint whose equation and exact Jacobian dg/dq are Python user functions
                     (at velocity level, G q', when the index-2 solver asks);
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

The multipliers are converted to this project's convention M q'' = F - G^T lambda (Exudyn's is
the same, M q'' + C_q^T lambda = f, but some of its rows are scaled differently):
Exudyn's distance constraint is |p - p0| - L = 0, ours |p - p0|^2 - L^2 = 0, so lambda = force / (2 L);
its coordinate constraint multiplies the second marker's value by factor1 and subtracts the
first, h3 q3 - q1 = 0, the negative of our g1 = q1 - h3 q3, so lambda1 = -force; the knife
edge's and Andrews' rows are ours, lambda = force. On the ladders, whose redundant rows'
multipliers are not unique, the lambda slot holds instead the 4*nodes generalised constraint
forces G^T lambda (unique, and the same in either scaling). max_g is max |g(q)| over the
position rows at the end (none on the knife edge: 0).

Usage: python exudyn_ga.py SOLVER SCENE T_END STEPS [STEPS ...]
Prints once SETUP,<wall_seconds> (the first model built and assembled), then per step count
    ROW,<setting>,<steps>,<cpu_seconds>,<max_g>,<q...>,<v...>,<lambda...>
or  FAIL,<setting>,<message>
cpu_seconds is SolveDynamic's CPU time, the median of 5 runs after a warm-up; on the chains and
ladders a warm-up over 1 s is the only run and its time is reported.
"""
import math
import sys

import andrews_parameters as A
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
    NodeGenericODE2,
    NodePoint2D,
    NodeRigidBody2D,
    ObjectConnectorCartesianSpringDamper,
    ObjectConnectorCoordinate,
    ObjectConnectorCoordinateSpringDamper,
    ObjectConnectorCoordinateVector,
    ObjectGenericODE2,
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


class AndrewsModel:
    """Andrews' squeezing mechanism as in zeitner-scenes/src/andrews.rs (the test set's parameters):
    q = (beta, Theta, gamma, Phi, delta, Omega, epsilon), its mass matrix M(q), force f(q, q'),
    the 6 loop-closure rows g(q) and their Jacobian G = dg/dq."""
    m1, m2, m3, m4, m5, m6, m7 = A.M
    i1, i2, i3, i4, i5, i6, i7 = A.I
    xa, ya, xb, yb, xc, yc = A.XA, A.YA, A.XB, A.YB, A.XC, A.YC
    c0, l0, mom = A.C0, A.L0, A.MOM
    d, da, e, ea, rr, ra, ss = A.D, A.DA, A.E, A.EA, A.RR, A.RA, A.SS
    sa, sb, sc, sd, ta, tb, u = A.SA, A.SB, A.SC, A.SD, A.TA, A.TB, A.U
    ua, ub, zf, zt, fa = A.UA, A.UB, A.ZF, A.ZT, A.FA
    Q0 = [-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
          0.222668390165885884674473185609, 0.487364979543842550225598953530,
          -0.222668390165885884674473185609, 1.23054744454982119249735015568]

    def mass(self, q):
        m2, m4, m6, da, rr, zt, u = self.m2, self.m4, self.m6, self.da, self.rr, self.zt, self.u
        ee, zz = self.e - self.ea, self.zf - self.fa
        th, ph, om = q[1], q[3], q[5]
        M = np.zeros((7, 7))
        M[0, 0] = self.m1 * self.ra**2 + m2 * (rr**2 - 2 * da * rr * math.cos(th) + da**2) + self.i1 + self.i2
        M[0, 1] = M[1, 0] = m2 * (da**2 - da * rr * math.cos(th)) + self.i2
        M[1, 1] = m2 * da**2 + self.i2
        M[2, 2] = self.m3 * (self.sa**2 + self.sb**2) + self.i3
        M[3, 3] = m4 * ee**2 + self.i4
        M[3, 4] = M[4, 3] = m4 * (ee**2 + zt * ee * math.sin(ph)) + self.i4
        M[4, 4] = (m4 * (zt**2 + 2 * zt * ee * math.sin(ph) + ee**2) + self.m5 * (self.ta**2 + self.tb**2)
                   + self.i4 + self.i5)
        M[5, 5] = m6 * zz**2 + self.i6
        M[5, 6] = M[6, 5] = m6 * (zz**2 - u * zz * math.sin(om)) + self.i6
        M[6, 6] = (m6 * (zz**2 - 2 * u * zz * math.sin(om) + u**2) + self.m7 * (self.ua**2 + self.ub**2)
                   + self.i6 + self.i7)
        return M

    def force(self, q, v):
        sc, sd, ga, th, ph, om = self.sc, self.sd, q[2], q[1], q[3], q[5]
        ee, zz = self.e - self.ea, self.zf - self.fa
        xd = sd * math.cos(ga) + sc * math.sin(ga) + self.xb
        yd = sd * math.sin(ga) - sc * math.cos(ga) + self.yb
        ls = math.hypot(xd - self.xc, yd - self.yc)
        fs = -self.c0 * (ls - self.l0) / ls
        fx, fy = fs * (xd - self.xc), fs * (yd - self.yc)
        k2, k4, k6 = self.m2 * self.da * self.rr, self.m4 * self.zt * ee, self.m6 * self.u * zz
        return np.array([
            self.mom - k2 * v[1] * (v[1] + 2 * v[0]) * math.sin(th),
            k2 * v[0] ** 2 * math.sin(th),
            fx * (sc * math.cos(ga) - sd * math.sin(ga)) + fy * (sd * math.cos(ga) + sc * math.sin(ga)),
            k4 * v[4] ** 2 * math.cos(ph),
            -k4 * v[3] * (v[3] + 2 * v[4]) * math.cos(ph),
            -k6 * v[6] ** 2 * math.cos(om),
            k6 * v[5] * (v[5] + 2 * v[6]) * math.cos(om),
        ])

    def constraints(self, q):
        be, th, ga, ph, de, om, ep = q
        e, zt, zf, u = self.e, self.zt, self.zf, self.u
        x = self.rr * math.cos(be) - self.d * math.cos(be + th)
        y = self.rr * math.sin(be) - self.d * math.sin(be + th)
        return np.array([
            x - self.ss * math.sin(ga) - self.xb,
            y + self.ss * math.cos(ga) - self.yb,
            x - e * math.sin(ph + de) - zt * math.cos(de) - self.xa,
            y + e * math.cos(ph + de) - zt * math.sin(de) - self.ya,
            x - zf * math.cos(om + ep) - u * math.sin(ep) - self.xa,
            y - zf * math.sin(om + ep) + u * math.cos(ep) - self.ya,
        ])

    def jacobian(self, q):
        be, th, ga, ph, de, om, ep = q
        e, zt, zf, u = self.e, self.zt, self.zf, self.u
        s, c = self.d * math.sin(be + th), self.d * math.cos(be + th)
        x_be, x_th = -self.rr * math.sin(be) + s, s  # d/dbeta, d/dTheta of x and y above
        y_be, y_th = self.rr * math.cos(be) - c, -c
        sp, cp = e * math.sin(ph + de), e * math.cos(ph + de)
        so, co = zf * math.sin(om + ep), zf * math.cos(om + ep)
        G = np.zeros((6, 7))
        G[0::2, 0], G[0::2, 1], G[1::2, 0], G[1::2, 1] = x_be, x_th, y_be, y_th
        G[0, 2], G[1, 2] = -self.ss * math.cos(ga), -self.ss * math.sin(ga)
        G[2, 3], G[2, 4] = -cp, -cp + zt * math.sin(de)
        G[3, 3], G[3, 4] = -sp, -sp - zt * math.cos(de)
        G[4, 5], G[4, 6] = so, so - u * math.cos(ep)
        G[5, 5], G[5, 6] = -co, -co - u * math.sin(ep)
        return G


def andrews(mbs):
    """Andrews' squeezing mechanism: one ObjectGenericODE2 on a 7-coordinate node, its mass matrix
    and force as Python user functions, and the 6 loop-closure rows as one position-level
    coordinate-vector constraint with its exact Jacobian G."""
    model = AndrewsModel()
    # Reference 0, so displacements (what the ODE2 user functions see) are the angles themselves.
    node = mbs.AddNode(NodeGenericODE2(referenceCoordinates=[0.0] * 7, initialCoordinates=model.Q0,
                                       initialCoordinates_t=[0.0] * 7, numberOfODE2Coordinates=7))
    mbs.AddObject(ObjectGenericODE2(
        nodeNumbers=[node], massMatrix=model.mass(model.Q0),
        massMatrixUserFunction=lambda mbs_, t, item, q, q_t: model.mass(q),
        forceUserFunction=lambda mbs_, t, item, q, q_t: model.force(q, q_t)))
    groundNode = mbs.AddNode(NodePointGround(referenceCoordinates=[0.0, 0.0, 0.0]))
    ground = mbs.AddMarker(MarkerNodeCoordinates(nodeNumber=groundNode))
    coordinates = mbs.AddMarker(MarkerNodeCoordinates(nodeNumber=node))

    def loop(mbs_, t, item, q, q_t, velocity_level):
        # The index-2 solver asks for the velocity rows G q' (and for G as their d/dq').
        return model.jacobian(q) @ q_t if velocity_level else model.constraints(q)

    def jacobian(mbs_, t, item, q, q_t, velocity_level):
        return model.jacobian(q)

    closure = mbs.AddObject(ObjectConnectorCoordinateVector(
        markerNumbers=[ground, coordinates], scalingMarker0=np.zeros((6, 1)),
        constraintUserFunction=loop, jacobianUserFunction=jacobian))

    def state():
        c = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates)
        cv = mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates_t)
        q, v = [float(c[i]) for i in range(7)], [float(cv[i]) for i in range(7)]
        return q, v, [float(f) for f in mbs.GetObjectOutput(closure, exu.OutputVariableType.Force)]

    return state, lambda q: list(model.constraints(q))


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


SCENES = {"pendulum": pendulum, "steam_generator": steam_generator, "andrews": andrews,
          "knife_edge": knife_edge, "spring_support": spring_support, "chain_64": chain(32),
          "chain_256": chain(128), "ladder_64": ladder(16), "ladder_256": ladder(64)}
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
                # Fixed steps as named: by default a step whose Newton fails is silently split.
                settings.timeIntegration.adaptiveStep = False
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
