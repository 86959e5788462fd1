# Free-field site response at element degree 4 (issue 14): free_field_transfer.sh (the same
# site, input, closed form (Kramer 1996, eq. 7.32) and bounds) on one element across (4 m) and
# 20 of 2 m up (4x and 2x fewer than its 1 m cells; 2 m so the soil/rock contact is an element
# edge): the free-field sides are then the whole model's lateral support. Measured: f1 to
# 2.1e-7, |H| at the peak to 4.2e-6, the band to 4.2e-6 of 1/alpha (degree 1 with 1 m cells:
# 1.0e-4, 3.4e-4, 4.9e-4; the O((k h)^2) dispersion is gone at p = 4).
SEM_DEGREE=4 FREE_FIELD_FACES=1,20 exec bash tests/cases/free_field_transfer.sh
