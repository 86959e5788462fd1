"""Reads the folder a slipwave run writes (-output_dir), as its writers lay it out:

  stations/<name>.csv   one row per time step: t, u_x, u_y[, u_z], v_*, a_*[, p, p_excess]
                        (src/io/stations.cpp)
  stations.h5           the same records, one group per station: time [n], displacement,
                        velocity, acceleration [n, dim][, pore_pressure, excess_pore_pressure [n]]
  energy.csv            the energy ledger, one row per evaluated step (src/app/energy_csv.cpp)
  run_info.json         the mesh's resolution and the time step (src/app/run_report.cpp)
  volume.xmf, volume.h5, volume/<frame>.h5
                        the volume frames: XDMF index, mesh, one file per frame
                        (src/io/volume_output.cpp, src/io/field_writer.cpp)
  interface_<name>.xmf, interface_<name>.h5, interface_<name>/<frame>.h5
                        the frames of interface <name>, one row per node pair
                        (src/io/interface_output.cpp)

Units are SI throughout. Energies are in J per metre of thickness in 2D (plane strain), J in 3D.
"""
import glob
import json
import os

import numpy as np

from .xdmf import XdmfError, read_index

# Units of the columns of the station CSVs and energy.csv, by column name.
_UNITS = {"t": "s", "p": "Pa", "p_excess": "Pa", "step": "-", "time": "s", "relative_balance_error": "-"}
_UNITS.update({f"{q}_{c}": unit for q, unit in (("u", "m"), ("v", "m/s"), ("a", "m/s^2")) for c in "xyz"})
# -station_stress: the stress s_* [Pa] and strain e_* [-] tensor components of the station's
# cell; stations.h5 holds them as datasets stress and strain whose width names them (2D: the
# components that plane strain does not make zero; src/io/stations.hpp).
_TENSOR_COMPONENTS = {3: ("xx", "yy", "xy"), 4: ("xx", "yy", "zz", "xy"), 6: ("xx", "yy", "zz", "xy", "yz", "xz")}
_UNITS.update({f"{q}_{c}": unit for q, unit in (("s", "Pa"), ("e", "-")) for c in _TENSOR_COMPONENTS[6]})
ENERGY_UNIT = "J (per m in 2D)"

# Units of the frames' fields (volume and interface), by field name.
FIELD_UNITS = {
    "displacement": "m", "displacement_relative": "m", "velocity": "m/s", "acceleration": "m/s^2", "stress": "Pa", "region": "-",
    "pore_pressure": "Pa", "excess_pore_pressure": "Pa", "max_shear_strain": "-", "secant_modulus_ratio": "-",
    "opening": "m", "slip": "m", "sigma_N": "Pa", "sigma_T": "Pa", "plastic_opening": "m", "accumulated_slip": "m",
    "status": "-", "dissipation": "J/m^2", "sigma_N_friction": "Pa", "sigma_N_effective": "Pa",
}

# Interface pair status codes (field "status"; physics/mohr_coulomb_interface.hpp).
INTERFACE_STATUS = ("stick", "slip", "open")


def column_unit(name):
    """The unit of a station or energy.csv column: t [s]; u_* [m]; v_* [m/s]; a_* [m/s^2];
    p, p_excess [Pa] (total and excess pore pressure, compression positive); s_* [Pa] and
    e_* [-] (stress and strain tensor components, -station_stress); step [-]; time
    [s]; relative_balance_error [-]; every other energy.csv column an energy, ENERGY_UNIT."""
    return _UNITS.get(name, ENERGY_UNIT)


class Table:
    """Named columns of equal length, read from a CSV with a header line.

    table["u_x"] is a column (a 1D numpy array, one value per row); table.names the column
    names in file order; len(table) the row count; table.unit(name) the column's unit."""

    def __init__(self, columns):
        self._columns = dict(columns)

    @property
    def names(self):
        return tuple(self._columns)

    def __getitem__(self, name):
        return self._columns[name]

    def __contains__(self, name):
        return name in self._columns

    def get(self, name, default=None):
        return self._columns.get(name, default)

    def __len__(self):
        return len(next(iter(self._columns.values()))) if self._columns else 0

    def unit(self, name):
        if name not in self._columns:
            raise KeyError(name)
        return column_unit(name)


def read_csv(path):
    """A slipwave CSV (a station's record, energy.csv) as a Table. A file with a header and no
    rows gives a Table of empty columns."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.size == 0:
        data = np.empty((0, len(header)))
    return Table({name: data[:, i] for i, name in enumerate(header)})


class Frames:
    """The frames of one grid of a run folder: "volume" or "interface_<name>".

    times: list of the frame times [s], in output order (only frames the XDMF index lists,
      which names complete files only: a run still going can be read).
    geometry: node coordinates [nodes, 3] [m] (z = 0 in 2D); for an interface, one node per
      node pair (the pair's position).
    topology: cells [cells, nodes per cell], node indices into geometry; topology_type the XDMF
      cell type ("Quadrilateral", "Hexahedron", ..., "Polyline" for a 2D interface).
    field(name, frame): values [rows, columns]; rows are nodes or cells (Center); columns 1
      (scalar), 3 (vector: x, y, z; z = 0 in 2D) or 9 (symmetric tensor as a row-major 3 x 3:
      xx, xy, xz, yx, yy, yz, zx, zy, zz). Units: FIELD_UNITS.
    Volume fields: displacement, velocity, acceleration (nodes), stress (cells, at the centre;
    includes the initial stress), region (cells, index of the region), pore_pressure and
    excess_pore_pressure (nodes, saturated scenes), max_shear_strain (the largest equivalent
    shear strain sqrt(2 e:e) a cell's points reached) and secant_modulus_ratio (the soil
    model's G/Gmax there; 0 and 1 outside hysteretic regions: scenes with hysteretic soil).
    Interface fields (one row per pair):
    opening, slip (tangential jump, structure minus soil, vector), sigma_N (tension positive),
    sigma_T (vector), plastic_opening, accumulated_slip (slip path), status (INTERFACE_STATUS
    codes), dissipation [J/m^2], sigma_N_friction (the friction lag's sigma*, where it is on:
    the default); saturated: pore_pressure, sigma_N_effective.
    """

    def __init__(self, out_dir, grid="volume"):
        self.out_dir = out_dir
        self.grid = grid
        index = read_index(os.path.join(out_dir, grid + ".xmf"))
        self.times, self._refs = [], []  # per frame: {field: HdfRef}
        self.topology_type = None
        for step in index.steps:
            if step.time is None:
                raise XdmfError(f"{index.path}: frame {len(self.times)} has no <Time Value>")
            self.times.append(step.time)
            self._refs.append({a.name: a.ref for a in step.attributes})
            if step.topology is not None:
                self.topology_type = step.topology.kind
        import h5py
        with h5py.File(os.path.join(out_dir, grid + ".h5"), "r") as mesh:
            self.geometry, self.topology = mesh["/geometry"][()], mesh["/topology"][()]

    def __len__(self):
        return len(self.times)

    def field_names(self, frame=0):
        return list(self._refs[frame])

    def _ref(self, name, frame):
        ref = self._refs[frame][name]
        if isinstance(ref, XdmfError):
            raise ref
        return ref

    def field(self, name, frame):
        """Field `name` of frame number `frame` (index order; negative counts from the end)."""
        import h5py
        ref = self._ref(name, frame)
        with h5py.File(os.path.join(self.out_dir, ref.file), "r") as h5:
            return h5[ref.dataset][()]

    def series(self, name):
        """Field `name` of every frame, in time order: a list of [rows, columns] arrays."""
        return [self.field(name, k) for k in range(len(self))]

    def stacked(self, names=None):
        """{field: values [frames, rows, columns]} of the fields every frame has (or of
        `names`), each frame's file opened once."""
        import h5py
        if names is None:
            names = [n for n in self.field_names(0) if all(n in refs for refs in self._refs)] if len(self) else []
        per_frame = []
        for k in range(len(self)):
            refs = {n: self._ref(n, k) for n in names}
            values = {}
            for file_name in dict.fromkeys(r.file for r in refs.values()):
                with h5py.File(os.path.join(self.out_dir, file_name), "r") as h5:
                    values.update({n: h5[r.dataset][()] for n, r in refs.items() if r.file == file_name})
            per_frame.append(values)
        return {n: np.stack([v[n] for v in per_frame]) for n in names}


class RunFolder:
    """The output folder of one slipwave run (-output_dir). What the run did not write raises
    OSError (FileNotFoundError) when asked for; the *_names() lists say what there is."""

    def __init__(self, path):
        self.path = path

    def _file(self, *parts):
        return os.path.join(self.path, *parts)

    # Stations ------------------------------------------------------------------------------

    def station_names(self):
        """Names of the stations recorded, sorted: those of stations/*.csv, else those of
        stations.h5."""
        names = sorted(os.path.splitext(os.path.basename(p))[0] for p in glob.glob(self._file("stations", "*.csv")))
        if names or not os.path.isfile(self._file("stations.h5")):
            return names
        import h5py
        with h5py.File(self._file("stations.h5"), "r") as f:
            return sorted(f)

    def station(self, name, source=None):
        """Station `name`'s record, one row per time step, as a Table: t [s]; u_x, u_y[, u_z]
        [m], v_* [m/s], a_* [m/s^2] (interpolated at the station's point; 2D has no z);
        saturated scenes add p and p_excess [Pa]; with -station_stress the stress of the
        station's cell s_xx, s_yy, s_zz, s_xy[, s_yz, s_xz] [Pa] (as the volume output shows
        it) and its strain e_xx, e_yy[, e_zz], e_xy[, e_yz, e_xz] [-] (tensor components: the
        engineering shear strain is 2 e_xy) come last. source "csv": stations/<name>.csv; "h5":
        stations.h5 (the same values); None: the CSV if there is one, else stations.h5."""
        path = self._file("stations", name + ".csv")
        if source is None:
            source = "csv" if os.path.isfile(path) or not os.path.isfile(self._file("stations.h5")) else "h5"
        if source == "csv":
            return read_csv(path)
        if source == "h5":
            return self._station_h5(name)
        raise ValueError(f"source {source!r}; allowed: 'csv', 'h5' or None")

    def _station_h5(self, name):
        import h5py
        with h5py.File(self._file("stations.h5"), "r") as f:
            g = f[name]
            columns = {"t": g["time"][()]}
            for q, dataset in (("u", "displacement"), ("v", "velocity"), ("a", "acceleration")):
                values = g[dataset][()]
                columns.update({f"{q}_{c}": values[:, i] for i, c in enumerate("xyz"[: values.shape[1]])})
            for column, dataset in (("p", "pore_pressure"), ("p_excess", "excess_pore_pressure")):
                if dataset in g:
                    columns[column] = g[dataset][()]
            for q, dataset in (("s", "stress"), ("e", "strain")):
                if dataset in g:
                    values = g[dataset][()]
                    columns.update({f"{q}_{c}": values[:, i] for i, c in enumerate(_TENSOR_COMPONENTS[values.shape[1]])})
        return Table(columns)

    def station_coordinates(self, name):
        """Station `name`'s point [m] (2 or 3 values) from stations.h5, or None without it."""
        if not os.path.isfile(self._file("stations.h5")):
            return None
        import h5py
        with h5py.File(self._file("stations.h5"), "r") as f:
            return [float(x) for x in f[name].attrs["coordinates"]]

    def stations(self):
        """{name: station(name)} for every station, in name order."""
        return {name: self.station(name) for name in self.station_names()}

    # Energy and run info -------------------------------------------------------------------

    def energy(self):
        """energy.csv as a Table, one row per evaluated step (every -energy_interval steps,
        at output times and at the last). Columns: step [-], time [s], then energies [J per m
        in 2D, J in 3D]: kinetic, strain (stored now); input_work, external_work (gravity,
        tractions, supports), absorbed (dashpots), damped (Rayleigh), anelastic (constant Q),
        interface_work, contact_damped (cumulative); interface_stored, interface_dissipated;
        stored_change (shadow energy since the start), balance_error = stored_change -
        (input_work + external_work + interface_work - absorbed - damped - anelastic -
        contact_damped) [- (fluid_inflow_work - darcy_dissipated - cavitation_work)],
        relative_balance_error [-] (over the largest energy so far); saturated scenes add
        fluid_stored, darcy_dissipated, fluid_inflow_work, cavitation_work (the pore fluid's
        work on its cavities, cumulative: docs/saturated-soil.md)."""
        return read_csv(self._file("energy.csv"))

    def run_info(self):
        """run_info.json as a dict: resolved_frequency_hz [Hz] (highest S-wave frequency the
        mesh carries), points_per_wavelength [-] (nodes per S wavelength that needs),
        slowest_region, h_min_m [m] (smallest cell), input_top_frequency_hz [Hz] (the highest of every time history of the scene: input wave, loads, DRM; 0 without
        any), time_step_s [s]; at element degree p > 1 also element_degree and
        element_size_m [m]; with hysteretic soil hysteretic_regions, per region its backbone
        (mkz, darendeli, gqh, table), gmax_pa, surfaces, strength_pa (0: no cap) and the parameters
        the backbone was built from (mkz: reference_strain, curvature, beta; darendeli:
        plasticity_index [%], ocr, mean_effective_stress_pa, frequency_hz, cycles; gqh:
        theta)."""
        with open(self._file("run_info.json")) as f:
            return json.load(f)

    # Frames --------------------------------------------------------------------------------

    def interface_names(self):
        """Names of the interfaces with frames (interface_<name>.xmf), sorted."""
        return sorted(os.path.basename(p)[len("interface_"):-len(".xmf")] for p in glob.glob(self._file("interface_*.xmf")))

    def interface(self, name):
        """The frames of interface `name` (Frames of grid interface_<name>)."""
        return Frames(self.path, "interface_" + name)

    def has_volume(self):
        return os.path.isfile(self._file("volume.xmf"))

    def volume(self):
        """The volume frames (Frames of grid volume; -output_fields 0 writes none)."""
        return Frames(self.path, "volume")
