"""The Wilson score interval of k successes in n trials, as experiments/wilson_interval.hpp
computes it for the C++ reports; shared by the table scripts beside this file."""
import math


def wilson(k, n, z=1.959964):
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)
