"""Reads a grid's frames as slipwave writes them (src/io/field_writer.cpp): the mesh in
DIR/<grid>.h5 (/geometry, /topology) and each frame's fields in their own file, found through
the XDMF index DIR/<grid>.xmf, which names only complete files."""
import os
import xml.etree.ElementTree as ET

import h5py


class Frames:
    def __init__(self, out_dir, grid="volume"):
        self.out_dir = out_dir
        self.times, self._refs = [], []  # per frame: {field: (file relative to out_dir, dataset)}
        for step in ET.parse(os.path.join(out_dir, grid + ".xmf")).getroot().iter("Grid"):
            if step.get("GridType") != "Uniform":
                continue
            self.times.append(float(step.find("Time").get("Value")))
            self._refs.append({a.get("Name"): tuple(a.find("DataItem").text.strip().split(":", 1)) for a in step.findall("Attribute")})
        with h5py.File(os.path.join(out_dir, grid + ".h5"), "r") as mesh:
            self.geometry, self.topology = mesh["/geometry"][()], mesh["/topology"][()]

    def __len__(self):
        return len(self.times)

    def field_names(self, frame):
        return list(self._refs[frame])

    def field(self, name, frame):
        """Field `name` of frame number `frame` (index order; negative counts from the end)."""
        file_name, path = self._refs[frame][name]
        with h5py.File(os.path.join(self.out_dir, file_name), "r") as h5:
            return h5[path][()]

    def series(self, name):
        """Field `name` of every frame, in time order."""
        return [self.field(name, k) for k in range(len(self))]
