#!/usr/bin/python3
"""tests/test_hdf5.pf: reads a running run's results file with h5py as a
SWMR reader (src/results/results_hdf5.f90), twice, a second and a half
apart, and prints

    rows_first  rows_second  whole

the rows /history/time holds each time, and 1 when every row read is
whole (the times one step apart from t = 0), else 0.
usage: read_running.py FILE.h5
"""
import sys
import time

import h5py


def times(path):
    with h5py.File(path, 'r', swmr=True) as f:
        t = f['history/time'][()]
        dt = f['deck/analysis'].attrs['dt']
    return t, dt


def whole(t, dt):
    return all(abs(t[i] - i * dt) <= 1e-9 * dt * max(i, 1) for i in range(len(t)))


first, dt = times(sys.argv[1])
time.sleep(1.5)
second, dt = times(sys.argv[1])
print(len(first), len(second), 1 if whole(first, dt) and whole(second, dt) else 0)
