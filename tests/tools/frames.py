"""The frames reader of the python/slipwave package (slipwave.Frames), under the name the
inline checks of tests/cases/*.sh import it by (`sys.path.insert(0, "tests/tools")`,
`from frames import Frames`)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import Frames  # noqa: E402,F401
