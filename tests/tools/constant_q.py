"""The fitted constant-Q body of a run, read from its report, and its complex modulus from the
definition M(w)/M_U = 1 - sum_l Y_l w_l / (w_l + i w) (exp(i w t) convention; see
include/slipwave/physics/constant_q.hpp), for the tests' closed forms."""
import re

import numpy as np


def model_from_report(text, region):
    """(relaxation frequencies [Hz], weights Y_l, reference frequency [Hz]) of a region."""
    block = text[text.index(f"region {region}: constant-Q"):]
    m = re.search(r"weight Y_l\):(.*); reference ([0-9.eE+-]+) Hz", block)
    pairs = re.findall(r"([0-9.eE+-]+): ([0-9.eE+-]+)", m.group(1))
    return np.array([float(a) for a, _ in pairs]), np.array([float(b) for _, b in pairs]), float(m.group(2))


def modulus_ratio(f, fl, weights):
    """M(f)/M_U."""
    w = 2 * np.pi * np.asarray(f, dtype=float)[..., None]
    wl = 2 * np.pi * fl
    return 1 - np.sum(weights * wl / (wl + 1j * w), axis=-1)


def complex_speed(f, fl, weights, f_ref, c_ref):
    """sqrt(M(f)/rho) for a material whose phase speed at f_ref is c_ref: the unrelaxed speed
    is c_ref Re[(M(f_ref)/M_U)^(-1/2)]."""
    c_unrelaxed = c_ref * np.real(1 / np.sqrt(modulus_ratio(f_ref, fl, weights)))
    return c_unrelaxed * np.sqrt(modulus_ratio(f, fl, weights))
