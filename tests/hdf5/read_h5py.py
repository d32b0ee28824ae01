#!/usr/bin/python3
"""Reads a results file <prefix>.h5 with h5py, the way the README shows, and
prints what it found as one line of numbers for tests/test_hdf5.pf to compare
with what the Fortran reader finds:

    rows  force_max  force_sum  peak_force_attr  summary_peak_force
    nnode  nsnap  w_peak_at_impact_node  units_are_str  status_completed

(floats with repr: 17 significant digits, they read back to the same double;
units_are_str and status_completed are 1 or 0).

Debian's interpreter (/usr/bin/python3) has h5py from python3-h5py
(tools/setup-debian); another python3 on PATH may not.
usage: read_h5py.py FILE.h5
"""
import sys

import h5py

with h5py.File(sys.argv[1], 'r') as f:
    force = f['history/force'][:]
    w_peak = f['peak/w'][:]
    impact_node = int(f['mesh'].attrs['impact_node'])       # numbered from 1
    units = f['history/force'].attrs['units']
    values = [len(force), float(force.max()), float(force.sum()),
              float(f['peak'].attrs['force']), float(f['summary'].attrs['peak_force']),
              int(f['mesh'].attrs['nnode']), f['fields/w'].shape[0],
              float(w_peak[impact_node - 1]),
              int(isinstance(units, str) and units == 'N'),
              int(f['summary'].attrs['status'] == 'completed')]
print(' '.join(repr(v) for v in values))
