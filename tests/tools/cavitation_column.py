#!/usr/bin/python3
"""An independent solution of the saturated column with cavitation (tests/cases/saturated_cavitation.sh).

usage: cavitation_column.py RUN --height H --rho RHO --vp VP --porosity N --fluid-bulk-modulus KF
       --hydraulic-conductivity K --limit P_CAV --f0 F --t0 T0 --amplitude A
       --pressure-stations name:z,... --velocity-stations name:z,... [--component y|z] [--cells N]
       [--max-error E]

The model (docs/saturated-soil.md, Cavitation), in 1D: a column of saturated soil, z up,
tension positive, no gravity, incompressible grains (alpha = 1, 1/M = n / K_f), water
(mobility kappa = k / (1000 * 9.80665)); the base at z = 0 absorbs with the undrained
impedance and lets in the up-going P wave whose velocity is a Ricker wavelet (peak A at t0,
central frequency f0); the top at z = H is free; no flow through either end. With m the fluid
content that Darcy flow brings into a cell (m_t = -dw/dz, w = -kappa dp/dz), the pore
pressure is a function of the state, p = max(M (m - alpha eps), p_cav): the water follows the
expansion down to the limit, a cavity takes the rest and closes first on the way back. The
skeleton: rho v_t = d sigma / dz, sigma = E eps - alpha p, E = lambda + 2 mu the drained
constrained modulus.

Method: velocity-strain finite differences on a staggered grid (velocities at the nodes,
strains, fluid contents and pressures at the cell centres, explicit in time at half the
smaller of the wave and diffusion limits), with the pressure evaluated from the state as
above; slipwave instead integrates the storage equation incrementally with the cavity
volume as a state (finite elements, lumped storage). The base condition is the
characteristic one, sigma(0) = rho c_u (v(0) - 2 v_inc), exact for the linear undrained
column the waves cross there. Default 2000 cells (0.1 m on the test's 200 m column; 4000
move the test's errors by less than 6e-4).

Compares the stations' p (total) and vertical velocity (v_y, or --component) of RUN with this solution: the L2 norm of the
difference over the run, relative to the L2 norm of the reference; exits 1 if one exceeds
--max-error.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder  # noqa: E402


def ricker(t, f0, t0, amplitude):
    a = (math.pi * f0 * (t - t0)) ** 2
    return amplitude * (1.0 - 2.0 * a) * np.exp(-a)


def solve(args, t_end, z_stations):
    """Histories v(z, t), p(z, t) at z_stations, sampled every step of the reference."""
    E = args.rho * args.vp**2  # drained constrained modulus lambda + 2 mu
    M = args.fluid_bulk_modulus / args.porosity  # incompressible grains: 1/M = n / K_f
    alpha = 1.0
    kappa = args.hydraulic_conductivity / (1000.0 * 9.80665)  # mobility: water, the unit conversion's g
    c_u = math.sqrt((E + alpha**2 * M) / args.rho)
    n = args.cells
    dz = args.height / n
    # Within the wave's limit and the explicit diffusion's, dz^2 / (2 kappa M).
    dt = 0.5 * min(dz / c_u, dz**2 / (2.0 * kappa * M) if kappa > 0 else 1e300)
    steps = int(math.ceil(t_end / dt))
    v = np.zeros(n + 1)
    eps = np.zeros(n)
    content = np.zeros(n)  # the fluid content m per cell: what Darcy flow brought in
    mass = np.full(n + 1, args.rho * dz)
    mass[0] = mass[-1] = 0.5 * args.rho * dz
    z_nodes = np.linspace(0.0, args.height, n + 1)
    z_cells = 0.5 * (z_nodes[:-1] + z_nodes[1:])
    impedance = args.rho * c_u
    times, vs, ps = [], [], []

    def pressure(e, m):
        return np.maximum(M * (m - alpha * e), args.limit)

    for k in range(steps + 1):
        t = k * dt
        p = pressure(eps, content)
        times.append(t)
        vs.append(np.interp(z_stations, z_nodes, v))
        # p at the top and base from the nearest cell centres (the free top has sigma = 0,
        # not p = 0: the pressure there is that of the strain the free surface takes).
        ps.append(np.interp(z_stations, z_cells, p))
        sigma = E * eps - alpha * p
        force = np.zeros(n + 1)
        force[:-1] += sigma
        force[1:] -= sigma
        # Base: the dashpot with the incident wave's traction, implicit in v(0).
        v_inc = ricker(t + 0.5 * dt, args.f0, args.t0, args.amplitude)
        v_new = v + dt * force / mass
        v_new[0] = (mass[0] * v[0] + dt * (force[0] - impedance * (0.5 * v[0] - 2.0 * v_inc))) / (mass[0] + 0.5 * dt * impedance)
        v = v_new
        eps = eps + dt * (v[1:] - v[:-1]) / dz
        # Darcy: m_t = -dw/dz, w = -kappa dp/dz between cells, no flow at both ends.
        w = np.zeros(n + 1)
        w[1:-1] = -kappa * (p[1:] - p[:-1]) / dz
        content = content - dt * (w[1:] - w[:-1]) / dz
    return np.array(times), np.array(vs), np.array(ps)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    for name in ("height", "rho", "vp", "porosity", "fluid_bulk_modulus", "hydraulic_conductivity", "limit", "f0", "t0", "amplitude"):
        ap.add_argument("--" + name.replace("_", "-"), type=float, required=True)
    ap.add_argument("--pressure-stations", required=True, help="name:z,... whose p is compared (z: elevation of the station [m])")
    ap.add_argument("--velocity-stations", required=True, help="name:z,... whose v_y is compared")
    ap.add_argument("--component", default="y", help="the vertical velocity component of the run: y in 2D, z in 3D")
    ap.add_argument("--cells", type=int, default=2000)
    ap.add_argument("--max-error", type=float, default=0.02)
    args = ap.parse_args()
    run = RunFolder(args.run)
    compared = [(s.split(":")[0], float(s.split(":")[1]), "p") for s in args.pressure_stations.split(",")]
    compared += [(s.split(":")[0], float(s.split(":")[1]), "v_" + args.component) for s in args.velocity_stations.split(",")]
    z = np.array([c[1] for c in compared])
    records = {name: run.station(name) for name, _, _ in compared}
    t_end = max(r["t"][-1] for r in records.values())
    t_ref, v_ref, p_ref = solve(args, t_end, z)
    ok = True
    for k, (name, zk, label) in enumerate(compared):
        r = records[name]
        got = r[label]
        want = np.interp(r["t"], t_ref, (p_ref if label == "p" else v_ref)[:, k])
        err = np.linalg.norm(got - want) / np.linalg.norm(want)
        ok &= err <= args.max_error
        print(f"  {name} (z = {zk:g} m) {label}: L2 difference {err:.2e} of the reference's norm (bound {args.max_error:.0e}); "
              f"min {got.min():.5g} vs {want.min():.5g}, max {got.max():.5g} vs {want.max():.5g}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
