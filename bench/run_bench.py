#!/usr/bin/env python3
"""make bench: the speed-accuracy trade of ./impact, measured.

Runs a grid of scenes of the paper's plate (Choi, Hong & Lee 1991: 150 x 100 x
2.7 mm [0/45/0/-45/0]2s, 243 g at 3 m/s, quarter model) over meshes, time
steps, tolerances (cr1, cr2), iteration schemes ('paper', 'fast') and storage
('band', 'skyline'), and writes (DOCS: --docs-dir, RESULTS: --results)

  RESULTS                        one row per run and sweep (columns: header)
  DOCS/performance/pareto.png    error against CPU time, the paper's scene,
                                 one curve per knob (postproc/bench_pareto.gp)
                                 (and knobs.png: the time step and tolerances)
  DOCS/performance/scenes.png    the same for the four scenes, largest error
  DOCS/performance/cost.png      CPU time per step against freedoms, log-log,
                                 with the fitted slope (postproc/bench_cost.gp)
  DOCS/PERFORMANCE.md            docs/PERFORMANCE.md with its block bench
                                 (between the bench:begin and bench:end
                                 comments, impact_files.fill_file) filled:
                                 measured figures, scheme agreement,
                                 recommended settings per accuracy

DOCS is out/docs and RESULTS out/bench/results.dat by default (make bench,
everyday: the checkout is left as it was); make docs gives docs and
bench/results.dat, the published ones (docs/PERFORMANCE.md filled in
place). The quick grid never writes those: --quick with either is refused.

Scenes: CN clamped nonlinear (the paper's scene), CL clamped linear, SN simply
supported nonlinear, SL simply supported linear. The error measures need the
first contact, so the runs stop at t_end = 2.1 ms (clamped: first contact
ends near 1.8-1.9 ms) or 1.7 ms (simply supported: the first contact ends
near 0.33 ms; the force peak comes in the second contact, near 1.03 ms
(SN) or 1.57 ms (SL), the largest deflection near 1.1-1.3 ms; the later
peaks of that contact are lower); the paper's own 3 ms scene is run as well.

Measures (from the history, every step written):
  peak force     largest force, refined by the parabola through the largest
                 sample and its neighbours (removes the O(dt^2) sampling error)
  duration       of the first contact: from t = 0 to the time the indentation
                 falls to the permanent indentation alpha0 = beta (alpha_m -
                 alpha_p) (eq. 12), interpolated linearly between the last
                 step in contact and the first out of it
  max deflection largest plate deflection at the impact point, refined like
                 the peak force
Model: every deck states the element's transverse shear and the contact
load (shear_rule = 'mitc9', load = 'hertz': the converged model, the
defaults since 25e00dd), so that the bench does not change when the defaults
do. The sweep mesh_1991 runs the paper's own model (shear_rule =
'selective', load = 'point') on the clamped scenes' meshes 4x6 to 16x24, for
comparison (errors against the converged model's reference). The sweep
mesh_dt refines the mesh and the step together (8x12 and 12x18 at 1.25 us):
the one-knob sweeps leave the other error at its 6x9 or 2.5 us value.
Reference (per scene): the additive error model q(h, dt) = q* + e_h + e_dt with
the iteration error made negligible (scheme 'fast', cr2 = 1e-10 for the
nonlinear scenes; the linear fast scheme solves its contact equation to
rounding): q* = R_h + R_dt - q0, where q0 is the 6x9, 2.5 us run, R_h the
Richardson extrapolation of the meshes 6x9, 12x18, 24x36 at 2.5 us and R_dt
that of the steps 1.25, 0.625, 0.3125 us on 6x9, each with its observed order
p = log2((q1 - q2)/(q2 - q3)), applied when the sequence converges
monotonically with 0.5 <= p <= 4 (P_RANGE); else the finest run stands for
that limit, and PERFORMANCE.md says which sequence and why (not monotone, not
converging, p out of range). The orders of two more sequences are reported
as checks, not used: the meshes 4x6, 8x12, 16x24 and the steps 2.5, 1.25,
0.625 us. Errors are relative, |q - q*| / |q*|.

CPU time: each run is repeated (--repeat, default 3) and the median of the
CPU times ./impact reports is kept (cpu_s of the summary: set-up and time loop;
the set-up alone is printed on standard output); the runs only the references
and the mesh_1991 comparison need run once, and so does the 48x72 cost run
(its set-up, the factorization, takes most of a minute). Runs are one at a
time (impact_files.run_many, one job). A run that stops (an iteration that
cannot converge at its tolerances) is recorded with status 'failed'.

Scheme agreement: every pair of runs that differ only in the scheme is
compared against the stated tolerance 3 max(cr1, sqrt(cr2)) (pair_tolerance).

Usage: python3 bench/run_bench.py [--repeat N] [--quick] [--reuse] [--docs-dir DIR] [--results FILE]
  --quick   a small grid (minutes): checks the machinery, not for the record
            (refused with --docs-dir docs or --results bench/results.dat)
  --docs-dir DIR   where PERFORMANCE.md and performance/ go (default out/docs)
  --results FILE   the table of every run (default out/bench/results.dat)
  --reuse   keep the runs of an earlier bench in build/bench/runs whose deck
            is unchanged (development); the default reruns everything
Environment: BENCH_OPENBLAS=<dir holding libblas.so.3 and liblapack.so.3 of
  OpenBLAS> adds the paper's scene and the kernel timings with that BLAS
  (found automatically in /usr/lib/x86_64-linux-gnu/openblas-*). When the
  system's BLAS (Debian's alternatives, tools/setup-debian) already is
  OpenBLAS, the other BLAS is the reference one
  (/usr/lib/x86_64-linux-gnu/blas and lapack). Which BLAS each run loaded is
  recorded (the real path of the libblas.so.3 ./impact maps, ldd).

The floor: the README's main job as shipped (input/clamped.nml:
scheme 'fast', HDF5 on, every step written; its output moved to
build/bench/runs/main_job) against steps x one band solve of its own size
(bench/kernels.f90 on the same deck), with the same BLAS in the same run,
for each BLAS: one line, printed and in PERFORMANCE.md.
"""

import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import impact_files as imf  # noqa: E402  (decks, summaries, histories, runs, the doc's block)
EXE = os.path.join(ROOT, 'impact')
KERNELS = os.path.join(ROOT, 'build', 'bench', 'bench_kernels')
RUN_DIR = os.path.join(ROOT, 'build', 'bench', 'runs')
# The published results and document (make docs), the template of every
# PERFORMANCE.md the bench writes.
PUBLISHED_RESULTS = os.path.join(ROOT, 'bench', 'results.dat')
PUBLISHED_DOCS = os.path.join(ROOT, 'docs')
TEMPLATE = os.path.join(PUBLISHED_DOCS, 'PERFORMANCE.md')
# What this bench writes (main(): --results, --docs-dir).
RESULTS = os.path.join(ROOT, 'out', 'bench', 'results.dat')
FIG_DIR = os.path.join(ROOT, 'out', 'docs', 'performance')
DOC = os.path.join(ROOT, 'out', 'docs', 'PERFORMANCE.md')
DECK_HEADER = ['make bench (bench/run_bench.py): the paper plate, quarter model; the element and the contact load',
               'stated; every other value the default']

# The paper's contact law constants (Table 2), for alpha0 of eq. (12).
ALPHA_P = 1.667e-5     # m
BETA = 0.094

# Deck defaults of the knobs (input/clamped.nml, the paper's values).
DEFAULT = dict(ny=6, nx=9, dt=2.5e-6, cr1=2.0e-3, cr2=1.0e-7, scheme='fast', storage='band',
               shear_rule='mitc9', load='hertz')
# The model is stated in every deck (not left to the defaults), so that the
# bench does not change silently when the defaults do. PAPER_MODEL: the
# paper's own element and load (2x2 shear, point force), a comparison sweep.
PAPER_MODEL = dict(shear_rule='selective', load='point')
# Tight tolerance of the reference runs (nonlinear scenes).
CR2_REF = 1.0e-10

SCENES = {
    'CN': dict(edges='clamped', theory='nonlinear', t_end=2.1e-3, title='clamped, nonlinear (the paper scene)'),
    'CL': dict(edges='clamped', theory='linear', t_end=2.1e-3, title='clamped, linear'),
    'SN': dict(edges='simply_supported', theory='nonlinear', t_end=1.7e-3, title='simply supported, nonlinear'),
    'SL': dict(edges='simply_supported', theory='linear', t_end=1.7e-3, title='simply supported, linear'),
}
# Quarter meshes, (ny, nx): elements along the 100 mm and the 150 mm side.
MESHES = [(2, 3), (4, 6), (6, 9), (8, 12), (12, 18), (16, 24), (24, 36), (32, 48), (48, 72)]


# The reference sequences (full grid; ratio 2 each, bench/run_bench.py
# docstring): the meshes from the paper's 6x9 up, a check sequence of other
# meshes (its orders only), and the time steps from 2.5 us down on 6x9.
REF_MESHES = [(6, 9), (12, 18), (24, 36)]
CHECK_MESHES = [(4, 6), (8, 12), (16, 24)]
REF_DTS = [2.5e-6, 1.25e-6, 0.625e-6, 0.3125e-6]
# Meshes of the sweep mesh_dt, at the step DT_FINE.
MESH_DT = [(8, 12), (12, 18)]
DT_FINE = 1.25e-6
# Runs with at least this many elements (the quarter's ny nx) are timed
# once: the 48x72 cost run, whose set-up (the factorization) takes most of
# a minute.
ONCE_FROM_ELEMENTS = 48 * 72
# Acceptable observed order of a Richardson extrapolation.
P_RANGE = (0.5, 4.0)
# Sweeps whose runs are run once (not timed: only their answers are used).
ONCE = ('ref_', 'mesh_1991')


def grid(quick):
    """The sweeps: name -> list of (scene, settings) with settings overriding DEFAULT."""
    full = not quick
    meshes_err = MESHES[:6] if full else MESHES[:4]            # up to 16x24 (8x12 quick)
    meshes_paper = MESHES[:4] if full else MESHES[:3]          # up to 8x12
    meshes_sky = MESHES[:5] if full else MESHES[:3]            # up to 12x18
    dts = [10e-6, 5e-6, 2.5e-6, 1.25e-6, 0.625e-6, 0.3125e-6] if full else [10e-6, 5e-6, 2.5e-6, 1.25e-6]
    dts_paper = [10e-6, 5e-6, 2.5e-6, 1.25e-6] if full else [10e-6, 2.5e-6]
    cr2s = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10] if full else [1e-6, 1e-7, 1e-9]
    cr2s_paper = [1e-5, 1e-7, 1e-9] if full else [1e-7, 1e-9]
    cr1s = [2e-2, 2e-3, 2e-4, 2e-5] if full else [2e-2, 2e-3]
    scenes = list(SCENES) if full else ['CN', 'SL']
    # the paper's model (2x2 shear, point force), fast scheme: the mesh
    # sequence that has no limit (comparison only, run once)
    meshes_1991 = [(4, 6), (6, 9), (8, 12), (12, 18), (16, 24)] if full else [(2, 3), (4, 6), (8, 12)]
    scenes_1991 = ['CN', 'CL'] if full else ['CN']
    g = {}

    def add(sweep, scene, **kw):
        g.setdefault(sweep, []).append((scene, kw))

    for sc in scenes:
        nonlinear = SCENES[sc]['theory'] == 'nonlinear'
        for ny, nx in meshes_err:
            add('mesh', sc, ny=ny, nx=nx)
        for ny, nx in meshes_paper:
            add('mesh_paper', sc, ny=ny, nx=nx, scheme='paper')
        for dt in dts:
            add('dt', sc, dt=dt)
        for dt in dts_paper:
            add('dt_paper', sc, dt=dt, scheme='paper')
        for cr1 in cr1s:
            add('cr1_paper', sc, cr1=cr1, scheme='paper')
        if nonlinear:
            for cr2 in cr2s:
                add('cr2', sc, cr2=cr2)
            for cr2 in cr2s_paper:
                add('cr2_paper', sc, cr2=cr2, scheme='paper')
        # reference runs: iteration error negligible
        cr2 = CR2_REF if nonlinear else DEFAULT['cr2']
        ref_meshes = REF_MESHES if full else [(2, 3), (4, 6), (8, 12)]
        check_meshes = CHECK_MESHES if full else []
        ref_dts = REF_DTS if full else [10e-6, 5e-6, 2.5e-6, 1.25e-6]
        for ny, nx in ref_meshes:
            add('ref_mesh', sc, ny=ny, nx=nx, cr2=cr2)
        for ny, nx in check_meshes:
            add('ref_mesh_check', sc, ny=ny, nx=nx, cr2=cr2)
        for dt in ref_dts:
            add('ref_dt', sc, dt=dt, cr2=cr2)
        add('ref_base', sc, cr2=cr2)
    # mesh and step refined together (the one-knob sweeps leave the other
    # error at its 6x9 or 2.5 us value)
    for sc in scenes:
        for ny, nx in (MESH_DT if full else [(4, 6)]):
            add('mesh_dt', sc, ny=ny, nx=nx, dt=DT_FINE)
    for sc in scenes_1991:
        for ny, nx in meshes_1991:
            add('mesh_1991', sc, ny=ny, nx=nx, **PAPER_MODEL)
    for ny, nx in meshes_sky:
        add('mesh_sky', 'CN', ny=ny, nx=nx, storage='skyline')
    # the paper's own run: 3 ms, both schemes
    for scheme in ('paper', 'fast'):
        add('paper_scene', 'CN', scheme=scheme, t_end=3.0e-3)
    # cost per step against freedoms: short runs (the first 0.2 ms, 80 steps;
    # 0.05 ms, 20 steps, on 24x36 and 32x48, 0.03 ms on 48x72), band to 48x72,
    # skyline to 24x36
    cost_meshes = MESHES if full else MESHES[:5]
    for ny, nx in cost_meshes:
        t_end = 2.0e-4 if ny <= 16 else (5.0e-5 if ny <= 32 else 3.0e-5)
        add('cost', 'CN', ny=ny, nx=nx, t_end=t_end)
        if ny <= 24:
            add('cost_sky', 'CN', ny=ny, nx=nx, t_end=t_end, storage='skyline')
    return g


# ------------------------------------------------------------------ runs

def settings(scene, kw):
    """The knobs of one run: the defaults, the scene's window, then kw."""
    s = dict(DEFAULT, t_end=SCENES[scene]['t_end'])
    s.update(kw)
    return s


def model_tag(s):
    """'' for the bench's model (DEFAULT), else e.g. 'selective-point'."""
    if (s['shear_rule'], s['load']) == (DEFAULT['shear_rule'], DEFAULT['load']):
        return ''
    return '{}-{}'.format(s['shear_rule'], s['load'])


def run_id(scene, s):
    return '{}_{}x{}_dt{:g}_c1{:g}_c2{:g}_{}_{}_t{:g}{}{}'.format(
        scene, s['ny'], s['nx'], s['dt'] * 1e6, s['cr1'], s['cr2'], s['scheme'], s['storage'],
        s['t_end'] * 1e6, '_' + model_tag(s) if model_tag(s) else '', '_' + s['blas'] if s.get('blas') else '')


def deck_groups(scene, s, prefix):
    """The deck of one run (impact_files' groups): the scene, the knobs s, every
    step written to prefix, no HDF5."""
    sc = SCENES[scene]
    return [['mesh', [['nx', str(s['nx'])], ['ny', str(s['ny'])], ['domain', "'quarter'"],
                      ['shear_rule', "'{}'".format(s['shear_rule'])]]],
            ['contact', [['load', "'{}'".format(s['load'])]]],
            ['boundary', [['edges', "'{}'".format(sc['edges'])]]],
            ['analysis', [['theory', "'{}'".format(sc['theory'])], ['dt', repr(s['dt'])], ['t_end', repr(s['t_end'])],
                          ['cr1', repr(s['cr1'])], ['cr2', repr(s['cr2'])], ['scheme', "'{}'".format(s['scheme'])],
                          ['storage', "'{}'".format(s['storage'])]]],
            ['output', [['prefix', "'{}'".format(prefix)], ['every', '1'], ['overwrite', '.true.'],
                        ['hdf5', '.false.']]]]


SETUP_RE = re.compile(r'set-up \(model, matrices, factorization\): cpu\s+([0-9.Ee+-]+)')


def timed_runs(run, count, summary):
    """count runs of one deck, one after the other (impact_files.run_many):
    [(result, its summary, its set-up cpu (s))], each read before the next run
    writes over it."""
    out = []

    def done(r):
        summ = imf.read_keys(summary) if os.path.exists(summary) else {}
        m = SETUP_RE.search(r['stdout'])
        out.append((r, summ, float(m.group(1)) if m else float('nan')))

    imf.run_many([run] * count, jobs=1, on_done=done, impact=EXE)
    return out


def parabola_peak(t, y):
    """Largest sample, refined by the parabola through it and its neighbours."""
    k = max(range(len(y)), key=lambda i: y[i])
    if 0 < k < len(y) - 1:
        c = y[k + 1] - 2.0 * y[k] + y[k - 1]
        if c < 0.0:
            return y[k] - (y[k + 1] - y[k - 1]) ** 2 / (8.0 * c), k
    return y[k], k


def measures(rows):
    """Peak force (N), first-contact duration (us), largest deflection (mm)."""
    t = [r[0] for r in rows]
    force = [r[1] for r in rows]
    alpha = [r[2] * 1e-3 for r in rows]       # m
    w = [r[3] for r in rows]                  # mm
    peak, kp = parabola_peak(t, force)
    wmax, kw = parabola_peak(t, w)
    # first contact: from the first step with F > 0 to the first step after it with F <= 0
    start = next((i for i, f in enumerate(force) if f > 0.0), None)
    duration = float('nan')
    if start is not None:
        end = next((i for i in range(start, len(force)) if force[i] <= 0.0), None)
        if end is not None:
            am = max(alpha[start:end])
            a0 = BETA * (am - ALPHA_P) if am > ALPHA_P else 0.0
            a1, a2 = alpha[end - 1] - a0, alpha[end] - a0
            frac = a1 / (a1 - a2) if a1 > 0.0 and a2 <= 0.0 and a1 != a2 else 1.0
            t_end = t[end - 1] + frac * (t[end] - t[end - 1])
            duration = t_end - 0.0        # contact begins at t = 0
    inside = kp < len(t) - 1 and kw < len(t) - 1
    return peak, duration, wmax, inside


def run_one(scene, s, repeat, reuse, env):
    """One run of the grid, `repeat` times (once if it stops): its record."""
    rid = run_id(scene, s)
    prefix = os.path.join(RUN_DIR, rid)
    deck = prefix + '.nml'
    cache = prefix + '.json'
    groups = deck_groups(scene, s, prefix)
    if reuse and os.path.exists(cache) and os.path.exists(deck) \
            and open(deck).read() == imf.deck_text(groups, DECK_HEADER):
        with open(cache) as f:
            rec = json.load(f)
        if len(rec['cpu']) >= repeat or rec.get('failed'):
            return rec
    imf.write_deck(deck, groups, DECK_HEADER)
    run = dict(deck=deck, env=env)
    runs = timed_runs(run, 1, prefix + '_summary.dat')
    r, summ, _ = runs[0]
    if r['exit'] != 0:
        # a run that stops (an iteration that cannot converge at these
        # tolerances) is a result too: recorded with status 'failed'
        msg = [l for l in r['stderr'].splitlines() if 'error' in l]
        rec = dict(id=rid, scene=scene, settings=s, cpu=[float(summ.get('cpu_s', 'nan'))], setup=[float('nan')],
                   neq=0, kd=0, stored=0, steps=int(summ.get('steps', '0') or 0),
                   solves=int(summ.get('plate_solves', '0') or 0), factorizations=0, unconverged=0,
                   peak=float('nan'), duration=float('nan'), wmax=float('nan'), inside=False,
                   failed=(msg[0] if msg else 'failed')[:300])
        print('  bench: run failed: {}: {}'.format(rid, rec['failed']))
        with open(cache, 'w') as f:
            json.dump(rec, f)
        return rec
    runs += timed_runs(run, repeat - 1, prefix + '_summary.dat')
    r, summ, _ = runs[-1]
    m = re.search(r'equations (\d+), half-bandwidth (\d+), stored entries (\d+)', r['stdout'])
    neq, kd, stored = (int(m.group(1)), int(m.group(2)), int(m.group(3))) if m else (0, 0, 0)
    peak, duration, wmax, inside = measures(imf.read_columns(prefix + '_history.dat')[1])
    rec = dict(id=rid, scene=scene, settings=s, cpu=[float(x[1]['cpu_s']) for x in runs],
               setup=[x[2] for x in runs], neq=neq, kd=kd, stored=stored,
               steps=int(summ['steps']), solves=int(summ['plate_solves']),
               factorizations=int(summ['factorizations']), unconverged=int(summ['unconverged_steps']),
               peak=peak, duration=duration, wmax=wmax, inside=inside, failed='')
    with open(cache, 'w') as f:
        json.dump(rec, f)
    return rec


# ------------------------------------------------------------- analysis

def richardson(q, ratio=2.0):
    """Richardson extrapolation of the last three values of a sequence (each
    step refined by `ratio`): (limit, observed order p, applied, status).
    It applies when the sequence converges monotonically (successive changes
    of one sign, the later one smaller) with p in P_RANGE; else the finest
    value stands for the limit and status says why: 'not monotone' (the
    changes alternate in sign), 'not converging' (the later change is not
    smaller), 'p out of range', 'undefined' (a value is nan)."""
    q1, q2, q3 = q[-3:]
    if any(x != x for x in (q1, q2, q3)):
        return q3, float('nan'), False, 'undefined'
    d1, d2 = q2 - q1, q3 - q2
    if d2 == 0.0:
        return q3, float('inf'), True, 'ok'
    if d1 * d2 < 0.0:
        return q3, float('nan'), False, 'not monotone'
    if abs(d2) >= abs(d1):
        return q3, float('nan'), False, 'not converging'
    p = math.log(d1 / d2) / math.log(ratio)
    if P_RANGE[0] <= p <= P_RANGE[1]:
        return q3 + d2 / (ratio ** p - 1.0), p, True, 'ok'
    return q3, p, False, 'p out of range'


def sequence_spread(q):
    """Largest distance of the last three values from the last one."""
    q = q[-3:]
    return max(abs(x - q[-1]) for x in q) if all(x == x for x in q) else float('nan')


def references(recs_by_sweep, scene):
    """q* per measure (peak, duration, wmax) and how it was found.

    q* = R_h + R_dt - q0: R_h the Richardson limit of the reference meshes
    (REF_MESHES, at the default step), R_dt that of the three finest steps
    (REF_DTS, on the default mesh), q0 the default run (the first of both).
    how[key]: dict with the sequences, their Richardson results (mesh,
    mesh_check, dt: the three finest steps, dt_coarse: the three coarsest),
    the error of q0 split into its mesh part (q0 - R_h) and its time-step
    part (q0 - R_dt), and the uncertainty of q*: the distance of the finest
    runs from their limits where Richardson applied, else the spread of the
    sequence's last three values (relative to q*)."""
    def get(sweep):
        return [r for sc, r in recs_by_sweep.get(sweep, []) if sc == scene]
    rm, rc, rd, rb = get('ref_mesh'), get('ref_mesh_check'), get('ref_dt'), get('ref_base')
    ref, how, ref6 = {}, {}, {}
    for key in ('peak', 'duration', 'wmax'):
        qb = rb[0][key]
        qm = [r[key] for r in sorted(rm, key=lambda r: r['settings']['ny'])]
        qc = [r[key] for r in sorted(rc, key=lambda r: r['settings']['ny'])]
        qd = [r[key] for r in sorted(rd, key=lambda r: -r['settings']['dt'])]
        lm, pm, okm, stm = richardson(qm)
        ld, pd, okd, std = richardson(qd)
        ref[key] = lm + ld - qb
        ref6[key] = ld        # the 6x9 mesh's own limit: time step and iterations converged
        unc = ((abs(lm - qm[-1]) if okm else sequence_spread(qm))
               + (abs(ld - qd[-1]) if okd else sequence_spread(qd)))
        how[key] = dict(
            qm=qm, qc=qc, qd=qd, q0=qb,
            mesh=(pm, okm, stm), mesh_check=richardson(qc)[1:] if len(qc) >= 3 else None,
            dt=(pd, okd, std), dt_coarse=richardson(qd[:3])[1:] if len(qd) >= 4 else None,
            err_h=(qb - lm) / ref[key] if ref[key] else float('nan'),
            err_dt=(qb - ld) / ref[key] if ref[key] else float('nan'),
            unc=unc / abs(ref[key]) if ref[key] else float('nan'))
    return ref, how, ref6


def additivity(recs_by_sweep, scene, ref, how):
    """The additive error model tested where the mesh and the step are
    refined together (sweep mesh_dt): each run against the prediction
    q(h, 2.5 us) + q(6x9, dt) - q(6x9, 2.5 us) from the one-knob sweeps (all
    at the default tolerances). how[key]['add']: list of (mesh, dt,
    measured, predicted); how[key]['add_defect']: the largest |measured -
    predicted| / |q*|, added to the uncertainty of q*."""
    def find(sweep, ny, dt):
        return next((r for sc, r in recs_by_sweep.get(sweep, []) if sc == scene
                     and r['settings']['ny'] == ny and r['settings']['dt'] == dt and not r.get('failed')), None)
    base = find('mesh', DEFAULT['ny'], DEFAULT['dt'])
    for key in ('peak', 'duration', 'wmax'):
        how[key]['add'], how[key]['add_defect'] = [], 0.0
    for sc, r in recs_by_sweep.get('mesh_dt', []):
        if sc != scene or r.get('failed') or base is None:
            continue
        st = r['settings']
        rh, rd = find('mesh', st['ny'], DEFAULT['dt']), find('dt', DEFAULT['ny'], st['dt'])
        if rh is None or rd is None:
            continue
        for key in ('peak', 'duration', 'wmax'):
            pred = rh[key] + rd[key] - base[key]
            how[key]['add'].append(('{}x{}'.format(st['ny'], st['nx']), st['dt'], r[key], pred))
            d = abs(r[key] - pred) / abs(ref[key]) if ref[key] else float('nan')
            if d == d:
                how[key]['add_defect'] = max(how[key]['add_defect'], d)
                how[key]['unc_richardson'] = how[key].get('unc_richardson', how[key]['unc'])
    for key in ('peak', 'duration', 'wmax'):
        if 'unc_richardson' in how[key]:
            how[key]['unc'] = how[key]['unc_richardson'] + how[key]['add_defect']


def changes(q):
    """Relative changes between successive values of a sequence."""
    return [(b - a) / a if a == a and b == b and a else float('nan') for a, b in zip(q, q[1:])]


def median(v):
    return statistics.median(v) if v else float('nan')


def fit_slope(points):
    """Least-squares slope and intercept of log y against log x."""
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    b = sxy / sxx
    return b, math.exp(my - b * mx)


def kernels(deck, env):
    if not os.path.exists(KERNELS):
        return None
    r = subprocess.run([KERNELS, deck], capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit('bench: {} {} failed:\n{}'.format(KERNELS, deck, r.stderr[-2000:]))
    return imf.keys_in(r.stdout)


REFERENCE_BLAS = ('/usr/lib/x86_64-linux-gnu/blas', '/usr/lib/x86_64-linux-gnu/lapack')


def openblas_dir():
    d = os.environ.get('BENCH_OPENBLAS', '')
    if d:
        return d if os.path.exists(os.path.join(d, 'libblas.so.3')) else ''
    for cand in ('/usr/lib/x86_64-linux-gnu/openblas-serial', '/usr/lib/x86_64-linux-gnu/openblas-pthread'):
        if os.path.exists(os.path.join(cand, 'libblas.so.3')):
            return cand
    return ''


def loaded_blas(env=None):
    """The BLAS library ./impact loads (the real path of its libblas.so.3,
    through Debian's alternatives), with the environment env."""
    r = subprocess.run(['ldd', EXE], capture_output=True, text=True, env=env)
    m = re.search(r'libblas\.so\.3 => (\S+)', r.stdout)
    return os.path.realpath(m.group(1)) if m else 'unknown'


def system_blas():
    """The BLAS library ./impact loads by default (its real path)."""
    return loaded_blas()


def blas_name(path):
    """'openblas' or 'reference' (or the file name) for a libblas path."""
    if 'openblas' in path:
        return 'openblas'
    if path.endswith('/blas/libblas.so.3') or 'libblas.so.3.' in os.path.basename(path):
        return 'reference'
    return os.path.basename(path)


def other_blas():
    """The BLAS to compare with: (name, LD_LIBRARY_PATH) of OpenBLAS when the
    system's is another, of the reference BLAS when the system's is OpenBLAS;
    None when it is not installed."""
    if blas_name(system_blas()) == 'openblas':
        if all(os.path.exists(d) for d in REFERENCE_BLAS):
            return 'reference', ':'.join(REFERENCE_BLAS)
        return None
    ob = openblas_dir()
    return ('openblas', ob) if ob else None


def main_job_floor(env, repeat, blas):
    """The floor line of one BLAS (module docstring): the README's main job
    as shipped, median CPU of `repeat` runs, against steps x one solve."""
    prefix = os.path.join(RUN_DIR, 'main_job_' + blas)
    runs = timed_runs(dict(deck=os.path.join(ROOT, 'input', 'clamped.nml'), options=['--overwrite'],
                           sets=['output.prefix=' + prefix], env=env), repeat, prefix + '_summary.dat')
    if any(r['exit'] != 0 for r, _, _ in runs):
        return None
    cpu = [float(summ['cpu_s']) for _, summ, _ in runs]
    setup = [x for _, _, x in runs]
    steps = int(runs[-1][1]['steps'])
    solves = int(runs[-1][1]['plate_solves'])
    k = kernels(os.path.join(ROOT, 'input', 'clamped.nml'), env)
    if not k:
        return None
    solve = float(k['solve_s'])
    # A lower bound of the run from its own kernels (same BLAS, same deck):
    # the set-up, one M x per step (M {b} of eq. 20) and K_N(D) D with each
    # solve (eq. 19), nothing written; then with the two energies of every
    # history row (strain energy, and one more M x for the kinetic energy).
    bound = median(setup) + steps * float(k['mass_s']) + solves * (solve + float(k['knl_s']))
    bound_rows = bound + steps * (float(k['energy_s']) + float(k['mass_s']))
    return dict(blas=blas, path=loaded_blas(env), cpu=median(cpu), setup=median(setup), steps=steps, solves=solves,
                solve=solve, floor=steps * solve, ratio=median(cpu) / (steps * solve),
                loop_ratio=(median(cpu) - median(setup)) / (steps * solve),
                bound=bound / (steps * solve), bound_rows=bound_rows / (steps * solve))


def floor_line(f):
    return ('floor ({} BLAS): input/clamped.nml as shipped (scheme fast, HDF5 on, every step), {} steps, {} solves: '
            'CPU {:.3f} s (set-up {:.3f} s) against {} x one band solve ({:.4f} ms) = {:.3f} s: '
            '{:.2f} x the floor ({:.2f} x for the time loop alone); its kernels alone (set-up, M x a step, '
            'K_N D a solve, nothing written) are {:.2f} x, with the energies of every row {:.2f} x'.format(
                f['blas'], f['steps'], f['solves'], f['cpu'], f['setup'], f['steps'], f['solve'] * 1e3, f['floor'],
                f['ratio'], f['loop_ratio'], f['bound'], f['bound_rows']))


# --------------------------------------------------------------- output

COLUMNS = [
    ('scene', '-', 'CN clamped nonlinear (the paper scene), CL clamped linear, SN / SL simply supported'),
    ('sweep', '-', 'the knob varied: mesh, dt, cr1, cr2 (suffix _paper: scheme paper; mesh_sky: skyline), '
                   'ref_*: reference runs, paper_scene: 3 ms, cost: short runs for the cost per step, '
                   'mesh_dt: meshes 8x12, 12x18 at 1.25 us, '
                   "mesh_1991: the paper's model (2x2 shear, point force), errors against the converged model's reference"),
    ('scheme', '-', "'paper' or 'fast'"),
    ('storage', '-', "'band' or 'skyline'"),
    ('blas', '-', "'system' (the default libblas: see the header) or the other one run ('openblas' or 'reference')"),
    ('ny', '-', 'elements along y (100 mm side) of the quarter'),
    ('nx', '-', 'elements along x (150 mm side)'),
    ('equations', '-', 'freedoms N'),
    ('half_bandwidth', '-', 'kd'),
    ('dt_us', 'us', 'time step'),
    ('t_end_us', 'us', 'end time'),
    ('cr1', '-', 'contact-force tolerance, eq. (17) (scheme paper only)'),
    ('cr2', '-', 'nonlinear-iteration tolerance, eq. (18)'),
    ('repeats', '-', 'runs timed'),
    ('cpu_s', 's', 'CPU time, median of the repeats'),
    ('cpu_min_s', 's', 'fastest repeat'),
    ('setup_s', 's', 'of which set-up: model, matrices, factorization (median)'),
    ('step_ms', 'ms', 'CPU per time step, (cpu - setup)/steps'),
    ('steps', '-', 'time steps'),
    ('plate_solves', '-', 'back substitutions'),
    ('factorizations', '-', 'factorizations of K_L + 4/dt^2 M'),
    ('unconverged', '-', 'iterations stopped at their limit'),
    ('peak_force_N', 'N', 'largest contact force (parabola through the largest samples)'),
    ('duration_us', 'us', 'first contact duration (interpolated end; nan: not ended)'),
    ('max_deflection_mm', 'mm', 'largest plate deflection at the impact point'),
    ('err_peak', '-', '|peak - reference| / reference (nan: no reference for this window)'),
    ('err_duration', '-', 'same for the first contact duration'),
    ('err_deflection', '-', 'same for the largest deflection'),
    ('err_max', '-', 'largest of the three'),
    ('status', '-', "'ok', or 'failed' (the run stopped: an iteration did not converge; see PERFORMANCE.md)"),
    ('err6_peak', '-', '6x9 runs only: against the 6x9 mesh own limit (time step and iterations converged)'),
    ('err6_duration', '-', 'same, first contact duration'),
    ('err6_deflection', '-', 'same, max deflection'),
    ('err6_max', '-', 'largest of the three'),
    ('shear_rule', '-', "the element's transverse shear (&mesh shear_rule): 'mitc9', or 'selective' (the paper's 2x2 rule, sweep mesh_1991)"),
    ('load', '-', "the contact load (&contact load): 'hertz', or 'point' (the paper's, sweep mesh_1991)"),
]


def fmt(v):
    if isinstance(v, str):
        return v
    if isinstance(v, int):
        return str(v)
    if v != v:
        return 'nan'
    return '{:.6e}'.format(v)


def write_results(rows, header_lines):
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    with open(RESULTS, 'w') as f:
        f.write('# {}: written by make bench (bench/run_bench.py); one row per run and sweep\n'.format(
            os.path.relpath(RESULTS, ROOT)))
        for line in header_lines:
            f.write('# ' + line + '\n')
        f.write('# columns:\n')
        for i, (name, unit, text) in enumerate(COLUMNS, 1):
            f.write('#  {:2d} {:<18s} ({}) {}\n'.format(i, name, unit, text))
        f.write('# ' + ' '.join('{}[{}]'.format(n, u) for n, u, _ in COLUMNS) + '\n')
        for r in rows:
            f.write(' '.join(fmt(v) for v in r) + '\n')


# ------------------------------------------------------------- scaling and sweeps
# The scaling table: full plates of the paper's laminate, clamped,
# nonlinear, scheme 'fast', 2.5 us, the first SCALING_STEPS steps, HDF5 off;
# (nx, ny, a, b): elements along a and b, the plate's sides (m). 150x150 is
# the 300 x 300 mm plate with 2 mm elements.
SCALING_MESHES = [(18, 12, 0.15, 0.10), (36, 24, 0.15, 0.10), (72, 48, 0.15, 0.10), (108, 72, 0.15, 0.10),
                  (150, 150, 0.30, 0.30)]
QUICK_SCALING_MESHES = [(18, 12, 0.15, 0.10), (27, 18, 0.15, 0.10), (36, 24, 0.15, 0.10)]
SCALING_STEPS = 40
# Runs up to this many elements are repeated (--repeat) and the least s/step
# kept (the machine is shared: noise); larger ones run once.
SCALING_REPEAT_ELEMENTS = 36 * 24
# Band storage runs where its three band matrices fit: the estimate
# 3 x 8 bytes x neq (kd + 1), neq ~ 5 (2 nx + 1)(2 ny + 1) and kd ~ 20
# min(nx, ny) + 4 (the 9-node elements, numbered across the shorter side:
# 244 at 18x12, 484 at 36x24, measured), at most --band-max-gib and half the
# memory available.
BAND_MAX_GIB = 2.0
SCALING_DIR = os.path.join(ROOT, 'build', 'bench', 'scaling')
# The sweep throughput: input/clamped.nml (quarter 6x4, 3 ms) over 3 masses x
# 4 velocities x 2 edge conditions, 24 scenes (quick: 2 x 2 x 2), run with
# one worker and with every CPU, twice each, alternately.
SWEEP_VARY = ['impactor.mass=0.1,0.243,0.5', 'impactor.velocity=1,2,3,4', 'boundary.edges=clamped,simply_supported',
              'mesh.nx+mesh.ny=6:4']
QUICK_SWEEP_VARY = ['impactor.mass=0.1,0.243', 'impactor.velocity=2,3', 'boundary.edges=clamped,simply_supported',
                    'mesh.nx+mesh.ny=6:4']
SWEEP_DIR = os.path.join(ROOT, 'build', 'bench', 'sweep')
SWEEP_TOOL = os.path.join(ROOT, 'tools', 'sweep')


def mem_available_gib():
    """MemAvailable of /proc/meminfo (GiB); inf when unknown."""
    try:
        with open('/proc/meminfo') as f:
            for line in f:
                if line.startswith('MemAvailable:'):
                    return int(line.split()[1]) / 2.0 ** 20
    except (OSError, ValueError, IndexError):
        pass
    return float('inf')


def band_estimate_gib(nx, ny):
    """The three band matrices of a full plate nx x ny (GiB), estimated."""
    neq = 5 * (2 * nx + 1) * (2 * ny + 1)
    kd = 20 * min(nx, ny) + 4
    return 3 * 8 * neq * (kd + 1) / 2.0 ** 30


def scaling_run(nx, ny, a, b, storage, repeat):
    """One mesh of the scaling table in one storage, `repeat` times: a dict
    with neq, kd, the storage the run used, s/step (least), set-up CPU (s),
    peak memory (MiB), cpu_s, or failed."""
    os.makedirs(SCALING_DIR, exist_ok=True)
    name = '{}x{}_{}'.format(nx, ny, storage)
    prefix = os.path.join(SCALING_DIR, name)
    sets = ['plate.a={}'.format(a), 'plate.b={}'.format(b), 'mesh.nx={}'.format(nx), 'mesh.ny={}'.format(ny),
            "mesh.domain=full", 'analysis.scheme=fast', 'analysis.dt=2.5e-6',
            'analysis.t_end={:g}'.format(SCALING_STEPS * 2.5e-6), 'analysis.storage=' + storage,
            'output.prefix=' + prefix, 'output.hdf5=.false.', 'output.overwrite=.true.']
    rec = dict(mesh='{}x{}'.format(nx, ny), plate='{:g} x {:g} mm'.format(a * 1e3, b * 1e3), asked=storage,
               per_step=[], setup=[], rss=[], cpu=[], failed='')
    for _ in range(repeat):
        r = imf.run_many([dict(deck=os.path.join(ROOT, 'input', 'clamped.nml'), sets=sets, log=prefix + '.log')],
                         jobs=1, impact=EXE)[0]
        summary = prefix + '_summary.dat'
        keys = imf.read_keys(summary) if r['exit'] == 0 and os.path.exists(summary) else {}
        if keys.get('status') != 'completed':
            rec['failed'] = r['diagnostic'] or 'exit status {}'.format(r['exit'])
            return rec
        with open(prefix + '.log', encoding='utf-8', errors='replace') as f:
            log = f.read()
        m = re.search(r'equations (\d+), half-bandwidth (\d+)', log)
        rec['neq'], rec['kd'] = (int(m.group(1)), int(m.group(2))) if m else (0, 0)
        m = re.search(r'scene: storage\s+(\w+)', log)
        rec['storage'] = m.group(1) if m else storage
        m = SETUP_RE.search(log)
        setup = float(m.group(1)) if m else float('nan')
        cpu = imf.summary_number(keys, 'cpu_s')
        rec['setup'].append(setup)
        rec['cpu'].append(cpu)
        rec['per_step'].append((cpu - setup) / max(int(keys.get('steps', '1')), 1))
        rec['rss'].append(r['max_rss_mib'] or float('nan'))
    return rec


def scaling(quick, repeat, band_max_gib):
    """The scaling table: every mesh in 'auto' storage, and in band storage
    where it fits; the growth exponent of s/step with the equations."""
    recs = []
    meshes = QUICK_SCALING_MESHES if quick else SCALING_MESHES
    band_limit = min(band_max_gib, mem_available_gib() / 2)
    for nx, ny, a, b in meshes:
        for storage in ('auto', 'band'):
            if storage == 'band' and band_estimate_gib(nx, ny) > band_limit:
                print('  scaling {}x{} band: skipped (its band matrices, some {:.1f} GiB, over {:.1f} GiB)'.format(
                    nx, ny, band_estimate_gib(nx, ny), band_limit), flush=True)
                continue
            t0 = time.time()
            rec = scaling_run(nx, ny, a, b, storage, repeat if nx * ny <= SCALING_REPEAT_ELEMENTS else 1)
            recs.append(rec)
            if rec['failed']:
                print('  scaling {}x{} {}: failed: {}'.format(nx, ny, storage, rec['failed']), flush=True)
                continue
            print('  scaling {:>8s} {:>7d} equations  {:<6s} ({})  {:.4g} s/step  set-up {:.3g} s  peak {:.0f} MiB'
                  '  ({:.0f} s)'.format(rec['mesh'], rec['neq'], rec['storage'], storage, min(rec['per_step']),
                                        min(rec['setup']), max(rec['rss']), time.time() - t0), flush=True)
    growth = {}
    for storage in ('auto', 'band'):
        pts = [(r['neq'], min(r['per_step'])) for r in recs if r['asked'] == storage and not r['failed']]
        growth[storage] = (fit_slope(pts)[0], pts) if len(pts) >= 2 else (float('nan'), pts)
    return recs, growth, band_limit


def gib_text(mib):
    return '{:.2f} GiB'.format(mib / 1024) if mib >= 1024 else '{:.0f} MiB'.format(mib)


def scaling_lines(recs, growth, band_limit, repeat):
    """The scaling table as Markdown lines (printed and in PERFORMANCE.md)."""
    L = ['Full plates (150 x 100 mm unless said; the paper\'s laminate), clamped, nonlinear, scheme `\'fast\'`, '
         '2.5 us, the first {} steps, HDF5 off; s/step = (CPU of the run - CPU of the set-up) / steps, the least of '
         '{} runs up to {} elements, one run above; peak memory: the process\'s maximum resident set (os.wait4). '
         'Storage `\'auto\'` (the default) and `\'band\'` where its three band matrices fit in {:.1f} GiB '
         '(estimated).'.format(SCALING_STEPS, repeat, SCALING_REPEAT_ELEMENTS, band_limit), '',
         '| mesh | plate | equations | half-band | storage | s/step | set-up (s) | peak memory |',
         '|---|---|---|---|---|---|---|---|']
    for r in recs:
        if r['failed']:
            L.append('| {} | {} | | | {} | failed: {} | | |'.format(r['mesh'], r['plate'], r['asked'],
                                                                   r['failed'][:80]))
            continue
        store = r['storage'] + (' (auto)' if r['asked'] == 'auto' else '')
        L.append('| {} | {} | {} | {} | {} | {:.3g} | {:.3g} | {} |'.format(
            r['mesh'], r['plate'], r['neq'], r['kd'], store, min(r['per_step']), min(r['setup']),
            gib_text(max(r['rss']))))
    L.append('')
    for storage, (slope, pts) in growth.items():
        if pts:
            L.append('Growth of s/step with the equations N, storage `\'{}\'` ({} meshes, {} to {} equations, least '
                     'squares of log s/step on log N): **N^{:.2f}**.'.format(storage, len(pts), min(p[0] for p in pts),
                                                                           max(p[0] for p in pts), slope))
    return L


def sweep_pass(vary, jobs):
    """A fresh sweep of the scenes `vary` run with `jobs` workers: wall (s),
    the CPU of the whole sweep (tools/sweep and all it started, os.wait4),
    of its scenes' processes and of their summaries' cpu_s (s)."""
    shutil.rmtree(SWEEP_DIR, ignore_errors=True)
    subprocess.run([SWEEP_TOOL, 'init', SWEEP_DIR, '--deck', os.path.join(ROOT, 'input', 'clamped.nml'),
                    '--impact', EXE] + [w for v in vary for w in ('--vary', v)],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(os.path.dirname(SWEEP_DIR), 'sweep_{}.log'.format(jobs)), 'w') as log:
        t0 = time.monotonic()
        p = subprocess.Popen([SWEEP_TOOL, 'run', SWEEP_DIR, '--jobs', str(jobs)], stdout=log,
                             stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        code, cpu, _ = imf.wait_usage(p)
        wall = time.monotonic() - t0
    scenes = sorted(os.listdir(os.path.join(SWEEP_DIR, 'scenes')))
    processes = summaries = walls = 0.0
    for n in scenes:
        d = os.path.join(SWEEP_DIR, 'scenes', n)
        status = imf.read_keys(os.path.join(d, 'scene.status'))
        processes += imf.summary_number(status, 'cpu_s')
        walls += imf.summary_number(status, 'wall_s')
        summaries += imf.summary_number(imf.read_keys(os.path.join(d, 'run_summary.dat')), 'cpu_s')
    return dict(jobs=jobs, scenes=len(scenes), exit=code, wall=wall, cpu=cpu, processes=processes,
                summaries=summaries, in_flight=walls / wall)


def load_average():
    """The 1-minute load average (/proc/loadavg), NaN when unknown."""
    try:
        with open('/proc/loadavg') as f:
            return float(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return float('nan')


def sweep_throughput(quick):
    """The sweep passes: one worker, every CPU, one, every CPU."""
    n = imf.cpu_count()
    passes = []
    loads = [load_average()]
    for jobs in ([1, n, 1, n] if n > 1 else [1, 1]):
        p = sweep_pass(QUICK_SWEEP_VARY if quick else SWEEP_VARY, jobs)
        passes.append(p)
        print('  sweep {} scenes, {} worker(s): {:.2f} s wall, {:.2f} scenes/s; CPU {:.2f} s, {:.2f}x its scenes\' '
              'processes, {:.2f}x their cpu_s{}'.format(p['scenes'], jobs, p['wall'], p['scenes'] / p['wall'],
                                                        p['cpu'], p['cpu'] / p['processes'],
                                                        p['cpu'] / p['summaries'],
                                                        '' if p['exit'] == 0 else ' (exit status {})'.format(p['exit'])),
              flush=True)
    loads.append(load_average())
    return passes, n, loads


def sweep_lines(passes, n, loads):
    """The sweep throughput as Markdown lines."""
    p0 = passes[0]
    L = ['`tools/sweep run` on {} scenes of `input/clamped.nml` (quarter 6x4, 3 ms; {}), fresh each pass, with one '
         'worker and with the {} CPUs this process may use, alternately; CPU: the whole sweep (the tool and every '
         'process it started, os.wait4) against its scenes\' processes (each `impact`, os.wait4) and against their '
         'summaries\' `cpu_s` (set-up and time loop only).'.format(p0['scenes'], ' x '.join(
             v.split('=')[0] for v in (SWEEP_VARY if p0['scenes'] == 24 else QUICK_SWEEP_VARY)), n), '',
         '| pass | workers | wall (s) | scenes/s | scenes in flight | sweep CPU (s) | scenes\' processes (s) | '
         'their cpu_s (s) | sweep / processes | sweep / cpu_s |', '|---|---|---|---|---|---|---|---|---|---|']
    for k, p in enumerate(passes, 1):
        L.append('| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |'.format(
            k, p['jobs'], p['wall'], p['scenes'] / p['wall'], p['in_flight'], p['cpu'], p['processes'],
            p['summaries'], p['cpu'] / p['processes'], p['cpu'] / p['summaries']))
    L.append('')
    L.append('Scenes in flight: the sum of the scenes\' wall times over the sweep\'s (how many ran at once, on '
             'average). Load average of the machine (1 min) before and after the passes: {:.1f}, {:.1f} (on {} '
             'CPUs: above that, the scenes wait for a CPU and more workers cannot shorten the sweep).'.format(
                 loads[0], loads[-1], os.cpu_count()))
    if n > 1:
        ratios = [passes[k + 1]['wall'] / passes[k]['wall'] for k in range(0, len(passes) - 1, 2)]
        L.append('Wall time with {} workers over one worker: {} (pass by pass).'.format(
            n, ', '.join('{:.2f}'.format(x) for x in ratios)))
    return L


def fill_doc(blocks):
    """Fills the blocks of DOC named in blocks, the others left as they are."""
    names = imf.fill_file(DOC, blocks, keep_others=True)
    missing = [b for b in blocks if b not in names]
    if missing:
        sys.exit('bench: {}: no block {} to fill'.format(DOC, ', '.join(missing)))



def main():
    global RESULTS, FIG_DIR, DOC
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--repeat', type=int, default=int(os.environ.get('BENCH_REPEAT', '3')))
    ap.add_argument('--quick', action='store_true')
    ap.add_argument('--reuse', action='store_true')
    ap.add_argument('--docs-dir', default=os.path.join(ROOT, 'out', 'docs'))
    ap.add_argument('--results', default=RESULTS)
    ap.add_argument('--parts', default='scaling,sweep',
                    help='what to run, a comma list of scaling (the scaling table), sweep (the sweep '
                         'throughput), grid (the speed-accuracy grid, ~15 min); default scaling,sweep')
    ap.add_argument('--band-max-gib', type=float, default=BAND_MAX_GIB,
                    help='scaling: band storage runs where its matrices fit in this (default {:g} GiB; '
                         'at most half the memory available)'.format(BAND_MAX_GIB))
    args = ap.parse_args()
    parts = [x.strip() for x in args.parts.split(',') if x.strip()]
    if not parts or any(x not in ('scaling', 'sweep', 'grid') for x in parts):
        sys.exit('bench: --parts {}: a comma list of scaling, sweep, grid'.format(args.parts))
    RESULTS = os.path.abspath(args.results)
    FIG_DIR = os.path.join(os.path.abspath(args.docs_dir), 'performance')
    DOC = os.path.join(os.path.abspath(args.docs_dir), 'PERFORMANCE.md')
    if args.quick:
        for given, published in ((args.docs_dir, PUBLISHED_DOCS), (args.results, PUBLISHED_RESULTS)):
            if os.path.realpath(given) == os.path.realpath(published):
                sys.exit('bench: --quick: the quick grid never writes the published {} (make docs runs the '
                         'full grid); give another place, or leave the default (out/)'.format(
                             os.path.relpath(published, ROOT)))
    t_wall0 = time.time()
    os.makedirs(RUN_DIR, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    os.makedirs(os.path.dirname(RESULTS), exist_ok=True)
    if not os.path.exists(EXE):
        sys.exit('bench: ./impact not built (make impact)')
    if not (os.path.exists(DOC) and os.path.samefile(DOC, TEMPLATE)):
        shutil.copyfile(TEMPLATE, DOC)
    print('bench: {} ({}); writes {} and {}'.format(', '.join(parts), 'quick' if args.quick else 'full',
                                                   os.path.relpath(DOC, ROOT), os.path.relpath(RESULTS, ROOT)))
    if 'scaling' in parts:
        recs, growth, band_limit = scaling(args.quick, args.repeat, args.band_max_gib)
        L = scaling_lines(recs, growth, band_limit, args.repeat)
        print('\n'.join(['', 'bench: the scaling table'] + L), flush=True)
        scaling_file = os.path.join(os.path.dirname(RESULTS), 'scaling.dat')
        with open(scaling_file, 'w') as f:
            f.write('# make bench: the scaling table ({}), {}\n# mesh plate equations half_band storage asked '
                    's_per_step setup_s peak_MiB\n'.format('quick' if args.quick else 'full', time.strftime('%Y-%m-%d')))
            for r in recs:
                if not r['failed']:
                    f.write('{} {} {} {} {} {} {:.6g} {:.6g} {:.1f}\n'.format(
                        r['mesh'], r['plate'].replace(' ', ''), r['neq'], r['kd'], r['storage'], r['asked'],
                        min(r['per_step']), min(r['setup']), max(r['rss'])))
        fill_doc({'bench-scaling': '\n'.join(L)})
    if 'sweep' in parts:
        passes, n, loads = sweep_throughput(args.quick)
        L = sweep_lines(passes, n, loads)
        print('\n'.join(['', 'bench: the sweep throughput'] + L), flush=True)
        fill_doc({'bench-sweep': '\n'.join(L)})
    if 'grid' not in parts:
        print('bench: wrote {} and {}; {:.0f} s'.format(os.path.relpath(DOC, ROOT),
                                                        os.path.relpath(os.path.dirname(RESULTS), ROOT),
                                                        time.time() - t_wall0))
        return
    env_sys = dict(os.environ)
    sys_name = blas_name(system_blas())
    alt = other_blas()
    alt_name = alt[0] if alt else ''
    ob = alt[1] if alt else ''
    print('bench: BLAS {} ({}){}'.format(sys_name, system_blas(), '; also ' + alt_name + ' from ' + ob if alt else ''))
    g = grid(args.quick)

    # run every distinct run once (a run may belong to several sweeps)
    todo = {}
    for sweep, items in g.items():
        for scene, kw in items:
            s = settings(scene, kw)
            todo.setdefault(run_id(scene, s), (scene, s))
    print('bench: {} runs x {} repeats{}'.format(len(todo), args.repeat, ' (quick grid)' if args.quick else ''))
    # runs only the references need (not on any curve) are run once
    timed = {run_id(scene, settings(scene, kw))
             for sweep, items in g.items() if not sweep.startswith(ONCE) for scene, kw in items
             if settings(scene, kw)['ny'] * settings(scene, kw)['nx'] < ONCE_FROM_ELEMENTS}
    recs = {}
    for n, (rid, (scene, s)) in enumerate(sorted(todo.items(), key=lambda kv: kv[1][1]['ny'] * kv[1][1]['nx'] / kv[1][1]['dt']), 1):
        t0 = time.time()
        recs[rid] = run_one(scene, s, args.repeat if rid in timed else 1, args.reuse, env_sys)
        r = recs[rid]
        print('  [{:3d}/{}] {:<60s} cpu {:8.3f} s  solves {:7d}  ({:.0f} s)'.format(
            n, len(todo), rid, median(r['cpu']), r['solves'], time.time() - t0), flush=True)
    by_sweep = {}
    for sweep, items in g.items():
        for scene, kw in items:
            by_sweep.setdefault(sweep, []).append((scene, recs[run_id(scene, settings(scene, kw))]))

    # the other BLAS: the paper's scene again, that BLAS loaded instead
    ob_recs = []
    env_ob = None
    if ob:
        env_ob = dict(os.environ, LD_LIBRARY_PATH=ob + (':' + os.environ['LD_LIBRARY_PATH'] if os.environ.get('LD_LIBRARY_PATH') else ''))
        for scheme in ('paper', 'fast'):
            s = dict(DEFAULT, t_end=3.0e-3, scheme=scheme, blas=alt_name)
            r = run_one('CN', s, args.repeat, args.reuse, env_ob)
            ob_recs.append(('paper_scene', 'CN', r))
            print('  [{}] {:<60s} cpu {:8.3f} s'.format(alt_name, r['id'], median(r['cpu'])), flush=True)

    # the floor: the README's main job as shipped against steps x one solve, per BLAS
    floors = []
    for name, env in ((sys_name, env_sys), (alt_name, env_ob)):
        if env is None:
            continue
        f = main_job_floor(env, max(args.repeat, 5), name)
        if f:
            floors.append(f)
            print('bench: ' + floor_line(f), flush=True)

    # references and errors
    refs, hows, refs6 = {}, {}, {}
    for scene in SCENES:
        if any(sc == scene for sc, _ in by_sweep.get('ref_base', [])):
            refs[scene], hows[scene], refs6[scene] = references(by_sweep, scene)
            additivity(by_sweep, scene, refs[scene], hows[scene])

    def errors(scene, r, ref):
        if scene not in ref or r['settings']['t_end'] != SCENES[scene]['t_end']:
            return [float('nan')] * 4
        e = [abs(r[k] - ref[scene][k]) / abs(ref[scene][k]) for k in ('peak', 'duration', 'wmax')]
        known = [x for x in e if x == x]     # a measure may be undefined (nan) for a scene
        return e + [max(known) if known else float('nan')]

    rows = []
    all_items = [(sw, sc, r) for sw, items in by_sweep.items() for sc, r in items] + ob_recs
    for sweep, scene, r in all_items:
        s = r['settings']
        cpu = median(r['cpu'])
        setup = median(r['setup'])
        rows.append([scene, sweep, s['scheme'], s['storage'], s.get('blas') or 'system', s['ny'], s['nx'],
                     r['neq'], r['kd'], s['dt'] * 1e6, s['t_end'] * 1e6, s['cr1'], s['cr2'], len(r['cpu']),
                     cpu, min(r['cpu']), setup, (cpu - setup) / max(r['steps'], 1) * 1e3, r['steps'], r['solves'],
                     r['factorizations'], r['unconverged'], r['peak'], r['duration'], r['wmax']]
                    + errors(scene, r, refs) + ['failed' if r.get('failed') else 'ok']
                    + (errors(scene, r, refs6) if (s['ny'], s['nx']) == (DEFAULT['ny'], DEFAULT['nx']) and not model_tag(s)
                       else [float('nan')] * 4)
                    + [s['shear_rule'], s['load']])

    # scheme agreement: every pair of runs that differ only in the scheme;
    # stated tolerance 3 max(cr1, sqrt(cr2)) (PERFORMANCE.md)
    tol = pair_tolerance(DEFAULT)
    pairs = []
    for rid, r in recs.items():
        s = r['settings']
        if s['scheme'] != 'paper' or s.get('blas'):
            continue
        sf = dict(s, scheme='fast')
        rf = recs.get(run_id(r['scene'], sf))
        if rf is None or r.get('failed') or rf.get('failed'):
            continue
        d = [abs(rf[k] - r[k]) / abs(r[k]) for k in ('peak', 'duration', 'wmax')]
        pairs.append((r, rf, d, pair_tolerance(s)))

    # cost per step against freedoms
    cost = {}
    for sweep in ('cost', 'cost_sky'):
        for per in ('steps', 'solves'):
            pts = sorted((r['neq'], (median(r['cpu']) - median(r['setup'])) / r[per])
                         for _, r in by_sweep.get(sweep, []) if not r.get('failed'))
            big = [p for p in pts if p[0] >= 1000]
            cost[(sweep, per)] = (pts, fit_slope(big) if len(big) >= 2 else (float('nan'), float('nan')))

    # kernels: the paper's mesh and the largest band mesh of the cost sweep
    kern = []
    deck69 = os.path.join(RUN_DIR, run_id('CN', dict(DEFAULT, t_end=3.0e-3, scheme='fast')) + '.nml')
    big = max((r for _, r in by_sweep.get('cost', [])), key=lambda r: r['neq'], default=None)
    for label, deck in (('6x9', deck69), ('{}x{}'.format(big['settings']['ny'], big['settings']['nx']) if big else '', os.path.join(RUN_DIR, big['id'] + '.nml') if big else '')):
        if not deck:
            continue
        k = kernels(deck, env_sys)
        if k:
            kern.append((label, 'system', k))
        if ob:
            k = kernels(deck, env_ob)
            if k:
                kern.append((label, alt_name, k))

    header = ['machine: {} cores, {}; BLAS: {} ({}){}'.format(
        os.cpu_count(), platform_cpu(), sys_name, system_blas(), '; {} from {}'.format(alt_name, ob) if ob else ''),
        'repeats: {}; wall time of the bench: see PERFORMANCE.md'.format(args.repeat)]
    write_results(rows, header)
    plots()
    wall = time.time() - t_wall0
    write_doc(rows, refs, hows, pairs, tol, cost, kern, by_sweep, ob_recs, wall, args, floors, alt_name)
    for f in floors:
        print('bench: ' + floor_line(f))
    print('bench: wrote {} ({} rows), {} and {}/; {:.0f} s'.format(
        os.path.relpath(RESULTS, ROOT), len(rows), os.path.relpath(DOC, ROOT), os.path.relpath(FIG_DIR, ROOT), wall))
    bad = [p for p in pairs if max(p[2]) > p[3]]
    if bad:
        print('bench: WARNING: {} scheme pairs differ by more than their tolerance'.format(len(bad)))


def pair_tolerance(s):
    """Stated agreement of the two schemes (PERFORMANCE.md): the paper scheme
    stops each step with its force within cr1 of the step's root (eq. 17),
    approached from one side, a bias the contact dynamics carry over several
    steps (measured up to 2.1 cr1); the plate iterations of both stop at a
    relative change sqrt(cr2) (eq. 18). Three times the larger."""
    return 3.0 * max(s['cr1'], math.sqrt(s['cr2']))


def platform_cpu():
    try:
        with open('/proc/cpuinfo') as f:
            for line in f:
                if line.startswith('model name'):
                    return line.split(':', 1)[1].strip()
    except OSError:
        pass
    return 'unknown CPU'


def plots():
    for gp in ('bench_pareto.gp', 'bench_cost.gp'):
        r = subprocess.run(['gnuplot', '-e', "results='{}'; outdir='{}'".format(RESULTS, FIG_DIR),
                            os.path.join(ROOT, 'postproc', gp)], capture_output=True, text=True)
        if r.returncode != 0:
            print('bench: gnuplot {} failed: {}'.format(gp, r.stderr[-1000:]))


def write_doc(rows, refs, hows, pairs, tol, cost, kern, by_sweep, ob_recs, wall, args, floors, alt_name):
    L = []
    L.append('*Generated by `make bench` on {} ({:.0f} s of wall time, {} repeats{}); '
             'do not edit between the markers.*'.format(time.strftime('%Y-%m-%d %H:%M'), wall, args.repeat,
                                                         ', quick grid' if args.quick else ''))
    L.append('')
    L.append('System BLAS (what ./impact loads): {} (`{}`); "system" in the tables below is that one.'.format(
        blas_name(system_blas()), system_blas()))
    L.append('')
    # the floor
    L.append('### The floor')
    L.append('')
    for f in floors:
        L.append('- ' + floor_line(f) + '; libblas: `{}`.'.format(f['path']))
    if not floors:
        L.append('- (not measured: build/bench/bench_kernels missing, or the main job failed)')
    L.append('')
    # the paper's scene, both schemes
    L.append('### The paper scene: 6x9 quarter mesh, 2.5 us, clamped, nonlinear, 3 ms')
    L.append('')
    L.append('| scheme | BLAS | CPU (s), median | set-up (s) | steps | plate solves | solves per step | peak force (N) | max deflection (mm) |')
    L.append('|---|---|---|---|---|---|---|---|---|')
    scene_runs = [('system', r) for sc, r in by_sweep.get('paper_scene', [])] + [(alt_name, r) for _, _, r in ob_recs]
    for blas, r in scene_runs:
        L.append('| {} | {} | {:.3f} | {:.3f} | {} | {} | {:.2f} | {:.1f} | {:.4f} |'.format(
            r['settings']['scheme'], blas, median(r['cpu']), median(r['setup']), r['steps'], r['solves'],
            r['solves'] / r['steps'], r['peak'], r['wmax']))
    sp = {(b, r['settings']['scheme']): r for b, r in scene_runs}
    if ('system', 'paper') in sp and ('system', 'fast') in sp:
        a, b = sp[('system', 'paper')], sp[('system', 'fast')]
        L.append('')
        L.append('The fast scheme needs {:.1f}x fewer plate solves and {:.1f}x less CPU time than the paper scheme.'.format(
            a['solves'] / b['solves'], median(a['cpu']) / median(b['cpu'])))
    L.append('')
    # solve bound
    L.append('### A plate solve against its bound')
    L.append('')
    L.append('A band solve is two triangular sweeps, 4 N kd flops, reading the factor (8 (kd+1) N bytes) twice. '
             'Its bound is the larger of two times measured on this machine by bench/kernels.f90: the flops at the '
             'peak multiply-add rate (independent vector FMAs), and two reads of the factor at the rate one pass '
             'over it runs. At 0.25 flop per byte the reads always bound it.')
    L.append('')
    L.append('| mesh | BLAS | N | kd | solve (ms) | GFLOP/s | peak GFLOP/s | dgemm GFLOP/s | read GB/s | bound (ms) | fraction of bound | M x (ms) | K_N(D)D (ms) |')
    L.append('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    frac69 = {}
    for label, blas, k in kern:
        ts = float(k['solve_s'])
        bound = max(float(k['solve_flop_bound_s']), float(k['solve_read_bound_s']))
        frac69[(label, blas)] = (ts, bound)
        L.append('| {} | {} | {} | {} | {:.3f} | {:.2f} | {:.1f} | {:.1f} | {:.1f} | {:.3f} | {:.0%} | {:.3f} | {:.3f} |'.format(
            label, blas, k['equations'], k['half_bandwidth'], ts * 1e3, float(k['solve_gflop_s']),
            float(k['peak_gflop_s']), float(k['gemm_gflop_s']), float(k['stream_gbyte_s']), bound * 1e3, bound / ts,
            float(k['mass_s']) * 1e3, float(k['knl_s']) * 1e3))
    L.append('')
    for blas, r in scene_runs:
        key = ('6x9', blas)
        if key in frac69:
            loop = median(r['cpu']) - median(r['setup'])
            ins = r['solves'] * frac69[key][0]
            L.append('- paper scene, scheme {}, {} BLAS: solves {:.0%} of the time loop, {:.0%} outside solves '
                     '(solves x solve time / (CPU - set-up)).'.format(
                         r['settings']['scheme'], blas, ins / loop, 1 - ins / loop))
    L.append('')
    # cost slope
    L.append('### Cost per time step against freedoms')
    L.append('')
    for sweep, name in (('cost', 'band'), ('cost_sky', 'skyline')):
        for per in ('steps', 'solves'):
            pts, (b, a) = cost.get((sweep, per), ([], (float('nan'), 0)))
            if pts:
                L.append('- {}, CPU per {}: slope {:.2f} (least squares on log-log, N >= 1000); N = {} ... {}: '
                         '{:.3f} ... {:.1f} ms.'.format(name, per[:-1], b, pts[0][0], pts[-1][0],
                                                        pts[0][1] * 1e3, pts[-1][1] * 1e3))
    its = [(r['neq'], r['solves'] / r['steps']) for _, r in sorted(by_sweep.get('cost', []), key=lambda x: x[1]['neq'])]
    if its:
        L.append('- plate solves per step in these runs: ' + ', '.join('{:.1f} (N = {})'.format(b, a) for a, b in its) + '.')
    L.append('')
    # references
    L.append('### References (converged answers) and observed orders')
    L.append('')
    quick = args.quick
    mesh_seq = '-'.join('{}x{}'.format(*m) for m in (REF_MESHES if not quick else [(2, 3), (4, 6), (8, 12)]))
    check_seq = '-'.join('{}x{}'.format(*m) for m in CHECK_MESHES) if not quick else ''
    dts_all = REF_DTS if not quick else [10e-6, 5e-6, 2.5e-6, 1.25e-6]
    dt_seq = '-'.join('{:g}'.format(d * 1e6) for d in dts_all[-3:])
    dt_coarse_seq = '-'.join('{:g}'.format(d * 1e6) for d in dts_all[:3])
    L.append('q* = R_h + R_dt - q0 (bench/run_bench.py): R_h the Richardson limit of the meshes {} (2.5 us), '
             'R_dt that of the steps {} us (6x9), q0 the 6x9, 2.5 us run; iteration error removed (fast, '
             'cr2 = 1e-10 on the nonlinear scenes). p = log2((q1 - q2)/(q2 - q3)) on each sequence of three '
             '(ratio 2). Richardson applies where the sequence converges monotonically with {:g} <= p <= {:g}; '
             'otherwise the cell says why and the finest run stands for that limit. The other two order '
             'columns are checks, not used in q*: the meshes {} (2.5 us) and the steps {} us (6x9). '
             '"6x9 mesh" and "2.5 us step": the two parts of the error of q0, q0 - R_h and q0 - R_dt, '
             'relative to q*. Uncertainty: the distance of the finest runs from their limits (where '
             'Richardson did not apply: the spread of the sequence\'s last three runs), plus the largest '
             'defect of the additive error model measured where mesh and step are refined together (next '
             'table); errors below it are not resolved.'.format(mesh_seq, dt_seq, P_RANGE[0], P_RANGE[1], check_seq or '(none, quick grid)',
                                    dt_coarse_seq))
    L.append('')

    def pcell(res, q):
        if res is None:
            return '-'
        p, ok, status = res
        if ok:
            return '{:.2f}'.format(p) if p != float('inf') else 'exact'
        ch = changes(q[-3:])
        txt = ', '.join('{:+.3f} %'.format(100 * c) for c in ch)
        if status == 'p out of range':
            return '**{:.2f}, out of range** ({})'.format(p, txt)
        return '**{}** ({})'.format(status, txt)

    names = dict(peak='peak force (N)', duration='first contact (us)', wmax='max deflection (mm)')
    fmts = dict(peak='{:.2f}', duration='{:.2f}', wmax='{:.5f}')
    L.append('| scene | measure | q* | mesh p, {} | time-step p, {} us | check: mesh p, {} | check: time-step p, {} us | '
             '6x9 mesh | 2.5 us step | uncertainty |'.format(mesh_seq, dt_seq, check_seq or '-', dt_coarse_seq))
    L.append('|---|---|---|---|---|---|---|---|---|---|')
    for scene, ref in refs.items():
        for key in ('peak', 'duration', 'wmax'):
            h = hows[scene][key]
            dts_q = h['qd']
            L.append('| {} | {} | {} | {} | {} | {} | {} | {:+.3%} | {:+.3%} | {:.3%} |'.format(
                scene, names[key], fmts[key].format(ref[key]), pcell(h['mesh'], h['qm']), pcell(h['dt'], dts_q),
                pcell(h['mesh_check'], h['qc']), pcell(h['dt_coarse'], dts_q[:3]),
                h['err_h'], h['err_dt'], h['unc']))
    L.append('')
    if any(hows[sc][k].get('add') for sc in refs for k in ('peak', 'duration', 'wmax')):
        L.append('Do the errors of the mesh and the step add? Runs with both refined (sweep mesh_dt) against '
                 'q(h, 2.5 us) + q(6x9, dt) - q(6x9, 2.5 us) from the one-knob sweeps (default tolerances); '
                 'defect relative to q*:')
        L.append('')
        L.append('| scene | run | peak force: measured / predicted (N), defect | first contact (us) | max deflection (mm) |')
        L.append('|---|---|---|---|---|')
        for scene in refs:
            adds = hows[scene]['peak'].get('add', [])
            for i, (mesh, dt, _, _) in enumerate(adds):
                cells = []
                for key in ('peak', 'duration', 'wmax'):
                    _, _, m, pr = hows[scene][key]['add'][i]
                    cells.append('{} / {}, {:+.2%}'.format(fmts[key].format(m), fmts[key].format(pr),
                                                            (m - pr) / refs[scene][key]))
                L.append('| {} | {} at {:g} us | {} |'.format(scene, mesh, dt * 1e6, ' | '.join(cells)))
        L.append('')
    L.append('The sequences (fast scheme; peak force N / first contact us / max deflection mm):')
    L.append('')
    for scene in refs:
        hw = hows[scene]
        for label, qk, tags in (('meshes', 'qm', mesh_seq.split('-')), ('check meshes', 'qc', check_seq.split('-') if check_seq else []),
                                ('steps (us)', 'qd', ['{:g}'.format(d * 1e6) for d in dts_all])):
            if not hw['peak'][qk]:
                continue
            L.append('- {} {}: '.format(scene, label) + '; '.join(
                '{} {:.2f} / {:.2f} / {:.5f}'.format(t, hw['peak'][qk][i], hw['duration'][qk][i], hw['wmax'][qk][i])
                for i, t in enumerate(tags)))
    L.append('')
    # the paper's model
    m91 = {}
    for sc, r in by_sweep.get('mesh_1991', []):
        m91.setdefault(sc, []).append(r)
    if m91:
        L.append("### The paper's model on the same meshes (2x2 shear, point force)")
        L.append('')
        L.append("`shear_rule = 'selective'`, `load = 'point'` (the decks of input/paper/), fast scheme, 2.5 us, "
                 "cr2 = 1e-7; errors against the converged model's q* above. Change per halving: from the mesh "
                 "with half as many elements per side.")
        L.append('')
        L.append('| scene | mesh | peak force (N) | first contact (us) | max deflection (mm) | error F / T / w against q* | change per halving F / T / w |')
        L.append('|---|---|---|---|---|---|---|')
        notes = []
        for sc, lst in m91.items():
            lst = sorted(lst, key=lambda r: r['settings']['ny'])
            byny = {r['settings']['ny']: r for r in lst}
            for r in lst:
                st = r['settings']
                e = [abs(r[k] - refs[sc][k]) / abs(refs[sc][k]) if sc in refs else float('nan') for k in ('peak', 'duration', 'wmax')]
                half = byny.get(st['ny'] // 2) if st['ny'] % 2 == 0 else None
                ch = ('{:+.2%} / {:+.2%} / {:+.2%}'.format(*[(r[k] - half[k]) / half[k] for k in ('peak', 'duration', 'wmax')])
                      if half else '')
                L.append('| {} | {}x{} | {:.2f} | {:.2f} | {:.5f} | {:.2%} / {:.2%} / {:.2%} | {} |'.format(
                    sc, st['ny'], st['nx'], r['peak'], r['duration'], r['wmax'], *e, ch))
            for tag, chain in (('4x6-8x12-16x24', [4, 8, 16]), ('6x9-12x18', [6, 12])):
                if all(n in byny for n in chain) and len(chain) == 3:
                    cells = []
                    for k in ('peak', 'duration', 'wmax'):
                        q = [byny[n][k] for n in chain]
                        cells.append(names[k].split(' (')[0] + ': ' + pcell(richardson(q)[1:], q))
                    notes.append('- {} {}: '.format(sc, tag) + '; '.join(cells) + '.')
        L.append('')
        if notes:
            L.append('Observed orders of the paper\'s model (as in the table above):')
            L.append('')
            L.extend(notes)
            L.append('')
    L.append('### The two schemes on the grid')
    L.append('')
    if pairs:
        worst = [max(p[2][i] for p in pairs) for i in range(3)]
        nbad = sum(1 for p in pairs if max(p[2]) > p[3])
        L.append('{} pairs of runs that differ only in the scheme (meshes, steps, tolerances, all scenes). '
                 'Largest relative difference: peak force {:.3%}, first contact {:.3%}, max deflection {:.3%}; '
                 'tolerance 3 max(cr1, sqrt(cr2)) ({:.1%} at the defaults): {}.'.format(
                     len(pairs), worst[0], worst[1], worst[2], tol,
                     'all within' if nbad == 0 else '{} outside'.format(nbad)))
        ratios = [p[0]['solves'] / p[1]['solves'] for p in pairs]
        L.append('Plate solves, paper / fast: {:.1f}x to {:.1f}x (median {:.1f}x).'.format(
            min(ratios), max(ratios), statistics.median(ratios)))
        L.append('')
        L.append('| scene | mesh | dt (us) | t_end (us) | cr1 | cr2 | solves paper | solves fast | dF | dT | dw | tolerance |')
        L.append('|---|---|---|---|---|---|---|---|---|---|---|---|')
        for rp, rf, d, tp in sorted(pairs, key=lambda p: (p[0]['scene'], p[0]['settings']['ny'], -p[0]['settings']['dt'], p[0]['settings']['cr1'], p[0]['settings']['cr2'])):
            s = rp['settings']
            L.append('| {} | {}x{} | {:g} | {:g} | {:g} | {:g} | {} | {} | {:.3%} | {:.3%} | {:.3%} | {:.2%} |'.format(
                rp['scene'], s['ny'], s['nx'], s['dt'] * 1e6, s['t_end'] * 1e6, s['cr1'], s['cr2'],
                rp['solves'], rf['solves'], *d, tp))
    L.append('')
    failed = sorted({(r[0], r[5], r[6], r[9], r[2], r[11], r[12]) for r in rows if r[29] == 'failed'})
    if failed:
        L.append('Runs that stopped (an iteration could not converge at these tolerances): ' + '; '.join(
            '{} {}x{} {:g} us {} cr1 = {:g}, cr2 = {:g}'.format(*f) for f in failed) + '.')
        L.append('')
    # recommendations
    L.append('### Cheapest measured settings for a given accuracy')
    L.append('')
    L.append('Largest of the three relative errors (peak force, first contact, max deflection) against the '
             'reference; the cheapest run of the grid (median CPU) that reaches it.')
    L.append('')
    L.append('| scene | error <= | mesh | dt (us) | scheme | cr1 | cr2 | storage | CPU (s) | errors F / T / w | note |')
    L.append('|---|---|---|---|---|---|---|---|---|---|---|')
    for scene in SCENES:
        if scene not in refs:
            continue
        cand = [r for r in rows if r[0] == scene and r[4] == 'system' and r[28] == r[28]
                and not r[1].startswith(ONCE)]
        unc = max(h['unc'] for h in hows[scene].values() if h['unc'] == h['unc'])
        for target in (0.05, 0.02, 0.01, 0.005, 0.002, 0.001):
            ok = [r for r in cand if r[28] <= target]
            if not ok:
                L.append('| {} | {:.1%} | not reached on the grid | | | | | | | | |'.format(scene, target))
                continue
            b = min(ok, key=lambda r: r[14])
            note = 'below the reference uncertainty ({:.2%})'.format(unc) if target < unc else ''
            L.append('| {} | {:.1%} | {}x{} | {:g} | {} | {:g} | {:g} | {} | {:.3f} | {:.2%} / {:.2%} / {:.2%} | {} |'.format(
                scene, target, b[5], b[6], b[9], b[2], b[11], b[12], b[3], b[14], b[25], b[26], b[27], note))
    L.append('')
    if 'bench' not in imf.fill_file(DOC, {'bench': '\n'.join(L)}, keep_others=True):
        sys.exit('bench: {}: no bench:begin / bench:end block to fill'.format(DOC))


if __name__ == '__main__':
    main()
