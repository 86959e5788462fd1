"""Observed convergence rates and their bounds, shared by tests/cases/sem_convergence_*.sh."""
import math


def rates(errors, counts):
    """Observed orders between consecutive runs: log(e_i / e_i+1) / log(n_i+1 / n_i), n the
    number of elements (or of steps) along the refined direction."""
    return [math.log(errors[i] / errors[i + 1]) / math.log(counts[i + 1] / counts[i]) for i in range(len(errors) - 1)]


def space_ok(label, degree, counts, errors, time_change=None, order=None, margin=0.3):
    """Prints one line; True when every rate is >= order - margin (order: p + 1 by default)
    and, where given, the field change between dt and 2 dt on the finest mesh (3x the time
    error at dt for a second-order scheme) is at most 0.1 of the error there, so the time
    error moves a rate by at most 0.05."""
    order = degree + 1 if order is None else order
    observed = rates(errors, counts)
    good = min(observed) >= order - margin and (time_change is None or time_change <= 0.1 * errors[-1])
    timing = "" if time_change is None else f"; field change at 2 dt {time_change:.1e} (bound {0.1 * errors[-1]:.1e})"
    print(f"p = {degree}: {label}: errors {' '.join(f'{e:.3e}' for e in errors)}; rates {' '.join(f'{r:.2f}' for r in observed)} "
          f"(bound >= {order - margin:.1f}){timing} {'ok' if good else 'FAIL'}")
    return good


def cases(args):
    """The tests' case words DEGREE:RUN,RUN,...:STEP as (degree, [RUN, ...], STEP)."""
    for word in args:
        degree, runs, step = word.split(":")
        yield int(degree), runs.split(","), step
