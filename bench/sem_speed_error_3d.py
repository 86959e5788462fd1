#!/usr/bin/env python3
"""The 3D series of the speed-against-error benchmark (issue 25): the plan of the runs and their
analysis (errors against a finer reference run, table, CSV rows, markdown). numpy only.

The problem: a vertical point force in an elastic whole space, the material and source of the
2D series (bench/sem_speed_error.py: rho 2000, vp 692.8, vs 400, Ricker f0 10 Hz, t0 0.12 s,
lambda_min = vs / (2.7638 f0) = 14.47 m). Whole space rather than half-space: its three planes of
symmetry leave one octant to mesh, and it has a closed-form solution (Aki & Richards 2002,
eq. 4.23, below) that measures the reference's own error. The octant [0, L]^3 with the force
F_z = 1e6 N x Ricker at the origin, where the model carries F / 8:
  x = 0 (left): u_x = 0 and y = 0 (front): u_y = 0, planes of mirror symmetry of a z force;
  z = 0 (bottom): u_x = u_y = 0, the plane of antisymmetry (u_z is even in z, u_x and u_y odd);
  x = L, y = L, z = L (right, back, top): absorbing (Lysmer dashpots).
Six receivers inside the octant at 2, 3 and 4 lambda_min from the source along two directions
(angles from the force's axis z and azimuth from x): "a" at 45 deg / 45 deg, where P and S carry
alike (their far fields go as cos and sin of that angle), "b" at 75 deg / 20 deg, mostly S.

Window and domain, as in 2D chosen so that no wave sent back by an absorbing side reaches a
receiver inside the window (the error is then the discretisation's alone). The window ends at
T = t0 + r_max / vs + 0.1 s = 0.365 s, when the S pulse has passed the farthest receivers (the
Ricker is below 1e-3 of its peak 0.1 s from t0). The first echo is a P wave leaving the source at
t = 0 (the Ricker there is 2e-5 of its peak) and reflected once by a side x_k = L: it travels
|R - 2 L e_k| to a receiver R; with L = 11 lambda_min = 159.2 m the earliest arrival, at receiver
b4 from the right side, is at 0.385 s > T (geometry() computes and checks every one; L = 10.5
lambda_min would let it in at 0.361 s).

Meshes: m x m x m hexahedra of degree p, m = round(n L / (p lambda_min)) for a target n of GLL
nodes per lambda_min (the receivers need not sit on nodes: stations are interpolated with the
element's basis, docs/spectral-elements.md). The reference is one run at a higher degree and a
finer mesh with the fourth-order integrator at a shortened step (REFERENCE below).

Error: relative L2 of the receivers' velocity traces, v_x, v_y and v_z of all six pooled,
sqrt(sum |v - v_ref|^2 / sum |v_ref|^2) over the station samples in [0, T] (every step), as
bench/sem_speed_error.py does in 2D; the reference run's record, sampled at its own (shorter)
step, is interpolated to the run's times by 4-point Lagrange cubics (a relative error of at most
(omega dt)^4 x 9 / 16 / 4!, 1.5e-7 at the top frequency for the reference's step 2.9e-4 s). The
closed form gives every run a second error, reported beside it, and the reference's own.

Usage (bench/cases/sem_speed_error.sh drives it):
  sem_speed_error_3d.py geometry          shell assignments: WHOLE (the runs' options but mesh,
                                          degree and integrator), REF_P, REF_M, REF_SAFETY
  sem_speed_error_3d.py plan              one line per run: p m (from the environment)
  sem_speed_error_3d.py analyse MANIFEST  lines: p m nx ny nz ranks log stations_dir mode
                                          (mode: reference, tuned, default or order4)
Environment: SEM_BENCH_3D_DEGREES (default "2 4"), SEM_BENCH_3D_PPW_<p> (target GLL nodes per
lambda_min), SEM_BENCH_3D_REF ("p m safety": the reference run), BENCH_CSV (rows appended),
SEM_BENCH_DOC (markdown file whose 3D results section is replaced).
"""
import math
import os
import re

import numpy as np

from speed_error_common import (fmt, machine_state, main, observed_orders, parse_log, pooled_error, read_csv, replace_section,
                                ricker_rate, times_at_targets)

# The material and the source's time function are the 2D series' (bench/sem_speed_error.py).
RHO, VP, VS = 2000.0, 692.820323, 400.0
F0, T0 = 10.0, 0.12
LAMBDA_MIN = VS / (2.7638 * F0)
FORCE = 1e6                               # the whole space's force [N]; the octant carries 1/8
LENGTH = 11                               # L in lambda_min
# Receivers: name, distance [lambda_min], angle from z [deg], azimuth from x [deg].
RECEIVERS = [(f"{d}{r}", r, theta, phi) for d, theta, phi in (("a", 45.0, 45.0), ("b", 75.0, 20.0)) for r in (2, 3, 4)]
T_END = T0 + max(r for _, r, _, _ in RECEIVERS) * LAMBDA_MIN / VS + 0.1
COMPONENTS = ("v_x", "v_y", "v_z")

# The reference: degree, elements per side, fraction of the fourth order's stable step:
# degree 8 at 10 elements per side (7.3 GLL nodes per lambda_min) and 0.45 of the limit, half the
# default step (there the time error (omega dt)^4 / 720 is 1.4e-7 at the top frequency). Its
# error against the closed form was 4.2e-5 at 0.9 of the limit (measured at commit, 78 s).
REFERENCE = (8, 10, 0.45)
# Default series, target GLL nodes per lambda_min: from the coarsest meshes, whose error is the
# elements' (p = 4 at 2.9 nodes: 6.2 % in every mode), to below 0.1 % at p = 4 (0.03 % at 8 nodes,
# fourth order). p = 2 at 8 nodes (2.1 M DOFs, ~30 s a mode) stops short of 0.1 %: its time there
# is extrapolated (10 nodes would be 4.1 M DOFs, ~1.5 min a mode).
DEFAULT_PPW = {2: [4, 5, 6, 8], 4: [3, 4, 5, 6, 8]}


def receiver_positions():
    out = []
    for _, r, theta, phi in RECEIVERS:
        th, ph = math.radians(theta), math.radians(phi)
        out.append(r * LAMBDA_MIN * np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)]))
    return out


def first_echo():
    """Earliest arrival at any receiver of a P wave that left the source at t = 0 and was
    reflected once by a side x_k = L (the path from its mirror image 2 L e_k): (time, receiver, k)."""
    length = LENGTH * LAMBDA_MIN
    return min((np.linalg.norm(pos - 2 * length * np.eye(3)[k]) / VP, name, k)
               for (name, _, _, _), pos in zip(RECEIVERS, receiver_positions()) for k in range(3))


def reference_run():
    env = os.environ.get("SEM_BENCH_3D_REF")
    if env:
        p, m, safety = env.split()
        return int(p), int(m), float(safety)
    return REFERENCE


def geometry():
    echo, name, k = first_echo()
    # The margin quoted in the module docstring, checked so a change of the constants cannot let
    # an echo into the window.
    assert echo > T_END, f"the echo from side {k} reaches {name} at {echo:.3f} s, inside the window (T = {T_END:.3f} s)"
    length = LENGTH * LAMBDA_MIN
    coords = ",".join(",".join(f"{c:.10g}" for c in pos) for pos in receiver_positions())
    names = ",".join(name for name, _, _, _ in RECEIVERS)
    # The source sits on the corner node (0, 0, 0) at every mesh.
    print(f"WHOLE='-mesh_dim 3 -mesh_box_upper {length:.10g},{length:.10g},{length:.10g} -regions rock -material_rock_rho {RHO:.10g}"
          f" -material_rock_vp {VP:.10g} -material_rock_vs {VS:.10g}"
          f" -bc_left_type fixed -bc_left_components x -bc_front_type fixed -bc_front_components y -bc_bottom_type fixed -bc_bottom_components x,y"
          f" -bc_right_type absorbing -bc_back_type absorbing -bc_top_type absorbing"
          f" -point_forces src -point_force_src_location 0,0,0 -point_force_src_force 0,0,{FORCE / 8:.10g} -point_force_src_stf ricker"
          f" -point_force_src_f0 {F0:.10g} -point_force_src_t0 {T0:.10g} -ts_max_time {T_END:.10g} -output_fields 0 -progress_interval 1000"
          f" -station_interval 0 -station_coordinates {coords} -station_names {names}'")
    p, m, safety = reference_run()
    print(f"REF_P={p} REF_M={m} REF_SAFETY={safety:.10g}")


def series(p):
    env = os.environ.get(f"SEM_BENCH_3D_PPW_{p}")
    ppw = [float(v) for v in env.split()] if env else DEFAULT_PPW.get(p, [4, 6, 8])
    # m elements along L: nodes per lambda_min = p m / L.
    return sorted({max(1, round(v * LENGTH / p)) for v in ppw})


def plan():
    for p in [int(v) for v in os.environ.get("SEM_BENCH_3D_DEGREES", "2 4").split()]:
        for m in series(p):
            print(p, m)


def exact_velocity(pos, t):
    """Velocity (3 x len(t)) at pos of the whole space under the force FORCE e_z x Ricker at the
    origin: Aki & Richards (2002) eq. 4.23 (near field, far P, far S) with the load's rate in
    place of the load. The near-field integral of tau X(t - tau) over [r/vp, r/vs] by 64-point
    Gauss-Legendre (its integrand is smooth: exact to round-off at this band)."""
    r = np.linalg.norm(pos)
    g = pos / r
    xg, wg = np.polynomial.legendre.leggauss(64)
    a, b = r / VP, r / VS
    tau = 0.5 * (b - a) * xg + 0.5 * (b + a)
    near = (0.5 * (b - a) * wg * tau) @ ricker_rate(t[None, :] - tau[:, None], F0, T0)
    c = 1 / (4 * np.pi * RHO)
    out = np.empty((3, len(t)))
    for i in range(3):
        gg, delta = g[i] * g[2], float(i == 2)
        out[i] = FORCE * c * ((3 * gg - delta) / r ** 3 * near + gg / (VP ** 2 * r) * ricker_rate(t - a, F0, T0)
                              - (gg - delta) / (VS ** 2 * r) * ricker_rate(t - b, F0, T0))
    return out


def lagrange_cubic(t_grid, values, t):
    """values (on the uniform grid t_grid) at times t by 4-point Lagrange interpolation."""
    dt = t_grid[1] - t_grid[0]
    assert np.allclose(np.diff(t_grid), dt, rtol=1e-6, atol=0), "the reference's samples are not uniform"
    s = (t - t_grid[0]) / dt
    j = np.clip(np.floor(s).astype(int) - 1, 0, len(t_grid) - 4)   # nodes j .. j + 3 around t
    x = s - j                                                     # in [1, 2] inside
    w = (-(x - 1) * (x - 2) * (x - 3) / 6, x * (x - 2) * (x - 3) / 2, -x * (x - 1) * (x - 3) / 2, x * (x - 1) * (x - 2) / 6)
    return sum(wk * values[j + k] for k, wk in enumerate(w))


def read_reference(stations_dir):
    names = [name for name, _, _, _ in RECEIVERS]
    records = [read_csv(os.path.join(stations_dir, f"{name}.csv")) for name in names]
    return lambda i, c, t: lagrange_cubic(records[i]["t"], records[i][c], t)


def exact_reference():
    positions = receiver_positions()
    index = {c: k for k, c in enumerate(COMPONENTS)}
    return lambda i, c, t: exact_velocity(positions[i], t)[index[c]]


def analyse(manifest):
    names = [name for name, _, _, _ in RECEIVERS]
    runs, ref = [], None
    for line in open(manifest):
        if not line.strip():
            continue
        p, m, nx, ny, nz, ranks, log, stations, mode = line.split()
        p, m, ranks = int(p), int(m), int(ranks)
        steps, loop, nodes, order = parse_log(log)
        dofs = 3 * (m * p + 1) ** 3
        if nodes is not None and 3 * nodes != dofs:
            print(f"warning: {log}: the run report says {nodes} nodes, (m p + 1)^3 = {dofs // 3}")
        err_exact, _ = pooled_error(stations, names, COMPONENTS, exact_reference(), T_END)
        run = dict(p=p, m=m, ranks=ranks, ppw=p * m / LENGTH, dofs=dofs, steps=steps, loop=loop, mode=mode, order=order,
                   log=log, stations=stations, err_exact=err_exact, rate=dofs * steps / loop / ranks)
        if mode == "reference":
            ref = run
        else:
            runs.append(run)
    assert ref is not None, f"{manifest}: no reference run"
    reference = read_reference(ref["stations"])
    for r in runs:
        r["err"], per_receiver = pooled_error(r["stations"], names, COMPONENTS, reference, T_END)
        r["err_far"] = max(per_receiver[names.index("a4")], per_receiver[names.index("b4")])
    runs.sort(key=lambda r: (r["p"], r["mode"], r["m"]))
    observed_orders(runs, "m")

    label = lambda r: f"{r['mode']}, order {r['order']}"
    table = ("| p | integrator | elements | GLL nodes per lambda_min | DOFs | steps | time loop [s] | error | error, receivers at 4 lambda_min | observed order | error against the closed form | M DOF-updates/s/core |\n"
             "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
    table += "".join(
        f"| {r['p']} | {label(r)} | {r['m']}³ | {r['ppw']:.3g} | {r['dofs']} | {r['steps']} | {r['loop']:.3g} | {100 * r['err']:.3g} % | {100 * r['err_far']:.3g} % | "
        f"{fmt(r['observed'], '.2f', '')} | {100 * r['err_exact']:.3g} % | {r['rate'] / 1e6:.1f} |\n" for r in runs)
    step = re.search(r"time step ([0-9.eE+-]+) s = ([0-9.]+) of the limit", open(ref["log"]).read())
    ref_line = (f"Reference: degree {ref['p']}, {ref['m']}³ elements ({ref['ppw']:.3g} GLL nodes per lambda_min, {ref['dofs']} DOFs), "
                f"order {ref['order']}, step {step.group(1)} s ({step.group(2)} of the stable limit), {ref['steps']} steps, time loop {ref['loop']:.3g} s; "
                f"its error against the closed form: {100 * ref['err_exact']:.3g} %.\n")
    # The series order4: the explicit -ts_cd_order 4 runs (made where the defaults chose central
    # differences) and the default runs that chose the fourth order.
    order4 = [dict(r, mode="order4") for r in runs if r["mode"] == "default" and r["order"] == 4] if any(r["mode"] == "order4" for r in runs) else []
    times = times_at_targets(runs + order4)
    lines = ("| p | integrator | time loop at 1 % error [s] | how | time loop at 0.1 % error [s] | how |\n"
             "|---:|---|---:|---|---:|---|\n")
    for key, t in times.items():
        orders = sorted({r["order"] for r in runs + order4 if (r["p"], r["mode"]) == key})
        (t1, how1), (t01, how01) = t[0.01], t[0.001]
        lines += f"| {key[0]} | {key[1]}, order {' and '.join(map(str, orders))} | {fmt(t1, '.3g')} | {how1 or 'not bracketed'} | {fmt(t01, '.3g')} | {how01 or 'not bracketed'} |\n"
    print(ref_line)
    print(table)
    print(lines)

    csv = os.environ.get("BENCH_CSV")
    if csv:
        with open(csv, "a") as out:
            for r in runs + [ref]:
                case = f"p{r['p']}_{r['m']}x{r['m']}x{r['m']}_{r['mode']}"
                metrics = [("degree", r["p"], "1"), ("integrator_order", r["order"], "1"), ("elements_per_side", r["m"], "1"),
                           ("gll_nodes_per_min_wavelength", r["ppw"], "1"), ("dofs", r["dofs"], "1"), ("steps", r["steps"], "1"),
                           ("time_loop_wall_time", r["loop"], "s"), ("l2_error_closed_form", r["err_exact"], "1"),
                           ("dof_updates_per_second_per_core", r["rate"], "1/s")]
                if r is not ref:
                    metrics += [("l2_error_velocity", r["err"], "1"), ("l2_error_farthest_receivers", r["err_far"], "1")]
                for metric, value, unit in metrics:
                    out.write(f"sem_speed_error_3d,{case},{metric},{value if isinstance(value, int) else format(value, '.4g')},{unit}\n")
            for key, t in times.items():
                for target, name in ((0.01, "1pct"), (0.001, "0p1pct")):
                    value, how = t[target]
                    if value is not None:
                        out.write(f"sem_speed_error_3d,p{key[0]}_{key[1]},time_loop_at_{name}_error_{how},{value:.4g},s\n")

    doc = os.environ.get("SEM_BENCH_DOC", os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "spectral-elements.md"))
    repeats = os.environ.get("SEM_BENCH_REPEATS", "1")
    section = (f"{BEGIN}\n### 3D results (last `bench/cases/sem_speed_error.sh` run with `SEM_BENCH_3D=1`)\n\n{machine_state()} "
               f"Time loop: the fastest of {repeats} run(s) per mesh and mode, {ref['ranks']} rank(s).\n\n"
               f"{ref_line}\n{table}\n{lines}{END}\n")
    replace_section(doc, BEGIN, END, section)
    print(f"3D table in {doc}")


BEGIN, END = "<!-- sem_speed_error_3d: begin (written by bench/sem_speed_error_3d.py) -->", "<!-- sem_speed_error_3d: end -->"


if __name__ == "__main__":
    main(__doc__, geometry, plan, analyse)
