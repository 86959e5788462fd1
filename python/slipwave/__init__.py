"""Reads the output folder of a slipwave run: stations, energy, run info, volume and interface
frames. See docs/python.md; the readers are in run_folder.py, the XDMF index in xdmf.py.

Scripts find the package relative to their own file, without installation:
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
    from slipwave import RunFolder
"""
from .run_folder import (ENERGY_UNIT, FIELD_UNITS, INTERFACE_STATUS, Frames, RunFolder, Table,  # noqa: F401
                         column_unit, read_csv)
from .xdmf import XdmfError, read_index  # noqa: F401
