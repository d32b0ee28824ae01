#!/bin/sh
# tests/test_hdf5.pf: reads FILE.h5 whole with h5dump, or, when h5dump
# refuses it (a run killed while it wrote the file in HDF5's SWMR mode
# leaves it marked as open for writing: src/results/results_hdf5.f90), with
# h5py as a SWMR reader, every dataset. Exit status 0 when it reads.
# usage: read_killed.sh FILE.h5
h5dump "$1" > /dev/null 2>&1 && exit 0
/usr/bin/python3 - "$1" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], 'r', swmr=True) as f:
    f.visititems(lambda name, obj: obj[()] if isinstance(obj, h5py.Dataset) else None)
PY
