# The measures of scripts/scene_metrics.py on synthetic records with closed-form answers
# (python/tests/test_scene_measures.py): the zero-phase low-pass keeps A g(f) of a sine,
# g = 1/(1 + (f/f_c)^8) (1/2 at the corner), and removes a 100 Hz line 10 times larger than
# the 5 Hz one; the largest slip excursion of piecewise-linear histories with known turning
# points, a small step back inside a slide not cutting it; the 5 %-damped PSA of a harmonic
# at each period of the floor spectra, A/(2 zeta) at resonance (0.1 %); the high-frequency
# share of every station (Parseval on whole periods) and the earlier keys kept.
set -eu
. tests/tools/lib.sh
$PY python/tests/test_scene_measures.py
