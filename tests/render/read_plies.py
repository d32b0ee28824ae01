#!/usr/bin/python3
"""Opens the <prefix>.xdmf of a run with &strength with a real XDMF reader and
writes what it found of the ply fields (src/results/xdmf_plies.f90) as
numbers, for tests/test_render.pf to compare with /strength of <prefix>.h5:

    reader  narrays  npts  ncell  nplate            (reader: 1 ParaView, 2 meshio)
    zmin zmax                                       the laminate's z (m)
    per cell: ply face damage_mode damage_map peak_sigma_11 peak_failure_index onset_time
    per Gauss point: xmin xmax ymin ymax            its cell in the plane (that of ply 1, face 1)
    peak_w at every node of the plate's grid        (the nodal fields, beside the laminate)

narrays counts the cell arrays found under the names the grid gives them,
with their units (NAMES below); a missing one is not an error here, the
test counts them. Floats with repr (they read back to the same double).

ParaView: paraview.simple.OpenDataFile (the reader a user gets, XDMF 3 "S"),
the laminate and the plate are the blocks with the cell array
'damage_map (-)' and the point array 'peak_w'. meshio: its time-series
reader reads the plate (the last temporal collection, "fields"); the
laminate is the collection "plies", given to the same reader (README,
"Looking at the fields"). Exit status 3 when the reader is not installed.

usage: read_plies.py --reader paraview|meshio FILE.xdmf OUT.txt
"""
import argparse
import os
import sys

NOT_INSTALLED = 3
NAMES = ('ply', 'face', 'damage_mode', 'ply_angle (deg)', 'damage_map (-)', 'onset_time (s)',
         'peak_sigma_11 (Pa)', 'peak_sigma_22 (Pa)', 'peak_tau_12 (Pa)', 'peak_tau_23 (Pa)', 'peak_tau_13 (Pa)',
         'peak_failure_index (-)')
PER_CELL = ('ply', 'face', 'damage_mode', 'damage_map (-)', 'peak_sigma_11 (Pa)', 'peak_failure_index (-)',
            'onset_time (s)')


def with_paraview(path):
    """(points, hexahedra, {name: cell array}, peak_w)."""
    from paraview.simple import OpenDataFile, servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = OpenDataFile(os.path.abspath(path))
    try:
        times = [float(t) for t in reader.TimestepValues]
    except TypeError:
        times = [float(reader.TimestepValues)]
    reader.UpdatePipeline(times[-1])
    out = servermanager.Fetch(reader)
    laminate = plate = None
    it = out.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        grid = it.GetCurrentDataObject()
        if grid.GetCellData().GetArray('damage_map (-)') is not None:
            laminate = grid
        if grid.GetPointData().GetArray('peak_w') is not None:
            plate = grid
        it.GoToNextItem()
    if laminate is None or plate is None:
        raise RuntimeError('ParaView shows no block with damage_map (-) or none with peak_w')
    cd = laminate.GetCellData()
    arrays = {cd.GetArrayName(i): vtk_to_numpy(cd.GetArray(i)) for i in range(cd.GetNumberOfArrays())}
    hexes = vtk_to_numpy(laminate.GetCells().GetConnectivityArray()).reshape(-1, 8)
    return (vtk_to_numpy(laminate.GetPoints().GetData()), hexes, arrays,
            vtk_to_numpy(plate.GetPointData().GetArray('peak_w')))


def with_meshio(path):
    import meshio
    with meshio.xdmf.TimeSeriesReader(path) as reader:    # the plate: mesh and "fields"
        reader.read_points_cells()
        _, point_data, _ = reader.read_data(reader.num_steps - 1)
        peak_w = point_data['peak_w']
    with meshio.xdmf.TimeSeriesReader(path) as reader:    # the laminate: the collection "plies"
        plies = reader.domain.find("Grid[@Name='plies']")
        reader.collection, reader.mesh_grid = list(plies), plies[0]
        points, blocks = reader.read_points_cells()
        _, _, cell_data = reader.read_data(reader.num_steps - 1)
    hexes = [b.data for b in blocks if b.type == 'hexahedron'][0]
    return points, hexes, {name: data[0] for name, data in cell_data.items()}, peak_w


def installed(module):
    try:
        __import__(module)
        return True
    except ImportError:
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--reader', choices=('paraview', 'meshio'), required=True)
    ap.add_argument('xdmf')
    ap.add_argument('out')
    args = ap.parse_args()
    module = 'paraview.simple' if args.reader == 'paraview' else 'meshio'
    if not installed(module):
        print(f'read_plies.py: {args.reader} is not installed (make setup)', file=sys.stderr)
        return NOT_INSTALLED
    points, hexes, arrays, peak_w = (with_paraview if args.reader == 'paraview' else with_meshio)(args.xdmf)
    found = [n for n in NAMES if n in arrays]
    print(f'read_plies.py: {args.xdmf}: {args.reader}: {len(points)} points, {len(hexes)} hexahedra, '
          f'arrays {sorted(arrays)}', file=sys.stderr)
    nply = int(max(arrays['ply']))
    lines = [f'{1 if args.reader == "paraview" else 2} {len(found)} {len(points)} {len(hexes)} {len(peak_w)}',
             f'{float(points[:, 2].min())!r} {float(points[:, 2].max())!r}']
    for c in range(len(hexes)):
        lines.append(' '.join(repr(float(arrays[n][c])) if n in arrays else '0' for n in PER_CELL))
    for first in hexes[::2 * nply]:
        xy = points[first, :2]
        lines.append(' '.join(repr(float(v)) for v in (xy[:, 0].min(), xy[:, 0].max(), xy[:, 1].min(),
                                                         xy[:, 1].max())))
    lines.append(' '.join(repr(float(v)) for v in peak_w))
    with open(args.out, 'w', encoding='utf-8') as f:
        f.write('\n'.join(lines) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
