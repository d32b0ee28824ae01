#!/usr/bin/python3
"""Opens <prefix>.xdmf with a real XDMF reader and writes what it found as
numbers, for tests/test_xdmf.pf to compare with the HDF5 datasets:

    reader  npoints  ncells  nodes_per_cell  nsteps      (reader: 1 ParaView, 2 meshio)
    the time of each step (s)
    x y of each point (m), one point a line
    the nodes of each cell, numbered from 0, one cell a line
    w at every point, one line per step (m)
    peak_w at every point, at the last step (m)

Floats with repr (17 significant digits: they read back to the same double).

The reader: ParaView's Python module (Debian's python3-paraview,
paraview.simple.OpenDataFile, no display needed) when it is installed,
else meshio (python3-meshio); --reader chooses one. Exit status 3 when the
reader asked for (or any, with auto) is not installed, 1 on another error.
Debian's interpreter (/usr/bin/python3) has both (tools/setup-debian).

usage: read_xdmf.py [--reader auto|paraview|meshio] FILE.xdmf OUT.txt
"""
import argparse
import os
import sys

NOT_INSTALLED = 3


def with_paraview(path):
    """(points, cells, times, w per step, peak_w at the last step) by ParaView."""
    from paraview.simple import OpenDataFile, servermanager
    from vtkmodules.numpy_interface import dataset_adapter as dsa
    # The XDMF 3 reader of ParaView 5.11 joins a file name without a
    # directory wrongly to the HDF5 file's name: give it an absolute path.
    reader = OpenDataFile(os.path.abspath(path))
    if reader is None:
        raise RuntimeError(f'ParaView has no reader for {path}')
    times = list(reader.TimestepValues or [])
    ws, peak = [], None
    points = cells = None
    for t in times:
        reader.UpdatePipeline(t)
        grid = servermanager.Fetch(reader)
        data = dsa.WrapDataObject(grid)
        if points is None:
            points = [(p[0], p[1]) for p in data.Points]
            cells = []
            for c in range(grid.GetNumberOfCells()):
                cell = grid.GetCell(c)
                cells.append([cell.GetPointId(i) for i in range(cell.GetNumberOfPoints())])
        ws.append([float(v) for v in data.PointData['w']])
        peak = [float(v) for v in data.PointData['peak_w']]
    return points, cells, times, ws, peak


def with_meshio(path):
    """The same by meshio's XDMF time-series reader."""
    import meshio
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        points, blocks = reader.read_points_cells()
        cells = [list(map(int, c)) for block in blocks for c in block.data]
        times, ws, peak = [], [], None
        for k in range(reader.num_steps):
            t, point_data, _ = reader.read_data(k)
            times.append(t)
            ws.append([float(v) for v in point_data['w']])
            peak = [float(v) for v in point_data['peak_w']]
    return [(p[0], p[1]) for p in points], cells, times, ws, peak


def installed(module):
    try:
        __import__(module)
        return True
    except ImportError:
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--reader', choices=('auto', 'paraview', 'meshio'), default='auto')
    ap.add_argument('xdmf')
    ap.add_argument('out')
    args = ap.parse_args()
    reader = args.reader
    if reader == 'auto':
        reader = 'paraview' if installed('paraview.simple') else 'meshio'
    module = 'paraview.simple' if reader == 'paraview' else 'meshio'
    if not installed(module):
        print(f'read_xdmf.py: {reader} is not installed (Debian: python3-{reader}; make setup)',
              file=sys.stderr)
        return NOT_INSTALLED
    points, cells, times, ws, peak = (with_paraview if reader == 'paraview' else with_meshio)(args.xdmf)
    print(f'read_xdmf.py: {args.xdmf}: read by {reader}: {len(points or [])} points, '
          f'{len(cells or [])} cells, {len(times)} time steps', file=sys.stderr)
    if not times:
        points, cells, peak = [], [], []
    nodes = len(cells[0]) if cells else 0
    lines = [f'{1 if reader == "paraview" else 2} {len(points)} {len(cells)} {nodes} {len(times)}',
             ' '.join(repr(float(t)) for t in times)]
    lines += [f'{x!r} {y!r}' for x, y in ((float(x), float(y)) for x, y in points)]
    lines += [' '.join(str(n) for n in c) for c in cells]
    lines += [' '.join(repr(v) for v in w) for w in ws]
    lines.append(' '.join(repr(v) for v in (peak or [])))
    with open(args.out, 'w', encoding='utf-8') as f:
        f.write('\n'.join(lines) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
