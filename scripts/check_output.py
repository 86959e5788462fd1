#!/usr/bin/python3
"""Checks an XDMF + HDF5 output of slipwave (io::FieldWriter) without ParaView.

usage: /usr/bin/python3 scripts/check_output.py DIR [--grid volume] [--expect-steps N] [--expect-fields a,b,c]

Parses DIR/<grid>.xmf and checks that every HDF DataItem names an existing dataset whose shape
equals the declared Dimensions and whose type matches NumberType/Precision, that all values
are finite (in every dataset of the HDF5 files it names, listed or not), that topology indices
address existing nodes, that attribute rows match the node or cell count, and that times
increase. Prints one summary line; exits 0 if all holds, else
prints each problem and exits 1.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from slipwave.xdmf import XdmfError, read_index  # noqa: E402

# XDMF defaults (NumberType Float, Precision 4) apply when an attribute is missing (slipwave.xdmf).
KINDS = {"Float": "f", "Int": "i", "UInt": "u", "Char": "i", "UChar": "u"}
NODES_PER_CELL = {"Triangle": 3, "Quadrilateral": 4, "Tetrahedron": 4, "Hexahedron": 8, "Wedge": 6, "Pyramid": 5}
COMPONENTS = {"Scalar": 1, "Vector": 3, "Tensor6": 6, "Tensor": 9}
GEOMETRY_COLUMNS = {"XYZ": 3, "XY": 2}


class Checker:
    def __init__(self, xmf_path):
        self.xmf_path = xmf_path
        self.base = os.path.dirname(os.path.abspath(xmf_path))
        self.problems = []
        self.checked = {}  # (file, path) -> array, each dataset read once
        self.files = {}

    def fail(self, where, message):
        self.problems.append(f"{where}: {message}")

    def data_item(self, ref, where):
        """Checks one HDF DataItem (a slipwave.xdmf.HdfRef, or the XdmfError that stands for
        it); returns its array or None."""
        if isinstance(ref, XdmfError):
            self.fail(where, str(ref))
            return None
        file_path, path, dims = os.path.join(self.base, ref.file), ref.dataset, ref.dims
        number_type, precision, text = ref.number_type, ref.precision, ref.text
        key = (file_path, path)
        if key not in self.checked:
            self.checked[key] = self.read(file_path, path, where)
        data = self.checked[key]
        if data is None:
            return None
        if data.shape != dims:
            self.fail(where, f"{text}: dataset shape {data.shape} != declared Dimensions {dims}")
            return None
        kind = KINDS.get(number_type)
        if kind is None:
            self.fail(where, f"unknown NumberType {number_type!r}")
        elif data.dtype.kind != kind or data.dtype.itemsize != precision:
            self.fail(where, f"{text}: dataset type {data.dtype} does not match NumberType={number_type} Precision={precision}")
        return data

    def read(self, file_path, path, where):
        if file_path not in self.files:
            if not os.path.isfile(file_path):
                self.fail(where, f"HDF5 file {file_path} does not exist")
                self.files[file_path] = None
            else:
                self.files[file_path] = h5py.File(file_path, "r")
        h5 = self.files[file_path]
        if h5 is None:
            return None
        if path not in h5 or not isinstance(h5[path], h5py.Dataset):
            self.fail(where, f"{os.path.basename(file_path)}:{path} is not a dataset")
            return None
        data = h5[path][()]
        if data.dtype.kind == "f" and not np.all(np.isfinite(data)):
            self.fail(where, f"{path}: {int(np.size(data) - np.count_nonzero(np.isfinite(data)))} non-finite values")
        return data

    def uniform_grid(self, step, label):
        """Checks one Uniform grid (a slipwave.xdmf.Step); returns (time or None, {field name: Center})."""
        time = step.time
        if step.has_time and time is None:
            self.fail(label, f"Time Value {step.time_text!r} is not a number")
        geometry, topology = step.geometry, step.topology
        if geometry is None or topology is None:
            self.fail(label, "missing Geometry or Topology")
            return time, {}
        gtype = geometry.kind or "XYZ"
        coords = self.data_item(geometry.ref, f"{label} Geometry")
        num_nodes = None
        if coords is not None:
            columns = GEOMETRY_COLUMNS.get(gtype)
            if columns is None:
                self.fail(label, f"GeometryType {gtype!r} not checked (XYZ or XY)")
            elif coords.ndim != 2 or coords.shape[1] != columns:
                self.fail(label, f"GeometryType {gtype} wants [nodes, {columns}], got {coords.shape}")
            else:
                num_nodes = coords.shape[0]
        ttype = topology.kind
        cells = self.data_item(topology.ref, f"{label} Topology")
        num_cells = None
        if cells is not None:
            per_cell = NODES_PER_CELL.get(ttype)
            if ttype in ("Polyline", "Polyvertex"):
                per_cell = int(topology.attributes.get("NodesPerElement", "0"))
            if per_cell is None or cells.ndim != 2 or cells.shape[1] != per_cell:
                self.fail(label, f"TopologyType {ttype} wants [cells, {per_cell}], got {cells.shape}")
            else:
                num_cells = cells.shape[0]
                declared = topology.attributes.get("NumberOfElements")
                if declared is not None and int(declared) != num_cells:
                    self.fail(label, f"NumberOfElements {declared} != {num_cells} topology rows")
                if num_nodes is not None and cells.size and (cells.min() < 0 or cells.max() >= num_nodes):
                    self.fail(label, f"topology indices span [{cells.min()}, {cells.max()}], nodes are [0, {num_nodes})")
        fields = {}
        for attribute in step.attributes:
            name, center, atype = attribute.name, attribute.center, attribute.kind
            where = f"{label} Attribute {name}"
            if name in fields:
                self.fail(where, "listed twice")
            fields[name] = center
            values = self.data_item(attribute.ref, where)
            if values is None:
                continue
            rows = {"Node": num_nodes, "Cell": num_cells}.get(center, "unknown")
            if rows == "unknown":
                self.fail(where, f"Center {center!r} not checked (Node or Cell)")
            elif rows is not None and values.shape[0] != rows:
                self.fail(where, f"{values.shape[0]} rows, but {rows} {center.lower()}s")
            components = COMPONENTS.get(atype)
            have = 1 if values.ndim == 1 else int(np.prod(values.shape[1:]))
            if components is None:
                self.fail(where, f"AttributeType {atype!r} not checked")
            elif have != components:
                self.fail(where, f"AttributeType {atype} wants {components} components, dataset has {have}")
        return time, fields

    def run(self, expect_steps, expect_fields):
        try:
            index = read_index(self.xmf_path)
        except (OSError, ET.ParseError) as error:
            self.fail(self.xmf_path, f"cannot parse: {error}")
            return None
        except XdmfError as error:
            self.fail(self.xmf_path, str(error))
            return None
        if index.collection and index.collection_type != "Temporal":
            self.fail(self.xmf_path, f"collection type {index.collection_type!r}, want Temporal")
        grids = index.steps
        steps = []
        for i, step in enumerate(grids):
            steps.append(self.uniform_grid(step, f"step {i} (grid {step.name})"))
        times = [t for t, _ in steps]
        if len(grids) > 1:
            if any(t is None for t in times):
                self.fail(self.xmf_path, "a step of the temporal collection has no <Time Value=...>")
            elif any(b <= a for a, b in zip(times, times[1:])):
                self.fail(self.xmf_path, f"times do not increase: {times}")
        if expect_steps is not None and len(grids) != expect_steps:
            self.fail(self.xmf_path, f"{len(grids)} steps, expected {expect_steps}")
        for i, (_, fields) in enumerate(steps):
            missing = [f for f in expect_fields if f not in fields]
            if missing:
                self.fail(self.xmf_path, f"step {i} lacks field(s) {', '.join(missing)} (has {', '.join(fields) or 'none'})")
        return steps

    def unlisted_non_finite(self):
        """Every float dataset of the HDF5 files the index names, also those it does not list."""
        for file_path, h5 in self.files.items():
            if h5 is None:
                continue
            def visit(name, obj):
                key = (file_path, "/" + name)
                if isinstance(obj, h5py.Dataset) and key not in self.checked and obj.dtype.kind == "f":
                    data = obj[()]
                    bad = int(np.size(data) - np.count_nonzero(np.isfinite(data)))
                    if bad:
                        self.fail(os.path.basename(file_path), f"/{name}: {bad} non-finite values (a dataset the index does not list)")
            h5.visititems(visit)

    def close(self):
        for h5 in self.files.values():
            if h5 is not None:
                h5.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dir", help="output directory holding GRID.xmf")
    parser.add_argument("--grid", default="volume", help="grid name = file stem of the .xmf (default volume)")
    parser.add_argument("--expect-steps", type=int, help="number of output steps the .xmf must list")
    parser.add_argument("--expect-fields", default="", help="comma-separated fields every step must have")
    args = parser.parse_args()
    xmf = os.path.join(args.dir, args.grid + ".xmf")
    expect_fields = [f for f in args.expect_fields.split(",") if f]
    if not os.path.isfile(xmf):
        print(f"check_output: FAIL: {xmf} does not exist")
        return 1
    checker = Checker(xmf)
    try:
        steps = checker.run(args.expect_steps, expect_fields)
        checker.unlisted_non_finite()
    finally:
        checker.close()
    if checker.problems:
        shown = 20  # a broken dataset shared by all steps repeats its problem per step
        for problem in checker.problems[:shown]:
            print(f"check_output: FAIL: {problem}")
        if len(checker.problems) > shown:
            print(f"check_output: FAIL: ... and {len(checker.problems) - shown} more problems")
        return 1
    times = [t for t, _ in steps]
    names = sorted({name for _, fields in steps for name in fields})
    span = f"t = {times[0]:g} .. {times[-1]:g}" if steps and times[0] is not None else "no time"
    print(f"check_output: OK {xmf}: {len(steps)} steps ({span}), fields {','.join(names) or 'none'}, "
          f"{len(checker.checked)} HDF5 datasets checked")
    return 0


if __name__ == "__main__":
    sys.exit(main())
