#!/usr/bin/python3
"""Unit tests of python/slipwave on a run folder that tests/cases/python_reader.sh makes.

The run: a 20 m x 6 m box of 20 x 6 cells of 1 m (soil: vs 300 m/s), a block 8 <= x <= 12,
4 <= y <= 6 (region "block", after "soil") tied to the soil by interface "base", an SV Ricker
from the absorbing bottom, a fixed time step, stations on mesh nodes. The options the script
gives are passed in the environment (SLIPWAVE_*); every expected number below is derived from
them or from the writers in src/ (named where used), not from the reader under test.

usage: SLIPWAVE_RUN=DIR SLIPWAVE_TS_DT=... /usr/bin/python3 python/tests/test_run_folder.py
"""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from slipwave import FIELD_UNITS, RunFolder, read_csv  # noqa: E402

ENV = os.environ
RUN = ENV.get("SLIPWAVE_RUN", "")
DT = float(ENV.get("SLIPWAVE_TS_DT", "nan"))  # -ts_dt [s]
INTERVAL = float(ENV.get("SLIPWAVE_OUTPUT_INTERVAL", "nan"))  # -output_interval [s]
MAX_TIME = float(ENV.get("SLIPWAVE_MAX_TIME", "nan"))  # -ts_max_time [s]
ENERGY_INTERVAL = int(ENV.get("SLIPWAVE_ENERGY_INTERVAL", "0"))  # -energy_interval [steps]
# -station_names and -station_coordinates: {name: (x, y)} [m], each on a mesh node.
STATIONS = {n: (float(x), float(y)) for n, x, y in (s.split(":") for s in ENV.get("SLIPWAVE_STATIONS", "").split(",") if s)}
CELLS = (20, 6)  # -mesh_box_faces; -mesh_box_upper 20,6: cells of 1 m
BLOCK = (8.0, 12.0, 4.0, 6.0)  # -region_block_box x0,x1,y0,y1 [m]
VS_SOIL = 300.0  # -material_soil_vs [m/s], the slowest region

STEPS = int(round(MAX_TIME / DT))  # the run's step count
FRAMES = int(round(MAX_TIME / INTERVAL)) + 1  # frames at 0, the interval's multiples and the end


def setUpModule():
    if not RUN or not os.path.isdir(RUN):
        raise unittest.SkipTest("SLIPWAVE_RUN is not a run folder: run tests/cases/python_reader.sh")


class Stations(unittest.TestCase):
    def setUp(self):
        self.run = RunFolder(RUN)

    def test_names(self):
        # -station_names; stations.cpp writes stations/<name>.csv per station.
        self.assertEqual(self.run.station_names(), sorted(STATIONS))

    def test_columns_and_units(self):
        # stations.cpp Flush: "t", then u, v, a per axis (x, y in 2D); no p without pores.
        for name in STATIONS:
            s = self.run.station(name)
            self.assertEqual(s.names, ("t", "u_x", "u_y", "v_x", "v_y", "a_x", "a_y"))
            self.assertEqual([s.unit(c) for c in s.names], ["s", "m", "m", "m/s", "m/s", "m/s^2", "m/s^2"])
            with self.assertRaises(KeyError):
                s.unit("u_z")

    def test_time_every_step(self):
        # Stations sample every step (simulation.cpp monitor), from t = 0 to -ts_max_time at -ts_dt.
        for name in STATIONS:
            t = self.run.station(name)["t"]
            self.assertEqual(len(t), STEPS + 1)
            self.assertEqual(t[0], 0.0)
            np.testing.assert_allclose(np.diff(t), DT, rtol=1e-9)
            self.assertAlmostEqual(t[-1], MAX_TIME, delta=1e-12)

    def test_h5_equals_csv(self):
        # The same rows go to both files; the CSV prints %.17g, which round-trips a double.
        for name in STATIONS:
            a, b = self.run.station(name, "csv"), self.run.station(name, "h5")
            self.assertEqual(a.names, b.names)
            for c in a.names:
                np.testing.assert_array_equal(a[c], b[c], err_msg=f"{name} {c}")

    def test_something_moves(self):
        # The SV Ricker reaches every station long before -ts_max_time (6 m at 300 m/s: 0.02 s).
        for name in STATIONS:
            self.assertGreater(np.max(np.abs(self.run.station(name)["v_x"])), 0.0, name)

    def test_equals_volume_frame_at_node(self):
        # A station on a node records that node's values (shape function 1 there, 0 elsewhere,
        # to round-off: stations.cpp); frames and station rows share the step's t.
        volume = self.run.volume()
        for name, (x, y) in STATIONS.items():
            s = self.run.station(name)
            node = np.nonzero(np.all(np.isclose(volume.geometry, [x, y, 0.0], atol=1e-9), axis=1))[0]
            self.assertEqual(len(node), 1, f"station {name} is not on one node")
            for frame, t in enumerate(volume.times):
                row = np.nonzero(np.abs(s["t"] - t) <= 1e-12)[0]
                self.assertEqual(len(row), 1, f"{name}: no station row at frame time {t}")
                for field, q in (("displacement", "u"), ("velocity", "v"), ("acceleration", "a")):
                    values = volume.field(field, frame)
                    scale = max(np.max(np.abs(values)), 1e-300)
                    for k, c in enumerate("xy"):
                        self.assertLessEqual(abs(s[f"{q}_{c}"][row[0]] - values[node[0], k]), 1e-10 * scale, f"{name} {q}_{c} frame {frame}")


class Energy(unittest.TestCase):
    def setUp(self):
        self.e = RunFolder(RUN).energy()

    def test_columns_and_units(self):
        # energy_csv.cpp: "step", kValueColumns; no fluid columns in a dry run.
        self.assertEqual(self.e.names, ("step", "time", "kinetic", "strain", "input_work", "external_work", "absorbed", "damped", "anelastic",
                                        "interface_work", "interface_stored", "interface_dissipated", "contact_damped", "stored_change",
                                        "balance_error", "relative_balance_error"))
        self.assertEqual(self.e.unit("step"), "-")
        self.assertEqual(self.e.unit("time"), "s")
        self.assertEqual(self.e.unit("relative_balance_error"), "-")
        self.assertEqual(self.e.unit("kinetic"), "J (per m in 2D)")

    def test_rows(self):
        # A row every -energy_interval steps, at every output time and at the last step
        # (simulation.cpp monitor); time = step x -ts_dt (10 digits).
        step = self.e["step"]
        self.assertTrue(set(range(0, STEPS + 1, ENERGY_INTERVAL)) <= set(step.astype(int)))
        self.assertEqual(step[-1], STEPS)
        self.assertTrue(np.all(np.diff(step) > 0))
        np.testing.assert_allclose(self.e["time"], step * DT, rtol=1e-9, atol=1e-15)

    def test_balance_is_its_terms(self):
        # energy_ledger.cpp: balance_error = stored_change - (input + external + interface work
        # - absorbed - damped - anelastic - contact damped), each printed with 10 digits.
        e = self.e
        booked = e["input_work"] + e["external_work"] + e["interface_work"] - e["absorbed"] - e["damped"] - e["anelastic"] - e["contact_damped"]
        terms = ("stored_change", "input_work", "external_work", "interface_work", "absorbed", "damped", "anelastic", "contact_damped")
        scale = max(np.max(np.abs(e[c])) for c in terms)
        self.assertGreater(scale, 0.0)
        np.testing.assert_allclose(e["balance_error"], e["stored_change"] - booked, rtol=0, atol=1e-8 * scale)

    def test_relative_error_over_largest_energy(self):
        # relative = balance_error / scale, scale >= the largest kinetic + |strain| so far
        # (energy_ledger.cpp), printed with 4 digits.
        e = self.e
        largest = np.maximum.accumulate(e["kinetic"] + np.abs(e["strain"]))
        live = largest > 0
        self.assertTrue(np.all(np.abs(e["relative_balance_error"][live]) <= np.abs(e["balance_error"][live]) / largest[live] * (1 + 1e-3) + 1e-300))
        self.assertTrue(np.all(e["kinetic"] >= 0))

    def test_empty_csv(self):
        # A header and no rows (a run killed before its first row): columns of length 0.
        with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
            f.write("step,time,kinetic\n")
        try:
            t = read_csv(f.name)
            self.assertEqual(t.names, ("step", "time", "kinetic"))
            self.assertEqual(len(t), 0)
        finally:
            os.remove(f.name)


class RunInfo(unittest.TestCase):
    def test_fields(self):
        info = RunFolder(RUN).run_info()
        # run_report.cpp WriteRunInfo; degree 1 writes no element_degree; the run has an
        # interface, so its answers (app/run_answers.hpp) are there, each a value and a unit.
        self.assertEqual(set(info), {"resolved_frequency_hz", "points_per_wavelength", "slowest_region", "resolving_element_size_m", "h_min_m", "input_top_frequency_hz",
                                     "time_step_s", "answers"})
        self.assertIn("net_slip", info["answers"])
        for key, answer in info["answers"].items():
            self.assertEqual(set(answer), {"value", "unit"}, key)
        self.assertEqual(info["time_step_s"], DT)  # -ts_dt, printed with 10 digits
        self.assertEqual(info["h_min_m"], 1.0)  # 20 m / 20 cells
        self.assertEqual(info["resolving_element_size_m"], 1.0)  # the soil's largest cell: every cell's
        self.assertEqual(info["points_per_wavelength"], 10)  # degree 1: Kuhlemeyer & Lysmer
        self.assertEqual(info["slowest_region"], "soil")
        self.assertAlmostEqual(info["resolved_frequency_hz"], VS_SOIL / (10 * 1.0), places=4)  # vs / (10 h)
        self.assertGreater(info["input_top_frequency_hz"], 0.0)


class Volume(unittest.TestCase):
    def setUp(self):
        self.v = RunFolder(RUN).volume()

    def test_frame_times(self):
        # Frames at t = 0, at the first step at or after each multiple of -output_interval,
        # and at the end (output_frames.hpp Due).
        t = np.array(self.v.times)
        self.assertEqual(len(self.v), FRAMES)
        self.assertEqual(t[0], 0.0)
        late = t - INTERVAL * np.arange(FRAMES)
        self.assertTrue(np.all((late > -1e-9) & (late < DT)), late)
        self.assertAlmostEqual(t[-1], MAX_TIME, delta=1e-12)

    def test_mesh(self):
        # Quadrilaterals of the box: (20 + 1) x (6 + 1) nodes, plus a second node at each
        # interface pair (the split: soil and block nodes at one place), z = 0 in 2D.
        nx, ny = CELLS
        pairs = len(RunFolder(RUN).interface("base").geometry)
        self.assertEqual(self.v.geometry.shape, ((nx + 1) * (ny + 1) + pairs, 3))
        self.assertEqual(self.v.topology.shape, (nx * ny, 4))
        self.assertEqual(self.v.topology_type, "Quadrilateral")
        np.testing.assert_array_equal(self.v.geometry[:, 2], 0.0)
        self.assertEqual(sorted(set(self.v.geometry[:, 0])), list(range(nx + 1)))

    def test_fields(self):
        # volume_output.cpp: node vectors written as 3 columns, the stress as a full 3 x 3
        # (field_writer.cpp), region an index into -regions soil,block.
        v = self.v
        self.assertEqual(v.field_names(0), ["displacement", "displacement_relative", "velocity", "acceleration", "stress", "region"])
        nodes, cells = len(v.geometry), len(v.topology)
        for name in ("displacement", "displacement_relative", "velocity", "acceleration"):
            values = v.field(name, -1)
            self.assertEqual(values.shape, (nodes, 3))
            np.testing.assert_array_equal(values[:, 2], 0.0)
            self.assertEqual(FIELD_UNITS[name], {"displacement": "m", "displacement_relative": "m", "velocity": "m/s", "acceleration": "m/s^2"}[name])
        stress = v.field("stress", -1)
        self.assertEqual(stress.shape, (cells, 9))
        np.testing.assert_array_equal(stress[:, [1, 2, 5]], stress[:, [3, 6, 7]])  # xy = yx, xz = zx, yz = zy
        region = v.field("region", 0)[:, 0]
        centres = v.geometry[v.topology].mean(axis=1)
        x0, x1, y0, y1 = BLOCK
        in_block = (centres[:, 0] > x0) & (centres[:, 0] < x1) & (centres[:, 1] > y0) & (centres[:, 1] < y1)
        np.testing.assert_array_equal(region, np.where(in_block, 1.0, 0.0))
        self.assertEqual(int(in_block.sum()), int((x1 - x0) * (y1 - y0)))  # cells of 1 m^2

    def test_stacked_equals_fields(self):
        v = self.v
        stack = v.stacked(["velocity", "region"])
        self.assertEqual(stack["velocity"].shape, (len(v), len(v.geometry), 3))
        for k in (0, len(v) - 1):
            np.testing.assert_array_equal(stack["velocity"][k], v.field("velocity", k))
        np.testing.assert_array_equal(np.array(v.series("region")), stack["region"])


class Interface(unittest.TestCase):
    def setUp(self):
        self.run = RunFolder(RUN)
        self.f = self.run.interface("base")

    def test_names(self):
        self.assertEqual(self.run.interface_names(), ["base"])  # -interfaces base

    def test_pairs(self):
        # One pair per node of the block's faces on the soil: its base y = 4 and its sides
        # x = 8 and x = 12 up to the surface y = 6; segments of the 2D line are Polylines.
        x0, x1, y0, y1 = BLOCK
        want = {(x, y0) for x in np.arange(x0, x1 + 1)} | {(x, y) for x in (x0, x1) for y in np.arange(y0, y1 + 1)}
        got = {(round(p[0], 9), round(p[1], 9)) for p in self.f.geometry}
        self.assertEqual(got, want)
        self.assertEqual(self.f.topology_type, "Polyline")
        self.assertEqual(self.f.topology.shape, (len(want) - 1, 2))  # an open chain

    def test_fields(self):
        # interface_output.cpp kWidths and InterfaceAssembler::pairFieldNames (dry soil, the default friction lag), after
        # the soil side's displacement (total and relative to the base: io/base_displacement).
        widths = {"displacement": 3, "displacement_relative": 3, "opening": 1, "slip": 3, "sigma_N": 1, "sigma_T": 3, "plastic_opening": 1, "accumulated_slip": 1, "status": 1, "dissipation": 1,
                  "sigma_N_friction": 1}
        self.assertEqual(self.f.field_names(0), list(widths))
        stack = self.f.stacked()
        for name, w in widths.items():
            self.assertEqual(stack[name].shape, (len(self.f), len(self.f.geometry), w), name)
            self.assertIn(name, FIELD_UNITS)
        self.assertTrue(set(np.unique(stack["status"])) <= {0.0, 1.0, 2.0})
        np.testing.assert_array_equal(stack["slip"][:, :, 2], 0.0)  # 2D: no z
        self.assertTrue(np.all(np.diff(stack["accumulated_slip"][:, :, 0], axis=0) >= 0))  # a path length grows

    def test_same_frames_as_volume(self):
        # output_frames.cpp writes the volume and every interface at the same steps.
        self.assertEqual(self.f.times, self.run.volume().times)


if __name__ == "__main__":
    unittest.main(verbosity=2)
