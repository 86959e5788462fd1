"""The XDMF index of a grid as slipwave writes it (src/io/field_writer.cpp): DIR/<grid>.xmf, a
temporal collection of Uniform grids, one per output frame, whose HDF DataItems name a
dataset of an HDF5 file ("FILE:/PATH", FILE relative to the .xmf's folder).

The parse is tolerant: what an element lacks or holds malformed is kept as an XdmfError in
its place, so that a checker (scripts/check_output.py) can report it and a reader
(run_folder.Frames) can raise it.
"""
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import List, Optional, Union


class XdmfError(ValueError):
    """An XDMF element that is missing or cannot be read as slipwave writes it."""


@dataclass(frozen=True)
class HdfRef:
    """One HDF DataItem: where its values are and what shape and type the index declares."""
    file: str  # HDF5 file, relative to the .xmf's folder
    dataset: str  # path of the dataset in that file, e.g. "/geometry"
    dims: tuple  # declared Dimensions, e.g. (rows, columns)
    number_type: str  # declared NumberType: "Float", "Int", ... (XDMF default "Float")
    precision: int  # declared bytes per value (XDMF default 4)
    text: str  # "FILE:/PATH" as written


def hdf_ref(item) -> HdfRef:
    """The HdfRef of a DataItem element; XdmfError when it is absent or not an HDF reference."""
    if item is None:
        raise XdmfError("no DataItem")
    fmt = item.get("Format", "XML")
    if fmt != "HDF":
        raise XdmfError(f"DataItem Format {fmt!r}; only HDF is checked")
    text = (item.text or "").strip()
    if ":" not in text:
        raise XdmfError(f"HDF DataItem {text!r} is not FILE:/PATH")
    file_name, dataset = text.split(":", 1)
    try:
        dims = tuple(int(d) for d in item.get("Dimensions", "").split())
    except ValueError:
        raise XdmfError(f"Dimensions {item.get('Dimensions')!r} are not integers") from None
    return HdfRef(file_name, dataset, dims, item.get("NumberType", item.get("DataType", "Float")), int(item.get("Precision", "4")), text)


def _ref_or_error(item) -> Union[HdfRef, XdmfError]:
    try:
        return hdf_ref(item)
    except XdmfError as error:
        return error


@dataclass
class Part:
    """A Geometry or Topology element: its type, its other XML attributes and its data."""
    kind: Optional[str]  # GeometryType ("XYZ") or TopologyType ("Quadrilateral", "Polyline", ...)
    attributes: dict  # the element's XML attributes (NumberOfElements, NodesPerElement, ...)
    ref: Union[HdfRef, XdmfError]


@dataclass
class Attribute:
    """A field of a frame (an XDMF Attribute)."""
    name: str
    center: str  # "Node" or "Cell"
    kind: str  # AttributeType: "Scalar" (1 column), "Vector" (3), "Tensor" (9, row-major 3 x 3)
    ref: Union[HdfRef, XdmfError]


@dataclass
class Step:
    """One Uniform grid of the collection: one output frame."""
    name: str
    has_time: bool  # whether the grid has a <Time> element
    time: Optional[float]  # its Value [s]; None when absent or not a number
    time_text: Optional[str]  # the Value as written (None: none)
    geometry: Optional[Part]  # None: no Geometry element
    topology: Optional[Part]  # None: no Topology element
    attributes: List[Attribute] = field(default_factory=list)


@dataclass
class Index:
    """A parsed .xmf: whether the top grid is a collection (slipwave writes a temporal one),
    its CollectionType, and its steps in file order (the top grid itself when it is not a
    collection)."""
    path: str
    collection: bool
    collection_type: Optional[str]
    steps: List[Step]

    @property
    def folder(self):
        """The folder the DataItems' file names are relative to."""
        return os.path.dirname(os.path.abspath(self.path))


def _part(element, type_key) -> Optional[Part]:
    if element is None:
        return None
    return Part(element.get(type_key, element.get("Type")), dict(element.attrib), _ref_or_error(element.find("DataItem")))


def _step(grid) -> Step:
    time_el = grid.find("Time")
    time_text = time_el.get("Value") if time_el is not None else None
    try:
        time = float(time_text) if time_text is not None else None
    except ValueError:
        time = None
    attributes = [Attribute(a.get("Name", "?"), a.get("Center", "Node"), a.get("AttributeType", a.get("Type", "Scalar")),
                            _ref_or_error(a.find("DataItem"))) for a in grid.findall("Attribute")]
    return Step(grid.get("Name", "?"), time_el is not None, time, time_text, _part(grid.find("Geometry"), "GeometryType"), _part(grid.find("Topology"), "TopologyType"),
                attributes)


def read_index(xmf_path) -> Index:
    """Parses DIR/<grid>.xmf. OSError or xml.etree.ElementTree.ParseError when it cannot be
    read, XdmfError when it has no Domain/Grid."""
    top = ET.parse(xmf_path).getroot().find("Domain/Grid")
    if top is None:
        raise XdmfError("no Domain/Grid")
    if top.get("GridType") == "Collection":
        return Index(xmf_path, True, top.get("CollectionType"), [_step(g) for g in top.findall("Grid")])
    return Index(xmf_path, False, None, [_step(top)])
