#!/usr/bin/python3
"""Unit tests of grid_band, the grid-convergence band of scripts/convergence_check.py, on
values that follow f(h) = f0 + C h^p exactly, whose observed order, Richardson estimate and
band are known in closed form (run by tests/cases/convergence_check_column.sh).

usage: /usr/bin/python3 python/tests/test_convergence_band.py
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from convergence_check import grid_band, summary  # noqa: E402

F0, C = 2.0, 0.3


def exact_series(hs, p):
    return [F0 + C * h ** p for h in hs]


class GridBand(unittest.TestCase):
    def test_three_levels_constant_ratio(self):
        """h = 1, 2, 4, p = 2: e32/e21 = 4, observed order ln 4 / ln 2 = 2; with the formal order
        2 the Richardson estimate is f0 exactly and the band 1.25 |f1 - f0| = 1.25 C."""
        b = grid_band(exact_series([1, 2, 4], 2), [2, 2], 2)
        self.assertAlmostEqual(b["order_observed"], 2.0, delta=1e-12)
        self.assertEqual(b["safety_factor"], 1.25)
        self.assertAlmostEqual(b["extrapolated"], F0, delta=1e-12)
        self.assertAlmostEqual(b["band"], 1.25 * C, delta=1e-12)
        self.assertAlmostEqual(b["relative_band"], 1.25 * C / (F0 + C), delta=1e-12)

    def test_three_levels_varying_ratio(self):
        """h = 1, 1.5, 3 (r21 = 1.5, r32 = 2), p = 1.3: the fixed point of Celik et al. (2008)
        recovers p = 1.3, and the estimate f0 and band 1.25 C h1^p follow."""
        b = grid_band(exact_series([1, 1.5, 3], 1.3), [1.5, 2], 2)
        self.assertAlmostEqual(b["order_observed"], 1.3, delta=1e-9)
        self.assertAlmostEqual(b["extrapolated"], F0, delta=1e-9)
        self.assertAlmostEqual(b["band"], 1.25 * C, delta=1e-9)

    def test_main_is_the_middle_level(self):
        """The main run the middle of h = 0.5, 1, 2 (p = 1): the band of f(1) is
        1.25 |f(1) - f0| = 1.25 C, Roache's coarse-grid GCI 1.25 |f1 - f2| r^p / (r^p - 1)."""
        values = exact_series([0.5, 1, 2], 1)
        b = grid_band(values, [2, 2], 1, main=1)
        self.assertEqual(b["value"], values[1])
        self.assertAlmostEqual(b["band"], 1.25 * C, delta=1e-12)
        self.assertAlmostEqual(b["band"], 1.25 * abs(values[0] - values[1]) * 2 / (2 - 1), delta=1e-12)

    def test_observed_above_formal(self):
        """p = 2 observed, formal 1: the formal order is used, f_ext = f1 - (f2 - f1) = f0 - 2 C
        and the band 1.25 |f1 - f_ext| = 1.25 * 3 C: wider than with the observed order."""
        b = grid_band(exact_series([1, 2, 4], 2), [2, 2], 1)
        self.assertAlmostEqual(b["order_observed"], 2.0, delta=1e-12)
        self.assertEqual(b["order"], 1)
        self.assertAlmostEqual(b["band"], 1.25 * 3 * C, delta=1e-12)
        self.assertIn("formal", b["note"])

    def test_two_levels(self):
        """Two levels h = 1, 2 with the formal order 1: Fs = 3, band 3 |f1 - f2| / (2 - 1) = 3 C
        for f linear in h (p = 1)."""
        b = grid_band(exact_series([1, 2], 1), [2], 1)
        self.assertIsNone(b["order_observed"])
        self.assertEqual(b["safety_factor"], 3.0)
        self.assertAlmostEqual(b["band"], 3 * C, delta=1e-12)

    def test_oscillating(self):
        """1.0, 1.2, 0.9 (finest first) oscillate: no observed order, Fs = 3 with the formal
        order 1: 3 |1.0 - 1.2| = 0.6, more than the spread 0.3."""
        b = grid_band([1.0, 1.2, 0.9], [2, 2], 1)
        self.assertIsNone(b["order_observed"])
        self.assertAlmostEqual(b["band"], 0.6, delta=1e-12)
        self.assertIn("oscillates", b["note"])

    def test_diverging(self):
        """1.0, 1.05, 1.3 -> finest pair 0.05, coarser 0.25: converging; 1.0, 1.3, 1.35: the finer
        pair differs more, not converging: Fs = 3, formal 1, band max(3 * 0.3, spread 0.35)."""
        self.assertIsNotNone(grid_band([1.0, 1.05, 1.3], [2, 2], 1)["order_observed"])
        b = grid_band([1.0, 1.3, 1.35], [2, 2], 1)
        self.assertIsNone(b["order_observed"])
        self.assertAlmostEqual(b["band"], 0.9, delta=1e-12)
        self.assertIn("does not converge", b["note"])

    def test_equal(self):
        """The same value on every level: band 0."""
        b = grid_band([1.5, 1.5, 1.5], [2, 2], 1)
        self.assertEqual(b["band"], 0.0)


class Summary(unittest.TestCase):
    def test_sorted_by_band(self):
        """Answers with relative bands 0.01 and exactly 0.05 are within 5 %, 0.3 is wider (said
        with its band), a zero value (no relative band) is listed apart."""
        bands = {"a": {"relative_band": 0.01}, "b": {"relative_band": 0.3}, "c": {"relative_band": 0.05}, "z": {"relative_band": None}}
        lines = summary(bands).splitlines()
        self.assertEqual(lines[0], "answers with a band within 5 %: a, c")
        self.assertEqual(lines[1], "answers with a wider band (read them with it): b (+-30 %)")
        self.assertEqual(lines[2], "zero on the main level (no relative band): z")

    def test_none_wider(self):
        lines = summary({"a": {"relative_band": 0.02}}).splitlines()
        self.assertEqual(lines, ["answers with a band within 5 %: a", "answers with a wider band (read them with it): none"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
