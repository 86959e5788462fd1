#!/usr/bin/python3
"""Unit tests of the measures of scripts/scene_metrics.py on synthetic records whose answers
are known in closed form (run by tests/cases/scene_metrics_measures.sh).

usage: /usr/bin/python3 python/tests/test_scene_measures.py
"""
import math
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
sys.path.insert(0, os.path.join(HERE, ".."))
import scene_metrics as sm  # noqa: E402
from slipwave import Table  # noqa: E402


def gain(f, f_cut):
    """The low-pass's gain, |4th-order Butterworth|^2 (what the filter run forward and backward gives)."""
    return 1.0 / (1.0 + (f / f_cut) ** 8)


def tapered(t, duration, ramp):
    """1 in the middle, cosine ramps of `ramp` seconds at both ends of [0, duration]."""
    return np.where(t < ramp, 0.5 - 0.5 * np.cos(np.pi * t / ramp),
                    np.where(t > duration - ramp, 0.5 - 0.5 * np.cos(np.pi * (duration - t) / ramp), 1.0))


class LowPassedPeak(unittest.TestCase):
    """A sine of amplitude A at f through the zero-phase low-pass keeps A g(f), g = 1/(1 +
    (f/f_c)^8): g = 1 - 2.6e-6 at f_c/5, 0.99611 at f_c/2, exactly 1/2 at f_c. The record is
    20 s at 1 kHz with 2 s cosine ramps at the ends: in the flat middle it is a pure sine
    whose crests fall on samples, and the filter's impulse response (about 1/f_c = 0.04 s
    long) reaches the ramps only through its tail, so the middle's amplitude is A g(f) to
    better than 1e-4 (measured 3.7e-5 at f_c; an abrupt start instead puts 0.60 A, not
    0.50 A, at f_c: the onset's spectrum passes)."""
    F_CUT = 25.0
    DT, DURATION, RAMP = 1e-3, 20.0, 2.0

    def setUp(self):
        self.t = np.arange(0.0, self.DURATION + self.DT / 2, self.DT)
        self.envelope = tapered(self.t, self.DURATION, self.RAMP)

    def test_sines_keep_their_gain(self):
        for f in (5.0, 12.5, 25.0):
            with self.subTest(f=f):
                a = 2.0 * self.envelope * np.sin(2 * np.pi * f * self.t)
                peak = sm.low_passed_peak(self.t, a, self.F_CUT)
                self.assertLess(abs(peak / (2.0 * gain(f, self.F_CUT)) - 1), 1e-4)

    def test_high_frequency_removed(self):
        """1 at 5 Hz plus 10 at 100 Hz = 4 f_c: the peak falls from over 10 to the 5 Hz sine's
        g(5) within what is left of the 100 Hz line, 10 g(100) = 1.5e-4."""
        a = self.envelope * (np.sin(2 * np.pi * 5 * self.t) + 10 * np.sin(2 * np.pi * 100 * self.t))
        self.assertGreater(np.max(np.abs(a)), 10.0)
        peak = sm.low_passed_peak(self.t, a, self.F_CUT)
        self.assertLessEqual(abs(peak - gain(5, self.F_CUT)), 10 * gain(100, self.F_CUT))


class SlipExcursion(unittest.TestCase):
    """The largest one-way slide of a mean-slip history made of straight legs between known
    turning points (piecewise linear, 100 samples a second)."""

    def history(self, knots_t, knots_s):
        t = np.linspace(knots_t[0], knots_t[-1], int(round(100 * (knots_t[-1] - knots_t[0]))) + 1)
        return t, np.interp(t, knots_t, knots_s)

    def test_largest_leg(self):
        """0 -> 3 -> 1 -> 5, held, -> 4 cm: the largest slide is 1 -> 5 = 4 cm; the range 5 cm.
        While held at 5 cm the slip jitters down by 0.1 cm (sin^2, 3 times a second: 6
        reversals of 0.1 cm, below the gate of 5 % of 5 cm) and never above 5 cm."""
        t, s = self.history([0, 1, 2, 3, 4, 5], [0.0, 0.03, 0.01, 0.05, 0.05, 0.04])
        held = (t > 3) & (t < 4)
        s[held] -= 0.001 * np.sin(3 * np.pi * (t[held] - 3)) ** 2
        self.assertAlmostEqual(sm.largest_excursion(s), 0.04, delta=1e-15)
        self.assertAlmostEqual(float(np.ptp(s)), 0.05, delta=1e-15)
        self.assertEqual(len(sm.reversals(s, 0.05 * 0.05)), 5)  # the start, 3, 1, 5 cm and the end: the jitter is gone

    def test_small_reversal_does_not_cut_a_slide(self):
        """0 -> 3 -> 1 -> 3 -> 2.9 -> 5 -> 4 cm: the 0.1 cm step back inside the 1 -> 5 slide is
        below the gate (5 % of 5 cm), so the slide is 4 cm; with no gate it is cut into 2 and
        2.1 cm, and the largest leg is the first, 3 cm."""
        t, s = self.history([0, 1, 2, 2.5, 2.6, 3, 4], [0.0, 0.03, 0.01, 0.03, 0.029, 0.05, 0.04])
        self.assertAlmostEqual(sm.largest_excursion(s), 0.04, delta=1e-15)
        self.assertAlmostEqual(sm.largest_excursion(s, gate_share=0.0), 0.03, delta=1e-15)

    def test_one_way(self):
        """A monotone slide of 2 cm is one excursion of 2 cm; a history at rest has none."""
        t, s = self.history([0, 2], [0.0, -0.02])
        self.assertAlmostEqual(sm.largest_excursion(s), 0.02, delta=1e-15)
        self.assertEqual(sm.largest_excursion(np.zeros(50)), 0.0)


class FloorSpectrum(unittest.TestCase):
    """At resonance, a = A sin(2 pi t / T) from rest, the 5 %-damped oscillator of period T
    reaches the steady amplitude A / (2 zeta w^2), PSA = A / (2 zeta) = 10 A, monotonically
    (Chopra, Dynamics of Structures, sec. 3.2); over 60 cycles the transient is down to
    exp(-2 pi 0.05 60) = 6e-9. Sampled at T/200 the peak between samples loses (w dt)^2/8 =
    1e-4: 0.1 % (the bound of tests/cases/response_spectrum.sh). Each key's period is
    checked with its own record."""

    def test_each_period(self):
        self.assertEqual(sm.SPECTRUM_PERIODS, (0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0))
        amplitude = 3.0
        for T in sm.SPECTRUM_PERIODS:
            with self.subTest(T=T):
                t = np.arange(0, 60 * 200 + 1) * (T / 200)
                psa = sm.psa_keys("block_top", t, amplitude * np.sin(2 * np.pi * t / T))
                self.assertEqual(sorted(psa), sorted(f"block_top_psa_{p:g}s" for p in sm.SPECTRUM_PERIODS))
                self.assertLess(abs(psa[f"block_top_psa_{T:g}s"] / (10 * amplitude) - 1), 1e-3)


class StationMeasures(unittest.TestCase):
    """station_measures on synthetic records of every station of the default scene plus one
    more: the earlier keys are kept, the floor and free-field spectra and low-passed peaks
    are there, and every station has its high-frequency shares."""
    DT = 1e-3

    def records(self, duration=4.0, ramp=0.0):
        """`duration` whole seconds: 5 Hz and 50 Hz have whole periods, on DFT bins; with
        ramp > 0 cosine ramps of that length [s] at both ends."""
        t = np.arange(0, int(round(duration / self.DT))) * self.DT
        envelope = tapered(t, t[-1], ramp) if ramp > 0 else 1.0
        slow, fast = envelope * np.sin(2 * np.pi * 5 * t), envelope * np.sin(2 * np.pi * 50 * t)
        theta = 0.01 * np.sin(2 * np.pi * t)  # rocking angle [rad]

        def record(a_x, a_y, u_y=None):
            return Table({"t": t, "u_y": np.zeros_like(t) if u_y is None else u_y, "a_x": a_x, "a_y": a_y})

        return {
            "block_top": record(slow + fast, np.zeros_like(t)),
            "block_base_left": record(slow, slow, -2.75 * theta),
            "block_base_right": record(slow, fast, 2.75 * theta),
            "free_field": record(2 * slow, np.zeros_like(t)),
            "bedrock": record(fast, np.zeros_like(t)),
            "pier": record(slow + 3 * fast, slow),
        }

    def test_keys_and_values(self):
        m = sm.station_measures(self.records(), 25.0)
        # earlier keys
        for key in ("peak_rocking_angle", "peak_structure_acceleration", "free_field_pga", "free_field_psa_0.1s",
                    "free_field_psa_0.3s", "free_field_psa_1s", "high_frequency_share_free_field", "high_frequency_share_block_top"):
            self.assertIn(key, m)
        # rocking: (u_y right - u_y left) / 5.5 m = theta, peak 0.01 rad (theta's crest at t = 0.25 s is a sample)
        self.assertAlmostEqual(m["peak_rocking_angle"], 0.01, delta=1e-15)
        # the tilt after shaking: theta's mean over the last 2 s, two whole periods of the 1 Hz
        # sine (trapezoids over whole periods of a sampled sine sum to zero), not its last
        # sample; the rocking left: its half range there, the crests at 2.25 and 3.25 s (samples)
        self.assertAlmostEqual(m["tilt_after_shaking"], 0.0, delta=1e-15)
        self.assertAlmostEqual(m["rocking_at_end"], 0.01, delta=1e-15)
        # a ramp: its mean over the window is its value at the window's middle
        t = np.arange(0, 4001) * 1e-3
        mean, half = sm.tail_window(t, 2 + 3 * t)
        self.assertAlmostEqual(mean, 2 + 3 * 3.0, delta=1e-12)
        self.assertAlmostEqual(half, 3.0, delta=1e-12)
        self.assertAlmostEqual(m["free_field_pga"], 2.0, delta=1e-12)  # crest of 2 sin(2 pi 5 t) at t = 0.05 s, a sample
        for name in ("block_top", "free_field"):
            for T in sm.SPECTRUM_PERIODS:
                self.assertIn(f"{name}_psa_{T:g}s", m)
            self.assertIn(f"{name}_peak_acceleration_lowpassed", m)
        self.assertEqual(m["lowpass_frequency_hz"], 25.0)
        self.assertEqual(m["resolved_frequency_hz"], 25.0)
        # Parseval on whole periods (each sine on one DFT bin): the share of power above 25 Hz is
        # the 50 Hz sines' share of sum A^2: equal amplitudes 1/2, 3 against 1: 9/10.
        expected = {"block_top": 0.5, "block_base_left": 0.0, "block_base_right": 0.0, "free_field": 0.0, "bedrock": 1.0, "pier": 0.9}
        expected_y = {"block_top": 0.0, "block_base_left": 0.0, "block_base_right": 1.0, "free_field": 0.0, "bedrock": 0.0, "pier": 0.0}
        for name in expected:
            self.assertAlmostEqual(m[f"high_frequency_share_{name}"], expected[name], delta=1e-12)
            self.assertAlmostEqual(m[f"high_frequency_share_{name}_y"], expected_y[name], delta=1e-12)

    def test_lowpass_corner(self):
        """A corner of its own (the coarsest level's, in scripts/convergence_check.py): the
        block top's 5 Hz + 50 Hz record (20 s, 2 s cosine ramps at its ends, as in LowPassedPeak)
        low-passed at 10 Hz keeps the 5 Hz sine, g(5) = 0.996, to 1e-4 (LowPassedPeak's
        bound) plus at most g(50) = 2.6e-6 of the 50 Hz one; the free field's 2 sin(2 pi 5 t),
        2 g(5)."""
        m = sm.station_measures(self.records(duration=20.0, ramp=2.0), 25.0, f_lowpass=10.0)
        self.assertEqual(m["lowpass_frequency_hz"], 10.0)
        self.assertLess(abs(m["block_top_peak_acceleration_lowpassed"] - gain(5, 10)), gain(50, 10) + 1e-4)
        self.assertLess(abs(m["free_field_peak_acceleration_lowpassed"] / (2 * gain(5, 10)) - 1), 1e-4)


if __name__ == "__main__":
    unittest.main(verbosity=2)
