#!/usr/bin/env pvpython
"""render.py: pictures of a run drawn by ParaView from its <prefix>.xdmf.

    sh postproc/xvfb-render pvpython postproc/render.py out/clamped [--size 1600x900]
    make render PREFIX_RUN=out/clamped          (the same: mk/render.mk)

Opens <prefix>.xdmf as a user does (paraview.simple.OpenDataFile) and writes

  <prefix>_render_w.png       the plate at the peak force: the XDMF's peak_w at
                              its last time step (the state of the step of the
                              largest contact force), coloured by w (mm), the
                              deflection exaggerated by the factor the picture
                              states, seen from the back face (the impactor
                              strikes the other one);
  <prefix>_render_damage.png  only for a run with &strength: the damage map seen
                              through the laminate, at each Gauss point the
                              largest failure index of any ply over the run (the
                              cells of the XDMF's laminate, damage_map; 1 =
                              failure) and, beside it, the mode of that index
                              where it reached 1, the impact point marked (a
                              cross, and a circle of the impactor's diameter).

A quarter or half model is mirrored into the whole plate (the model's own
symmetry). The titles name the scene from the deck echo at the top of
<prefix>_history.dat (edges, plate, plies, impactor mass and velocity, theory)
and the peak force and its time from <prefix>_summary.dat.

Debian 12's ParaView (5.11) aborts on a render without an X display, its
offscreen mode too: run it under xvfb-run (Debian: xvfb; tools/setup-debian
installs it with the tests' packages), with the X server's -noreset
(postproc/xvfb-render says why). pvpython or Debian's /usr/bin/python3
(python3-paraview). Exit status 0; 1 with a message on an error.
"""
import argparse
import os
import re
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

#: The failure modes of /strength (src/strength/failure_criteria.f90), and a colour each.
MODES = {1: ('fibre tension', [0.75, 0.10, 0.10]), 2: ('fibre compression', [0.95, 0.55, 0.10]),
         3: ('matrix tension', [0.20, 0.40, 0.85]), 4: ('matrix compression', [0.45, 0.75, 0.95]),
         5: ('shear 12/13', [0.20, 0.65, 0.30]), 6: ('shear 23', [0.60, 0.35, 0.70])}
CRITERIA = {'hashin': 'Hashin (1980)', 'max_stress': 'maximum stress', 'tsai_wu': 'Tsai–Wu (1971)'}
BLACK, WHITE, MARK = [0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.0, 0.35, 0.9]


class RenderError(Exception):
    pass


# ------------------------------------------------------------------ the run's words

def deck_echo(history):
    """{'group.var': value text} from the deck echo at the top of a history file."""
    text, group = {}, None
    try:
        with open(history, encoding='utf-8') as f:
            for line in f:
                if not line.startswith('#') or line.startswith('# columns'):
                    break
                m = re.match(r'#\s*&(\w+)\s+(.*)', line)
                if m:
                    group = m.group(1)
                    text[group] = m.group(2)
                elif group and re.match(r'#\s{4,}\S', line):
                    text[group] += ' ' + line[1:].strip()
    except OSError:
        return {}
    values = {}
    for group, body in text.items():
        names = list(re.finditer(r'(\w+) = ', body))
        for i, m in enumerate(names):
            end = names[i + 1].start() if i + 1 < len(names) else len(body)
            values[f'{group}.{m.group(1)}'] = body[m.end():end].strip().rstrip(',').strip()
    return values


def number(values, key, default=None):
    """The leading number of a deck value ('0.15 m' -> 0.15)."""
    m = re.match(r'[-+0-9.eE]+', values.get(key, ''))
    try:
        return float(m.group(0)) if m else default
    except ValueError:
        return default


def word(values, key, default=''):
    return values.get(key, default).strip("'")


def scene_title(values, prefix):
    """'clamped plate 150 × 100 × 2.7 mm, 20 plies; 243 g at 3 m/s; nonlinear theory'."""
    a, b, h = (number(values, f'plate.{k}') for k in 'abh')
    mass, v = number(values, 'impactor.mass'), number(values, 'impactor.velocity')
    if None in (a, b, h, mass, v):
        return os.path.basename(prefix)
    plies = len(re.findall(r'-?[0-9.]+(?:[eE][-+]?[0-9]+)?', values.get('laminate.angles', '')))
    edges = word(values, 'boundary.edges').replace('_', ' ')
    return (f'{edges} plate {a * 1e3:g} × {b * 1e3:g} × {h * 1e3:g} mm, {plies} plies; '
            f'impactor {mass * 1e3:g} g at {v:g} m/s; {word(values, "analysis.theory")} theory')


def summary(path):
    out = {}
    try:
        with open(path, encoding='utf-8') as f:
            for line in f:
                if '=' in line and not line.startswith('#'):
                    k, v = line.split('=', 1)
                    out[k.strip()] = v.strip()
    except OSError:
        pass
    return out


# ------------------------------------------------------------------ the data

def leaves(obj):
    """The datasets of a reader's output (composite or not)."""
    if obj.IsA('vtkCompositeDataSet'):
        it = obj.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            yield it.GetCurrentDataObject()
            it.GoToNextItem()
    else:
        yield obj


def read_xdmf(path):
    """(plate, laminate): the grid of the nodal fields and that of the ply fields
    (None without &strength) at the XDMF's last time step."""
    reader = simple.OpenDataFile(os.path.abspath(path))   # absolute: ParaView 5.11's XDMF 3 reader
    if reader is None:
        raise RenderError(f'ParaView has no reader for {path}')
    try:
        times = [float(t) for t in reader.TimestepValues]
    except TypeError:                                      # one time step: a number
        times = [float(reader.TimestepValues)]
    reader.UpdatePipeline(times[-1] if times else 0.0)
    plate = laminate = None
    for grid in leaves(servermanager.Fetch(reader)):
        if grid.GetPointData().GetArray('peak_w') is not None:
            plate = grid
        if grid.GetCellData().GetArray('damage_map (-)') is not None:
            laminate = grid
    if plate is None:
        raise RenderError(f'{path}: no grid with the nodal field peak_w')
    return plate, laminate


def cells_of(grid, nodes):
    """The connectivity of a grid whose cells all have `nodes` points, (ncell, nodes)."""
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    return conn.reshape(-1, nodes)


def mirrors(xy):
    """The reflections (sx, sy) that make the whole plate of a quarter or half model."""
    tol = 1e-9 * np.ptp(xy, axis=0).max()
    sx = (1, -1) if xy[:, 0].min() >= -tol else (1,)
    sy = (1, -1) if xy[:, 1].min() >= -tol else (1,)
    return [(a, b) for a in sx for b in sy]


def mirrored(xy, polys, point_arrays=None, cell_arrays=None):
    """The model mirrored into the whole plate: points, polygons (kept
    counter-clockwise) and their arrays."""
    point_arrays, cell_arrays = point_arrays or {}, cell_arrays or {}
    parts = mirrors(xy)
    pts = np.vstack([xy * [sx, sy] for sx, sy in parts])
    cells = np.vstack([(polys if sx * sy > 0 else polys[:, ::-1]) + k * len(xy)
                       for k, (sx, sy) in enumerate(parts)])
    pa = {n: np.concatenate([a] * len(parts)) for n, a in point_arrays.items()}
    ca = {n: np.concatenate([a] * len(parts)) for n, a in cell_arrays.items()}
    return pts, cells, pa, ca, len(parts) > 1


def polydata(points, polys=None, lines=None, point_arrays=None, cell_arrays=None):
    """A vtkPolyData of points (n, 3), polygons or polylines (m, k)."""
    pd = vtkPolyData()
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=1))
    pd.SetPoints(p)
    for cells, setter in ((polys, pd.SetPolys), (lines, pd.SetLines)):
        if cells is None:
            continue
        cells = np.asarray(cells, dtype=np.int64)
        ca = vtkCellArray()
        ca.SetData(numpy_to_vtkIdTypeArray(np.arange(0, cells.size + 1, cells.shape[1], dtype=np.int64), deep=1),
                   numpy_to_vtkIdTypeArray(cells.ravel(), deep=1))
        setter(ca)
    for arrays, data in ((point_arrays, pd.GetPointData()), (cell_arrays, pd.GetCellData())):
        for name, a in (arrays or {}).items():
            arr = numpy_to_vtk(np.ascontiguousarray(a), deep=1)
            arr.SetName(name)
            data.AddArray(arr)
    return pd


# ------------------------------------------------------------------ drawing

class Picture:
    """One render view, reused for every picture (a second view opens a
    second X connection, which Xvfb refused now and then), and what it shows."""

    def __init__(self, size):
        self.size = list(size)
        self.view = simple.CreateView('RenderView')
        self.view.ViewSize = self.size
        self.view.OrientationAxesVisibility = 0
        self.view.UseColorPaletteForBackground = 0
        self.view.Background = WHITE
        self.sources, self.bars = [], []
        self.k = self.size[0] / 1600                # font sizes are given for a picture 1600 pixels wide

    def points(self, size):
        return max(6, int(round(size * self.k)))

    def add(self, pd, name):
        """Shows the vtkPolyData pd; its display."""
        src = simple.TrivialProducer(registrationName=name)
        src.GetClientSideObject().SetOutput(pd)
        src.UpdatePipeline()
        self.sources.append(src)
        return simple.Show(src, self.view)

    def flat(self, pd, name):
        """pd in its true colours, unlit (a map seen from above)."""
        d = self.add(pd, name)
        d.Ambient, d.Diffuse, d.Specular = 1.0, 0.0, 0.0
        return d

    def lines(self, points, cells, name, colour, width=2.0):
        d = self.flat(polydata(points, lines=cells), name)
        d.AmbientColor = d.DiffuseColor = colour
        d.LineWidth = width
        return d

    def text(self, words, size=18, position=None, bold=False):
        t = simple.Text(Text=words)
        self.sources.append(t)
        d = simple.Show(t, self.view)
        d.Color = BLACK
        d.FontSize = self.points(size)
        d.Bold = int(bold)
        if position is None:
            d.WindowLocation = 'Upper Center'
        else:
            d.WindowLocation = 'Any Location'
            d.Position = list(position)
        return d

    def bar(self, lut, title, position, length):
        bar = simple.GetScalarBar(lut, self.view)
        bar.Title = title
        bar.ComponentTitle = ''
        bar.TitleColor = bar.LabelColor = BLACK
        bar.TitleFontSize = bar.LabelFontSize = self.points(18)
        bar.ScalarBarThickness = self.points(16)
        bar.AddRangeLabels = 0
        bar.WindowLocation = 'Any Location'
        bar.Position = list(position)
        bar.ScalarBarLength = length
        bar.Visibility = 1
        self.bars.append(bar)
        return bar

    def save(self, path):
        simple.Render(self.view)
        simple.SaveScreenshot(path, self.view, ImageResolution=self.size, TransparentBackground=0)
        print(f'written: {path}')
        for bar in self.bars:
            bar.Visibility = 0
        for src in self.sources:
            simple.Hide(src, self.view)
            simple.Delete(src)
        self.sources, self.bars = [], []

    def close(self):
        """Ends the view while the X connection is there (left to the
        interpreter's exit, pvpython ended on a GLXBadContext error)."""
        simple.Delete(self.view)
        self.view = None


def lagrange9(xi, eta):
    """The nine shape functions of src/model/shape_functions.f90 at (xi, eta), (len(xi), 9)."""
    def l3(s):
        return np.stack([0.5 * s * (s - 1), 1 - s * s, 0.5 * s * (s + 1)], axis=-1)
    ia = np.array([0, 2, 2, 0, 1, 2, 1, 0, 1])
    ib = np.array([0, 0, 2, 2, 0, 1, 2, 1, 1])
    return l3(xi)[:, ia] * l3(eta)[:, ib]


def quad9_surface(xy, cells, values, n=6):
    """The 9-node elements drawn as n x n quadrilaterals each, points and
    values by the elements' shape functions: points (m, 2), quads (k, 4),
    values (m)."""
    s = np.linspace(-1.0, 1.0, n + 1)
    xi, eta = np.meshgrid(s, s)                      # eta along rows
    phi = lagrange9(xi.ravel(), eta.ravel())          # ((n+1)^2, 9)
    pts = np.einsum('pk,ekd->epd', phi, xy[cells]).reshape(-1, 2)
    val = np.einsum('pk,ek->ep', phi, values[cells]).reshape(-1)
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    local = np.stack([j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i],
                     axis=-1).reshape(-1, 4)
    quads = (local[None, :, :] + (n + 1) ** 2 * np.arange(len(cells))[:, None, None]).reshape(-1, 4)
    return pts, quads, val


def render_w(pic, plate, values, run, path):
    """The plate at the peak force, coloured by w (mm), seen from the back face."""
    nodes = vtk_to_numpy(plate.GetPoints().GetData())[:, :2].astype(float)
    w = vtk_to_numpy(plate.GetPointData().GetArray('peak_w')).astype(float)
    pts2, quads, wm = quad9_surface(nodes, cells_of(plate, 9), w)
    xy, quads, pa, _, whole = mirrored(pts2, quads, {'w (mm)': wm * 1e3})
    wmm = pa['w (mm)']
    extent = np.ptp(xy, axis=0).max()
    wmax = float(np.abs(wmm).max()) or 1.0
    factor = float(f'{0.12 * extent / (wmax * 1e-3):.2g}')     # the largest w drawn as 12 % of the plate
    # w points the way the impactor moves, -z here (the XDMF's convention)
    surface = polydata(np.column_stack([xy, -factor * wmm * 1e-3]), polys=quads, point_arrays={'w (mm)': wmm})
    pic.add(surface, 'plate surface')
    smooth = simple.GenerateSurfaceNormals(Input=simple.Clean(Input=pic.sources[-1], Tolerance=1e-9))
    pic.sources += [smooth.Input, smooth]
    simple.Hide(pic.sources[-3], pic.view)
    d = simple.Show(smooth, pic.view)
    d.Interpolation = 'Gouraud'
    d.Specular = 0.2
    simple.ColorBy(d, ('POINTS', 'w (mm)'))
    lut = simple.GetColorTransferFunction('w (mm)')
    lut.ApplyPreset('Viridis (matplotlib)', True)
    lut.RescaleTransferFunction(min(0.0, float(wmm.min())), float(wmm.max()))
    pic.bar(lut, 'w (mm)', [0.89, 0.22], 0.5)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    frame = np.array([[lo[0], lo[1], 0], [hi[0], lo[1], 0], [hi[0], hi[1], 0], [lo[0], hi[1], 0]])
    pic.lines(frame, [[0, 1, 2, 3, 0]], 'undeformed outline', [0.45, 0.45, 0.45], 1.5)
    facts = summary(run + '_summary.dat')
    f, t = facts.get('peak_force_N'), facts.get('time_of_peak_us')
    peak = f'F = {float(f):.0f} N at t = {float(t):.0f} µs' if f and t else 'the step of the largest contact force'
    pic.text(scene_title(values, run), size=22, bold=True)
    pic.text(f'deflection w at the peak force, {peak}: largest {wmax:.3g} mm, drawn × {factor:g}; '
             'seen from the back face (the impactor strikes the other one)', size=18, position=[0.02, 0.06])
    pic.text('grey: the undeformed plate' + ('; the modelled part mirrored into the whole plate' if whole else ''),
             size=16, position=[0.02, 0.02])
    view = pic.view
    view.CameraParallelProjection = 0
    centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), -0.4 * factor * wmax * 1e-3]
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 0.5 * extent, centre[1] - 1.5 * extent, centre[2] - 0.9 * extent]
    view.CameraViewUp = [0, 0, -1]
    simple.ResetCamera(view)
    view.GetActiveCamera().Zoom(1.35)
    pic.save(path)


def projected_damage(laminate):
    """The damage map seen through the laminate: per Gauss point its planar
    cell (4 corners x, y), the largest index of its plies and faces, that
    index's mode and ply."""
    cells = cells_of(laminate, 8)
    pts = vtk_to_numpy(laminate.GetPoints().GetData())
    arr = {n: vtk_to_numpy(laminate.GetCellData().GetArray(n)) for n in ('damage_map (-)', 'damage_mode', 'ply')}
    nply = int(arr['ply'].max())
    fi = arr['damage_map (-)'].reshape(-1, 2 * nply)
    best = fi.argmax(axis=1)
    rows = np.arange(len(fi))
    corners = cells[::2 * nply, 4:8]                 # the upper face of each point's first cell (module header
    xy = pts[corners.ravel(), :2].astype(float)      # of src/results/xdmf_plies.f90)
    quads = np.arange(len(xy)).reshape(-1, 4)
    return (xy, quads, fi[rows, best], arr['damage_mode'].reshape(-1, 2 * nply)[rows, best],
            arr['ply'].reshape(-1, 2 * nply)[rows, best])


def render_damage(pic, laminate, values, run, path):
    """The damage map: the largest index through the thickness, and its mode."""
    xy0, quads0, fi0, mode0, ply0 = projected_damage(laminate)
    failed_mode = np.where(fi0 >= 1.0, mode0, 0).astype(float)
    xy, quads, _, ca, whole = mirrored(xy0, quads0, cell_arrays={'failure index (-)': fi0, 'mode': failed_mode})
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    width, height = hi - lo
    shift = 1.4 * width                              # the mode map beside the index map, room for a bar
    aspect = pic.size[0] / pic.size[1]
    # the parallel scale: the maps take 62 % of the height (titles above, notes below) or 96 % of the width
    scale = max(height / 0.62, (shift + 1.4 * width) / aspect / 0.96) / 2
    cx = lo[0] + 0.5 * (shift + 1.4 * width)
    cy = lo[1] + 0.5 * height + (0.5 - 0.45) * 2 * scale
    def at(x, y):                                    # world -> the view's normalised coordinates
        return [0.5 + (x - cx) / (2 * scale * aspect), 0.5 + (y - cy) / (2 * scale)]
    for k, name in enumerate(('failure index (-)', 'mode')):
        pts = np.column_stack([xy[:, 0] + k * shift, xy[:, 1], np.zeros(len(xy))])
        d = pic.flat(polydata(pts, polys=quads, cell_arrays={name: ca[name]}), name)
        simple.ColorBy(d, ('CELLS', name))
        frame = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]]) + [k * shift, 0]
        pic.lines(np.column_stack([frame, np.full(4, 1e-5)]), [[0, 1, 2, 3, 0]], f'outline {k}', BLACK, 1.5)
        mark_impact(pic, values, k * shift, f'impact {k}')
    # the index: the palette of postproc/damage_map.gp, 2 and above black
    lut = simple.GetColorTransferFunction('failure index (-)')
    lut.ColorSpace = 'RGB'
    lut.RGBPoints = [0.0, 1, 1, 1, 0.5, 1, 1, 0, 1.0, 1, 0, 0, 2.0, 0, 0, 0]
    lut.AutomaticRescaleRangeMode = 'Never'
    lut.UseAboveRangeColor = 1
    lut.AboveRangeColor = BLACK
    length = height / (2 * scale)
    pic.bar(lut, 'failure index (-)', at(hi[0] + 0.05 * width, lo[1]), length)
    # the mode: categories
    mlut = simple.GetColorTransferFunction('mode')
    mlut.InterpretValuesAsCategories = 1
    ann, colours = [], []
    for m in sorted(set(int(m) for m in failed_mode)):
        label, colour = MODES.get(m, ('index < 1', [0.9, 0.9, 0.9]))
        ann += [str(m), label]
        colours += colour
    mlut.Annotations = ann
    mlut.IndexedColors = colours
    bar = pic.bar(mlut, 'mode where the index ≥ 1', at(hi[0] + shift + 0.1 * width, lo[1]), length)
    bar.TextPosition = 'Ticks left/bottom, annotations right/top'
    crit = CRITERIA.get(word(values, 'strength.criterion', 'hashin'), word(values, 'strength.criterion'))
    k = int(np.argmax(fi0))
    pic.text(scene_title(values, run), size=22, bold=True)
    pic.text(f'damage map, {crit} criterion: the largest failure index of any ply at each Gauss point over the run '
             f'(1 = failure)', size=18, position=at(lo[0], hi[1] + 0.13 * height))
    pic.text(f'left: the index, largest {fi0[k]:.3g} (ply {int(ply0[k])} from the impacted face, '
             f'{MODES.get(int(mode0[k]), ("?",))[0]}); right: its mode where it reached 1',
             size=18, position=at(lo[0], hi[1] + 0.04 * height))
    pic.text('blue: the impact point and a circle of the impactor\'s diameter'
             + ('; the modelled part mirrored into the whole plate' if whole else ''), size=16,
             position=[0.02, 0.02])
    view = pic.view
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = [cx, cy, 0]
    view.CameraPosition = [cx, cy, 10 * width]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = scale
    pic.save(path)


def mark_impact(pic, values, dx, name):
    """A cross at the impact point and a circle of the impactor's diameter."""
    x0, y0 = number(values, 'impactor.x0', 0.0), number(values, 'impactor.y0', 0.0)
    r = 0.5 * number(values, 'impactor.diameter', 0.0127)
    t = np.linspace(0, 2 * np.pi, 49)
    ring = np.column_stack([x0 + dx + r * np.cos(t), y0 + r * np.sin(t), np.full(49, 2e-5)])
    pic.lines(ring, [list(range(49))], name + ' ring', MARK, 2.5)
    c = 0.8 * r
    cross = np.array([[x0 + dx - c, y0, 2e-5], [x0 + dx + c, y0, 2e-5], [x0 + dx, y0 - c, 2e-5],
                      [x0 + dx, y0 + c, 2e-5]])
    pic.lines(cross, [[0, 1], [2, 3]], name + ' cross', MARK, 2.5)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('prefix', help="the run's prefix (out/clamped: out/clamped.xdmf, _history.dat, ...)")
    ap.add_argument('--size', default='1600x900', help='the pictures, width x height in pixels (1600x900)')
    a = ap.parse_args()
    try:
        size = tuple(int(s) for s in a.size.lower().split('x'))
        if len(size) != 2 or min(size) < 100:
            raise ValueError
    except ValueError:
        print(f'render.py: --size {a.size}: expected WIDTHxHEIGHT, at least 100x100', file=sys.stderr)
        return 1
    prefix = a.prefix[:-5] if a.prefix.endswith('.xdmf') else a.prefix
    xdmf = prefix + '.xdmf'
    if not os.path.exists(xdmf):
        print(f'render.py: {xdmf} not found (a run with &output hdf5 and xdmf writes it)', file=sys.stderr)
        return 1
    values = deck_echo(prefix + '_history.dat')
    try:
        plate, laminate = read_xdmf(xdmf)
        pic = Picture(size)
        render_w(pic, plate, values, prefix, prefix + '_render_w.png')
        if laminate is None:
            print(f'render.py: {xdmf} has no ply fields (a run without &strength): no damage map')
        else:
            render_damage(pic, laminate, values, prefix, prefix + '_render_damage.png')
        pic.close()
    except RenderError as e:
        print(f'render.py: {e}', file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
