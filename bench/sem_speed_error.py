#!/usr/bin/env python3
"""Speed against error of elements of degree p (issue 14's benchmark): the plan of the runs, and
their analysis (errors against the exact solution, table, CSV rows, markdown, PNG plot).

The problem: Lamb's line load on an elastic half-space (rho 2000, vp 692.8, vs 400: nu = 0.25),
a vertical load 1e5 N/m x Ricker (f0 10 Hz, t0 0.12 s) at the surface, as in
tests/cases/lamb_line_load.sh: half model, rollers on the symmetry plane x = 0 (which carries
half the load), absorbing right side and base. Six surface receivers at 8, 12, ..., 28 minimum
S wavelengths lambda_min = vs / (2.7638 f0) = 14.47 m (2.7638 f0: the Ricker's top
frequency, where its spectrum is 5 % of the peak; the issue's lambda_min 62.7 m comes from the
same definition). Every length is a multiple of 4 lambda_min, so with m elements per
4 lambda_min every receiver and every side falls on an element vertex at any degree.

Window and domain, chosen so that no wave reflected by an absorbing side reaches any receiver
before the window ends (the Lysmer dashpots are exact only at normal incidence; this makes the
error the discretisation's alone). The window ends at T = 1.33 s: the Rayleigh pulse reaches
the farthest receiver (405.2 m) at t0 + x / c_R = 0.12 + 1.102 = 1.222 s (c_R = 0.9194 vs) and
has passed it 0.11 s later (the Ricker is below 1e-3 of its peak 0.1 s from t0). The fastest
echo is a P wave leaving the source at t = 0 (the Ricker there is 2e-5 of its peak):
  right side at L = 48 lambda_min = 694.7 m: at the farthest receiver after
    (2 L - 405.2) / vp = 1.421 s > T;
  base at H = 32 lambda_min = 463.1 m: at the nearest receiver (115.8 m) after
    sqrt(115.8^2 + (2 H)^2) / vp = 1.347 s > T (the other receivers are farther from it).

Error: relative L2 of the surface velocity traces (v_x and v_y of all six receivers pooled:
sqrt(sum |v - v_ref|^2 / sum |v_ref|^2) over the station samples in [0, T]) against
tests/tools/lamb_line_load.py (frequency-wavenumber integral, validated there against Flamant
and the Rayleigh arrival). The reference velocity is the response to the load's time
derivative (exact, no numerical differentiation), on a 2.5e-4 s grid, interpolated to the
station times by a cubic spline.

Usage (bench/cases/sem_speed_error.sh drives it):
  sem_speed_error.py geometry            shell assignments: the domain, window and receivers
  sem_speed_error.py plan                one line per run: p m nx ny (from the environment)
  sem_speed_error.py analyse MANIFEST    MANIFEST lines: p m nx ny ranks log stations_dir [mode]
                                         (mode: tuned or default, bench/cases/sem_speed_error.sh)
Environment: SEM_BENCH_DEGREES (default "1 2 4 6"), SEM_BENCH_PPW_<p> (the refinement series
as target nodes per lambda_min counted in GLL nodes, p x lambda_min / h; each is rounded to
whole elements per 4 lambda_min), SEM_BENCH_FULL=1 (adds p = 1 meshes at 14 and 56 nodes per lambda_min, ~8 min more),
BENCH_CSV (rows appended there), SEM_BENCH_DOC (markdown file whose results section is
replaced; default docs/spectral-elements.md; the PNG goes next to it).
"""
import math
import os
import sys

import numpy as np

from speed_error_common import (ROOT, TARGETS, fmt, machine_state, main, observed_orders, parse_log, pooled_error, replace_section,  # noqa: F401
                                ricker_rate, times_at_targets)

sys.path.insert(0, os.path.join(ROOT, "tests", "tools"))
from lamb_line_load import ricker, surface_response  # noqa: E402

RHO, VP, VS = 2000.0, 692.820323, 400.0
F, F0, T0 = 1e5, 10.0, 0.12
LAMBDA_MIN = VS / (2.7638 * F0)
UNIT = 4 * LAMBDA_MIN                    # every length is a multiple of it (vertices at any degree)
LENGTH_UNITS, DEPTH_UNITS = 12, 8        # L = 48 lambda_min, H = 32 lambda_min
RECEIVERS = [8, 12, 16, 20, 24, 28]      # travel in lambda_min
T_END = 1.33
TARGET_ERROR = 0.01

# Default refinement series, target GLL nodes per lambda_min. Sized for ~10 min on one core of
# this machine when idle; p = 1 dominates (48 nodes per wavelength: 7.1 M DOFs, ~3900 steps,
# ~4-5 min alone) and needs it: its error is 1 % at ~44 (measured 10.2 % at 14, order 2.0).
DEFAULT_PPW = {1: [10, 20, 28, 40, 48], 2: [5, 6, 8, 10, 14, 20], 4: [3, 4, 5, 6, 7, 8, 10], 6: [4.5, 6, 7.5, 9]}
FULL_EXTRA_PPW = {1: [14, 56]}


def receivers_x():
    return [k * LAMBDA_MIN for k in RECEIVERS]


def geometry():
    L, H = LENGTH_UNITS * UNIT, DEPTH_UNITS * UNIT
    c_r = 0.9194 * VS
    # The margins quoted in the module docstring, checked here so a change of the constants
    # cannot silently let an echo into the window.
    right_echo = (2 * L - receivers_x()[-1]) / VP
    base_echo = math.hypot(receivers_x()[0], 2 * H) / VP
    assert right_echo > T_END and base_echo > T_END and T0 + receivers_x()[-1] / c_r + 0.1 < T_END
    coords = ",".join(f"{x:.10g},{H:.10g}" for x in receivers_x())
    names = ",".join(f"r{k}" for k in RECEIVERS)
    print(f"L={L:.10g} H={H:.10g} T_END={T_END} STATIONS={coords} NAMES={names}")
    # The source: a point just inside the corner (0, H); the nearest node (the corner) takes it.
    src = f"{0.01:.10g},{H - 0.01:.10g}"
    print(f"SRC={src}")
    # The run's options but the mesh and the degree (bench/cases/sem_speed_error.sh and
    # small_run_time.sh): the half model carries half the load.
    print(f"LAMB='-mesh_box_upper {L:.10g},{H:.10g} -regions soil -material_soil_rho {RHO:.10g} -material_soil_vp {VP:.10g} -material_soil_vs {VS:.10g}"
          f" -bc_left_type fixed -bc_left_components x -bc_right_type absorbing -bc_bottom_type absorbing"
          f" -point_forces src -point_force_src_location {src} -point_force_src_force 0,{-F / 2:.10g} -point_force_src_stf ricker"
          f" -point_force_src_f0 {F0:.10g} -point_force_src_t0 {T0:.10g} -ts_max_time {T_END} -output_fields 0 -progress_interval 1000"
          f" -station_coordinates {coords} -station_names {names}'")


def series(p):
    env = os.environ.get(f"SEM_BENCH_PPW_{p}")
    if env:
        ppw = [float(v) for v in env.split()]
    else:
        ppw = DEFAULT_PPW.get(p, [4, 6, 8, 10])
        if os.environ.get("SEM_BENCH_FULL") == "1":
            ppw = ppw + FULL_EXTRA_PPW.get(p, [])
    # m elements per 4 lambda_min: nodes per lambda_min = p m / 4.
    ms = sorted({max(1, round(4 * v / p)) for v in ppw})
    return ms


def plan():
    for p in [int(v) for v in os.environ.get("SEM_BENCH_DEGREES", "1 2 4 6").split()]:
        for m in series(p):
            print(p, m, LENGTH_UNITS * m, DEPTH_UNITS * m)


def reference(cache):
    """Surface velocities (v_x, v_y with y up) at the receivers on a fine grid, cached."""
    key = f"{RHO}_{VP}_{VS}_{F}_{F0}_{T0}_{RECEIVERS}"
    if os.path.exists(cache):
        data = np.load(cache)
        if str(data["key"]) == key:
            return data["t"], data["vx"], data["vy"]
    t = np.arange(0.0, 4.0, 2.5e-4)
    # d/dt of the Ricker: the response to it is the velocity.
    dricker = ricker_rate(t, F0, T0)
    assert np.allclose(np.gradient(ricker(t, F0, T0), t)[1:-1], dricker[1:-1], atol=2e-3 * np.abs(dricker).max())
    vx, vy = [], []
    for x in receivers_x():
        uz, ux = surface_response(x, t, F * dricker, RHO, VP, VS, f_max=50)
        # u_z is positive down, the mesh's y up; u_x positive away from the load, as the mesh's x.
        vx.append(ux)
        vy.append(-uz)
    np.savez(cache, key=key, t=t, vx=np.array(vx), vy=np.array(vy))
    return t, np.array(vx), np.array(vy)


def run_error(stations_dir, ref):
    from scipy.interpolate import CubicSpline
    t_ref, vx_ref, vy_ref = ref
    traces = {"v_x": vx_ref, "v_y": vy_ref}
    return pooled_error(stations_dir, [f"r{k}" for k in RECEIVERS], ("v_x", "v_y"), lambda i, c, t: CubicSpline(t_ref, traces[c][i])(t), T_END)


def analyse(manifest):
    work = os.path.dirname(os.path.abspath(manifest))
    ref = reference(os.path.join(work, "reference.npz"))
    runs = []
    for line in open(manifest):
        if not line.strip():
            continue
        fields = line.split()
        p, m, nx, ny, ranks, log, stations = fields[:7]
        mode = fields[7] if len(fields) > 7 else "default"
        p, m, nx, ny, ranks = int(p), int(m), int(nx), int(ny), int(ranks)
        steps, loop, nodes, order = parse_log(log)
        expected = (nx * p + 1) * (ny * p + 1)
        if nodes is not None and nodes != expected:
            print(f"warning: {log}: the run report says {nodes} nodes, (nx p + 1)(ny p + 1) = {expected}")
        err, per_receiver = run_error(stations, ref)
        dofs = 2 * expected
        runs.append(dict(p=p, m=m, nx=nx, ny=ny, ranks=ranks, ppw=p * m / 4, dofs=dofs, steps=steps, loop=loop, err=err, mode=mode, order=order,
                         err_far=per_receiver[-1], rate=dofs * steps / loop / ranks))
    runs.sort(key=lambda r: (r["p"], r["mode"], r["m"]))
    series_keys = sorted({(r["p"], r["mode"]) for r in runs})
    observed_orders(runs, "m")

    label = lambda r: f"{r['mode']}, order {r['order']}"
    header = ("| p | integrator | elements | h / lambda_min | GLL nodes per lambda_min | DOFs | steps | time loop [s] | error | error, farthest receiver | observed order | M DOF-updates/s/core |\n"
              "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
    table = header + "".join(
        f"| {r['p']} | {label(r)} | {r['nx']} x {r['ny']} | {4 / r['m']:.3g} | {r['ppw']:.3g} | {r['dofs']} | {r['steps']} | {r['loop']:.3g} | {100 * r['err']:.3g} % | "
        f"{100 * r['err_far']:.3g} % | {fmt(r['observed'], '.2f', '')} | {r['rate'] / 1e6:.1f} |\n" for r in runs)

    summary = {}
    for key, times in times_at_targets(runs).items():
        mine = [r for r in runs if (r["p"], r["mode"]) == key]
        summary[key] = dict(times=times, rate=mine[-1]["rate"], label=label(mine[-1]))
    q1 = summary.get((1, "default"), {}).get("times", {}).get(TARGET_ERROR, (None, ""))[0]
    lines = ("| p | integrator | time loop at 1 % error [s] | how | time loop at 0.1 % error [s] | how | Q1 time / this time at 1 % (target >= 40) | M DOF-updates/s/core (finest run) |\n"
             "|---:|---|---:|---|---:|---|---:|---:|\n")
    for key in series_keys:
        s = summary[key]
        (t1, how1), (t01, how01) = s["times"][0.01], s["times"][0.001]
        ratio = q1 / t1 if q1 and t1 else None
        s["ratio"] = ratio
        lines += (f"| {key[0]} | {s['label']} | {fmt(t1, '.3g')} | {how1 or 'not bracketed'} | {fmt(t01, '.3g')} | {how01 or 'not bracketed'} | "
                  f"{fmt(ratio, '.3g')} | {s['rate'] / 1e6:.1f} |\n")
    print(table)
    print(lines)

    csv = os.environ.get("BENCH_CSV")
    if csv:
        with open(csv, "a") as out:
            for r in runs:
                case = f"p{r['p']}_{r['nx']}x{r['ny']}_{r['mode']}"
                for metric, value, unit in (("degree", r["p"], "1"), ("integrator_order", r["order"], "1"), ("elements_x", r["nx"], "1"), ("elements_y", r["ny"], "1"),
                                            ("gll_nodes_per_min_wavelength", r["ppw"], "1"), ("dofs", r["dofs"], "1"), ("steps", r["steps"], "1"),
                                            ("time_loop_wall_time", r["loop"], "s"), ("l2_error_surface_velocity", r["err"], "1"),
                                            ("l2_error_farthest_receiver", r["err_far"], "1"), ("dof_updates_per_second_per_core", r["rate"], "1/s")):
                    out.write(f"sem_speed_error,{case},{metric},{value if isinstance(value, int) else format(value, '.4g')},{unit}\n")
            for key in series_keys:
                s = summary[key]
                for target, name in ((0.01, "1pct"), (0.001, "0p1pct")):
                    t, how = s["times"][target]
                    if t is not None:
                        out.write(f"sem_speed_error,p{key[0]}_{key[1]},time_loop_at_{name}_error_{how},{t:.4g},s\n")
                if s["ratio"] is not None:
                    out.write(f"sem_speed_error,p{key[0]}_{key[1]},q1_time_over_time_at_1pct_error,{s['ratio']:.4g},1\n")

    doc = os.environ.get("SEM_BENCH_DOC", os.path.join(ROOT, "docs", "spectral-elements.md"))
    png = os.path.splitext(doc)[0] + "_speed_error.png"
    plot(runs, series_keys, png)
    write_doc(doc, os.path.basename(png), table, lines)
    print(f"table in {doc}, plot in {png}")


def plot(runs, series_keys, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for p, mode in series_keys:
        mine = [r for r in runs if (r["p"], r["mode"]) == (p, mode)]
        style = "o-" if mode == "default" else "s--"
        ax1.loglog([r["err"] for r in mine], [r["loop"] for r in mine], style, label=f"p = {p}, {mode}")
        ax2.loglog([r["ppw"] for r in mine], [r["err"] for r in mine], style, label=f"p = {p}, {mode}")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    for target in TARGETS:
        ax1.axvline(target, color="gray", ls="--", lw=1)
    ax1.set_xlabel("relative L2 error of the surface velocities")
    ax1.set_ylabel("wall time of the time loop [s]")
    ax1.invert_xaxis()
    ax1.set_title("Lamb's line load, receivers at 8-28 lambda_min")
    for target in TARGETS:
        ax2.axhline(target, color="gray", ls="--", lw=1)
    ax2.set_xlabel("GLL nodes per minimum S wavelength")
    ax2.set_ylabel("relative L2 error")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


BEGIN, END = "<!-- sem_speed_error: begin (written by bench/sem_speed_error.py) -->", "<!-- sem_speed_error: end -->"


def write_doc(doc, png_name, table, lines):
    section = (f"{BEGIN}\n## Results (last `bench/cases/sem_speed_error.sh` run)\n\n{machine_state()}\n\n"
               f"![wall time against error]({png_name})\n\n{table}\n{lines}{END}\n")
    replace_section(doc, BEGIN, END, section)


if __name__ == "__main__":
    main(__doc__, geometry, plan, analyse)
