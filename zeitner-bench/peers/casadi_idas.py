"""Peer: CasADi's IDAS (SUNDIALS, variable order BDF up to 5) on the index-1 formulation.

Differential states x = (q, v), algebraic z = lambda:
    q' = v,  v' = M^-1 (F - G^T lambda),  0 = G v' + b  (the acceleration-level constraint).
The position constraints are not enforced (index-1 drift); max_g reports how far they drift (the
largest |g| over 100 output times; 0 on the knife edge, whose only row is velocity-level).
Scenes: pendulum, steam_generator, andrews, knife_edge, spring_support; chain_64 and chain_256
(32 / 128 pendulums hung from the origin, released horizontally) and ladder_64 and ladder_256
(2x16 / 2x64 nodes, rods along both rails and as rungs, the ends pinned by 8 coordinate rows, 3
of all rows redundant), as in zeitner-bench/src/scaling/scenes.rs. On the ladders the multipliers
are not unique, and the lambda slot holds instead the N generalised constraint forces G^T lambda;
IDAS fails there (its Newton matrices are singular, see REDUNDANT below), printing FAIL.
On the chains and ladders a warm-up run over 1 CPU second is the only run and its time is
reported; otherwise cpu_seconds is the median of 5 runs after the warm-up.
Functions are CasADi SX expressions, evaluated in one of two modes:
    vm       CasADi's SX virtual machine (the default);
    codegen  the integrator's own JIT: CasADi generates C for the functions IDAS calls (the DAE
             residual daeF and its Jacobian jacF), gcc -O3 compiles them into a .so it loads.

Usage: python casadi_idas.py [vm|codegen] SCENE T_END RTOL [RTOL ...]
Prints once SETUP,<wall_seconds> (model and integrators built, in codegen mode including the C
generation and the gcc runs; not part of any row's cpu_seconds), then one line per tolerance:
    ROW,<setting>,<steps>,<cpu_seconds>,<max_g>,<q...>,<v...>,<lambda...>
or  FAIL,<setting>,<message>
"""
import math
import os
import re
import sys

import andrews_parameters as A
from ladder_geometry import ladder_span, sagging_ladder
import tempfile
import time

import casadi as ca
import numpy as np


def pendulum():
    m, L, g = 1.0, 1.0, 9.81
    q = ca.SX.sym("q", 2)
    v = ca.SX.sym("v", 2)
    t = ca.SX.sym("t")
    M = ca.diag(ca.SX([m, m]))
    F = ca.vertcat(0, -m * g)
    gq = ca.vertcat(q[0] ** 2 + q[1] ** 2 - L * L)
    return q, v, t, M, F, gq, [1.0, 0.0], [0.0, 0.0]


def steam_generator():
    m, J, grav, h1, h2, h3, d, p0, rise = 4.0e5, 1.5e7, 9.81, 4.0, 6.0, 8.0, 2.0e6, 1.0e6, 0.01
    q = ca.SX.sym("q", 3)
    v = ca.SX.sym("v", 3)
    t = ca.SX.sym("t")
    M = ca.diag(ca.SX([m, m, J]))
    P = p0 * ca.fmin(t / rise, 1.0)
    F = ca.vertcat(P - d * v[0], -m * grav, P * h1)
    gq = ca.vertcat(q[0] - h3 * q[2], q[0] ** 2 + (q[1] - h2) ** 2 - h2 * h2)
    return q, v, t, M, F, gq, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]


def andrews():
    m1, m2, m3, m4, m5, m6, m7 = A.M
    i1, i2, i3, i4, i5, i6, i7 = A.I
    xa, ya, xb, yb, xc, yc = A.XA, A.YA, A.XB, A.YB, A.XC, A.YC
    c0, l0, mom = A.C0, A.L0, A.MOM
    d, da, e, ea, rr, ra, ss = A.D, A.DA, A.E, A.EA, A.RR, A.RA, A.SS
    sa, sb, sc, sd, ta, tb, u = A.SA, A.SB, A.SC, A.SD, A.TA, A.TB, A.U
    ua, ub, zf, zt, fa = A.UA, A.UB, A.ZF, A.ZT, A.FA
    q = ca.SX.sym("q", 7)
    v = ca.SX.sym("v", 7)
    t = ca.SX.sym("t")
    be, th, ga, ph, de, om, ep = [q[i] for i in range(7)]
    bep, thp, gap, php, dep, omp, epp = [v[i] for i in range(7)]
    ee, zz = e - ea, zf - fa
    M = ca.SX.zeros(7, 7)
    M[0, 0] = m1 * ra**2 + m2 * (rr**2 - 2 * da * rr * ca.cos(th) + da**2) + i1 + i2
    M[0, 1] = M[1, 0] = m2 * (da**2 - da * rr * ca.cos(th)) + i2
    M[1, 1] = m2 * da**2 + i2
    M[2, 2] = m3 * (sa**2 + sb**2) + i3
    M[3, 3] = m4 * ee**2 + i4
    M[3, 4] = M[4, 3] = m4 * (ee**2 + zt * ee * ca.sin(ph)) + i4
    M[4, 4] = m4 * (zt**2 + 2 * zt * ee * ca.sin(ph) + ee**2) + m5 * (ta**2 + tb**2) + i4 + i5
    M[5, 5] = m6 * zz**2 + i6
    M[5, 6] = M[6, 5] = m6 * (zz**2 - u * zz * ca.sin(om)) + i6
    M[6, 6] = m6 * (zz**2 - 2 * u * zz * ca.sin(om) + u**2) + m7 * (ua**2 + ub**2) + i6 + i7
    xd = sd * ca.cos(ga) + sc * ca.sin(ga) + xb
    yd = sd * ca.sin(ga) - sc * ca.cos(ga) + yb
    ls = ca.sqrt((xd - xc) ** 2 + (yd - yc) ** 2)
    fs = -c0 * (ls - l0) / ls
    fx, fy = fs * (xd - xc), fs * (yd - yc)
    F = ca.vertcat(
        mom - m2 * da * rr * thp * (thp + 2 * bep) * ca.sin(th),
        m2 * da * rr * bep**2 * ca.sin(th),
        fx * (sc * ca.cos(ga) - sd * ca.sin(ga)) + fy * (sd * ca.cos(ga) + sc * ca.sin(ga)),
        m4 * zt * ee * dep**2 * ca.cos(ph),
        -m4 * zt * ee * php * (php + 2 * dep) * ca.cos(ph),
        -m6 * u * zz * epp**2 * ca.cos(om),
        m6 * u * zz * omp * (omp + 2 * epp) * ca.cos(om),
    )
    x = rr * ca.cos(be) - d * ca.cos(be + th)
    y = rr * ca.sin(be) - d * ca.sin(be + th)
    gq = ca.vertcat(
        x - ss * ca.sin(ga) - xb,
        y + ss * ca.cos(ga) - yb,
        x - e * ca.sin(ph + de) - zt * ca.cos(de) - xa,
        y + e * ca.cos(ph + de) - zt * ca.sin(de) - ya,
        x - zf * ca.cos(om + ep) - u * ca.sin(ep) - xa,
        y - zf * ca.sin(om + ep) + u * ca.cos(ep) - ya,
    )
    q0 = [-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
          0.222668390165885884674473185609, 0.487364979543842550225598953530,
          -0.222668390165885884674473185609, 1.23054744454982119249735015568]
    return q, v, t, M, F, gq, q0, [0.0] * 7


def spring_support():
    support, m, L, k, c, g = 1e-3, 1.0, 1.0, 1e7, 200.0, 9.81
    q = ca.SX.sym("q", 4)
    v = ca.SX.sym("v", 4)
    t = ca.SX.sym("t")
    M = ca.diag(ca.SX([support, support, m, m]))
    F = ca.vertcat(-k * q[0] - c * v[0], -k * q[1] - c * v[1] - support * g, 0, -m * g)
    gq = ca.vertcat((q[2] - q[0]) ** 2 + (q[3] - q[1]) ** 2 - L * L)
    ys = -support * g / k
    return q, v, t, M, F, gq, [0.0, ys, L, ys], [0.0] * 4


def knife_edge():
    m, J, g, alpha, omega = 2.0, 0.5, 9.81, 0.3, 2.0
    q = ca.SX.sym("q", 3)
    v = ca.SX.sym("v", 3)
    t = ca.SX.sym("t")
    M = ca.diag(ca.SX([m, m, J]))
    F = ca.vertcat(m * g * ca.sin(alpha), 0, 0)
    # A velocity-level row: the blade does not slide sideways.
    gv = ca.vertcat(-ca.sin(q[2]) * v[0] + ca.cos(q[2]) * v[1])
    return q, v, t, M, F, gv, [0.0, 0.0, 0.0], [0.0, 0.0, omega]


def chain(links):
    """scaling/scenes.rs's chain: m = l = 1, g = 9.81, from horizontal_chain() (x_i = i + 1) at rest."""
    def scene():
        m, L, g = 1.0, 1.0, 9.81
        n = 2 * links
        q = ca.SX.sym("q", n)
        v = ca.SX.sym("v", n)
        t = ca.SX.sym("t")
        M = ca.diag(ca.SX([m] * n))
        F = ca.vertcat(*[0 if i % 2 == 0 else -m * g for i in range(n)])
        x = [0, *[q[2 * i] for i in range(links)]]
        y = [0, *[q[2 * i + 1] for i in range(links)]]
        gq = ca.vertcat(*[(x[i + 1] - x[i]) ** 2 + (y[i + 1] - y[i]) ** 2 - L * L for i in range(links)])
        q0 = [float(i // 2 + 1) if i % 2 == 0 else 0.0 for i in range(n)]
        return q, v, t, M, F, gq, q0, [0.0] * n
    return scene


def ladder(nodes):
    """scaling/scenes.rs's ladder, rows in its order: m = l = 1, g = 9.81, span = ladder_span(nodes),
    from sagging_ladder() at rest."""
    def scene():
        m, L, g = 1.0, 1.0, 9.81
        span = ladder_span(nodes)
        n = 4 * nodes
        q = ca.SX.sym("q", n)
        v = ca.SX.sym("v", n)
        t = ca.SX.sym("t")
        M = ca.diag(ca.SX([m] * n))
        F = ca.vertcat(*[0 if i % 2 == 0 else -m * g for i in range(n)])

        def rod(a, b):  # points a and b, b_i = 2i, t_i = 2i + 1
            return (q[2 * b] - q[2 * a]) ** 2 + (q[2 * b + 1] - q[2 * a + 1]) ** 2 - L * L

        rows = [rod(2 * i + rail, 2 * i + 2 + rail) for i in range(nodes - 1) for rail in (0, 1)]
        rows += [rod(2 * i, 2 * i + 1) for i in range(nodes)]
        last = n - 4
        rows += [q[0], q[1], q[2], q[3] - L, q[last] - span, q[last + 1], q[last + 2] - span, q[last + 3] - L]
        return q, v, t, M, F, ca.vertcat(*rows), sagging_ladder(nodes), [0.0] * n
    return scene


SCENES = {"pendulum": pendulum, "steam_generator": steam_generator, "andrews": andrews,
          "spring_support": spring_support, "knife_edge": knife_edge,
          "chain_64": chain(32), "chain_256": chain(128), "ladder_64": ladder(16), "ladder_256": ladder(64)}
# Scenes whose rows constrain velocities, g(q, v) = 0, linear in v.
VELOCITY_ROWS = {"knife_edge"}
# Scenes whose runs take seconds: a warm-up over LONG_RUN CPU seconds is their only run.
LARGE = {"chain_64", "chain_256", "ladder_64", "ladder_256"}
LONG_RUN = 1.0
# Scenes with redundant rows, whose multipliers are not unique: their lambda slot holds instead
# the generalised constraint forces G^T lambda (N values).
# IDAS's Newton systems are solved by CasADi's default sparse QR. With redundant rows they are
# singular: it fails in IDACalcIC (IDA_NO_RECOVERY), as do CasADi's other direct solvers (csparse,
# lapacklu, mumps) and, without IDACalcIC, IDASolve (IDA_CONV_FAIL at t = 0). That failure is the
# result: CasADi's iterative least-squares solver lsqr does resolve them, but too slowly to use
# (ladder_64: 3 to 4 s a run at rtol 1e-4 to 1e-6, then at 1e-7 unfinished after 19 CPU minutes;
# ladder_256 at 1e-4 unfinished after 16).
REDUNDANT = {"ladder_64", "ladder_256"}


# Integrator options per mode. With "jit" the integrator generates one C file holding the
# functions it calls and compiles it with the "shell" plugin, here gcc -O3 (CasADi's default
# command line adds only -fPIC).
MODES = {
    "vm": {},
    "codegen": {"jit": True, "compiler": "shell",
                # The temporary directory removes the files; CasADi's own cleanup would run
                # after it and warn that they are gone.
                "jit_cleanup": False,
                "jit_options": {"compiler": "gcc", "flags": ["-O3"], "cleanup": False}},
}


def main():
    args = sys.argv[1:]
    mode = args.pop(0) if args[0] in MODES else "vm"
    scene, t_end, rtols = args[0], float(args[1]), [float(r) for r in args[2:]]
    if mode == "codegen":
        # The generated .c is written to the working directory: keep it and the .o/.so out of
        # the repository, in a directory removed at exit.
        work = tempfile.TemporaryDirectory(prefix="casadi_idas_")
        os.chdir(work.name)
    setup_start = time.perf_counter()
    q, v, t, M, F, gq, q0, v0 = SCENES[scene]()
    n, z = q.shape[0], gq.shape[0]
    lam = ca.SX.sym("lam", z)
    # G q'' + b = 0: the rows' second derivative, or the first of velocity rows (none of the
    # scenes' constraints depends on t).
    if scene in VELOCITY_ROWS:
        G = ca.jacobian(gq, v)
        b = ca.jacobian(gq, q) @ v
    else:
        G = ca.jacobian(gq, q)
        b = ca.jacobian(ca.mtimes(G, v), q) @ v
    acc = ca.solve(M, F - G.T @ lam)
    x = ca.vertcat(q, v)
    dae = {"x": x, "z": lam, "t": t, "ode": ca.vertcat(v, acc), "alg": G @ acc + b}
    # Consistent initial multipliers from the acceleration-level system; on the large scenes
    # solved numerically, the least-squares solution of least norm where redundant rows make it
    # singular.
    if scene in LARGE:
        system0 = ca.Function("system0", [q, v, t], [G @ ca.solve(M, G.T), G @ ca.solve(M, F) + b])
        A0, r0 = (x.full() for x in system0(q0, v0, 0.0))
        lam0 = np.linalg.lstsq(A0, r0, rcond=None)[0]
    else:
        lam0_fun = ca.Function("lam0", [q, v, t], [ca.solve(G @ ca.solve(M, G.T), G @ ca.solve(M, F) + b)])
        lam0 = lam0_fun(q0, v0, 0.0)
    # The reported multipliers: lambda, or on scenes with redundant rows G^T lambda.
    report_fun = ca.Function("report", [q, v, lam], [G.T @ lam if scene in REDUNDANT else lam])
    # max_g: the position rows' drift (velocity rows have none to report).
    g_fun = ca.Function("g", [q], [ca.SX.zeros(1) if scene in VELOCITY_ROWS else gq])
    grid = [t_end * k / 100.0 for k in range(1, 101)]
    # All integrators are built (and in codegen mode compiled, once per tolerance, since the
    # tolerances are integrator options) before any is timed, so SETUP stays out of the rows.
    integrators = {}
    for rtol in rtols:
        opts = {"abstol": rtol * 1e-2, "reltol": rtol, "max_num_steps": 10**7, "calc_ic": True, "suppress_algebraic": True}
        try:
            integrators[rtol] = ca.integrator("F", "idas", dae, 0.0, grid, {**opts, **MODES[mode]})
        except Exception as error:
            integrators[rtol] = error
    print(f"SETUP,{time.perf_counter() - setup_start:.6e}", flush=True)
    for rtol in rtols:
        setting = f"rtol={rtol:.0e}"
        try:
            integrator = integrators[rtol]
            if isinstance(integrator, Exception):
                raise integrator
            args = {"x0": ca.vertcat(*q0, *v0), "z0": lam0}
            start = time.process_time()
            result = integrator(**args)  # warm-up
            warm_up = time.process_time() - start
            times = [warm_up] if scene in LARGE and warm_up > LONG_RUN else []
            for _ in range(0 if times else 5):
                start = time.process_time()
                result = integrator(**args)
                times.append(time.process_time() - start)
            times.sort()
            xf = result["xf"].full()
            zf = result["zf"].full()
            max_g = max(float(ca.mmax(ca.fabs(g_fun(xf[:n, k])))) for k in range(xf.shape[1]))
            stats = integrator.stats()
            steps = stats.get("nsteps", stats.get("n_steps", 0))
            qe, ve = xf[:n, -1], xf[n:, -1]
            le = report_fun(qe, ve, zf[:, -1]).full().ravel()
            values = ",".join(f"{float(x):.17e}" for x in [*qe, *ve, *le])
            print(f"ROW,{setting},{int(steps)},{times[len(times) // 2]:.6e},{max_g:.6e},{values}", flush=True)
        except Exception as error:  # a peer that cannot reach an accuracy is a result
            # CasADi's error without the call chain's prefixes ("Error in Function::call for 'F'
            # [IdasInterface] at .../function.cpp:1655: ..."), which would fill the 200 characters.
            message = re.sub(r"Error in Function::call for '[^']*' \[\w+\] at \S+:\s+|\.\.\./casadi/\S+:\s+", "", str(error))
            if scene in REDUNDANT:
                message = f"redundant rows: {message}"
            message = message.replace("\n", " ").replace(",", ";")[:200]
            print(f"FAIL,{setting},{message}", flush=True)


if __name__ == "__main__":
    main()
