#!/usr/bin/env python3
"""make stress: ./impact far from the paper's scene.

Runs every scene of SCENES (below) through ./impact, at most --jobs at a
time, and checks each one:
  - no NaN or Inf anywhere in its history or summary;
  - it completed, or it stopped with the diagnostic of a time step that did
    not converge ("time step did not converge", naming the step, the time
    and the residuals) -- never a silent wrong answer, never a crash or a
    time-out;
  - the energy balance (history column 13, E0 - (kinetic + strain +
    contact energy)) stays within ENERGY_LOST of E0 = m v0^2/2, and no
    energy is created beyond ENERGY_CREATED of E0.
Each scene changes one thing of the paper's scene (the clamped 150 x 100 x
2.7 mm plate, quarter 9 x 6 mesh, 243 g at 3 m/s, 2.5 us steps, nonlinear),
except the few marked 'beyond', which combine extremes on purpose.

Writes build/stress/results.dat (one row per scene, a '#' header naming
each column and its unit) and DOCS/STABILITY.md: a copy of docs/STABILITY.md
with its blocks filled (<!-- name:begin --> ... <!-- name:end -->: the table,
the envelope, the worst energy error, the scenes that needed a fall-back;
impact_files.fill_file). DOCS is --docs-dir: out/docs by default (make stress
gives $(DOCS_DIR)); with docs, docs/STABILITY.md is filled in place (make
docs: the published document). With --only, the report holds only those
scenes: written to out/docs and the like, never to docs/.
The scenes run through impact_files.run_many. Exit status 0 when every scene
passes, 1 otherwise.

With --random N, the scenes are instead N random extreme scenes
(random_scenes: mass, velocity, thickness, time step, mesh, edges and theory
drawn at random over the ranges of SCENES, scheme 'fast', 400 steps each;
--seed S makes another draw); their report goes to out/docs, never docs/.

Usage: tools/stress/stress.py [--jobs N] [--only NAME...] [--random N [--seed S]] [--impact PATH]
                              [--docs-dir DIR]
Python 3 standard library only.
"""

import argparse
import math
import os
import random
import re
import shutil
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WORK = os.path.join(ROOT, 'build', 'stress')
# The committed document, the template of every report.
TEMPLATE = os.path.join(ROOT, 'docs', 'STABILITY.md')
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import impact_files as imf  # noqa: E402

# The stated energy bound, as fractions of the impact energy E0 = m v0^2/2:
# the integration may lose at most ENERGY_LOST and create at most
# ENERGY_CREATED (docs/STABILITY.md, "The energy bound").
ENERGY_LOST = 0.01
ENERGY_CREATED = 0.001
# Wall-clock limit of one scene (s): a scene that takes longer has hung.
TIMEOUT_S = 900

# The paper's scene, with the paper's scheme (stated: the default is 'fast'):
# every scene starts from it.
BASE = {
    'plate': {'a': '0.15', 'b': '0.10', 'h': '0.0027'},
    'impactor': {'mass': '0.243', 'velocity': '3.0'},
    'mesh': {'nx': '9', 'ny': '6', 'domain': "'quarter'"},
    'boundary': {'edges': "'clamped'"},
    'analysis': {'theory': "'nonlinear'", 'dt': '2.5e-6', 't_end': '3.0e-3', 'scheme': "'paper'"},
    'output': {'every': '1', 'hdf5': '.false.', 'overwrite': '.true.'},
}


def scene(name, what, changes):
    """A scene: its name, what it tests, and the deck variables it changes
    ({'group': {'variable': 'value'}})."""
    return {'name': name, 'what': what, 'changes': changes}


def group(title, *scenes, beyond=False):
    """The scenes of one row group of the table, under its title; beyond:
    they combine extremes on purpose, past what the model covers."""
    return [dict(sc, group=title, beyond=beyond) for sc in scenes]


SCENES = [
    *group('reference',
           scene('paper', "the paper's clamped plate (Fig. 10)", {})),
    # -- time steps
    *group('time step',
           scene('dt_0.05us', 'dt = 0.05 us (4000 steps to 0.2 ms)',
                 {'analysis': {'dt': '5.0e-8', 't_end': '2.0e-4'}, 'output': {'every': '20'}}),
           scene('dt_0.25us', 'dt = 0.25 us (4000 steps to 1 ms)',
                 {'analysis': {'dt': '2.5e-7', 't_end': '1.0e-3'}, 'output': {'every': '20'}}),
           scene('dt_10us', 'dt = 10 us', {'analysis': {'dt': '1.0e-5'}}),
           scene('dt_20us', 'dt = 20 us', {'analysis': {'dt': '2.0e-5'}}),
           scene('dt_20us_fixed_point', "dt = 20 us, force_update = 'fixed_point'",
                 {'analysis': {'dt': '2.0e-5', 'force_update': "'fixed_point'"}}),
           scene('dt_20us_fast', "dt = 20 us, scheme = 'fast'",
                 {'analysis': {'dt': '2.0e-5', 'scheme': "'fast'"}})),
    # -- impactor velocity and mass
    *group('impactor',
           scene('v_0.05', 'v0 = 0.05 m/s', {'impactor': {'velocity': '0.05'}}),
           scene('v_50', 'v0 = 50 m/s', {'impactor': {'velocity': '50.0'}, 'analysis': {'t_end': '1.0e-3'}}),
           scene('m_1g', 'm = 1 g', {'impactor': {'mass': '0.001'}, 'analysis': {'t_end': '1.0e-3'}}),
           scene('m_20kg', 'm = 20 kg (10 ms)',
                 {'impactor': {'mass': '20.0'}, 'analysis': {'t_end': '1.0e-2'}, 'output': {'every': '4'}})),
    # -- meshes
    *group('mesh',
           scene('mesh_1x1', 'quarter 1 x 1 (one element)', {'mesh': {'nx': '1', 'ny': '1'}}),
           scene('mesh_72x48', "quarter 72 x 48 (the paper's 8 x 12 refined 6 times; 68640 equations), 10 steps",
                 {'mesh': {'nx': '72', 'ny': '48'}, 'analysis': {'t_end': '2.5e-5', 'scheme': "'fast'"}}),
           scene('full_skyline', "full plate 18 x 12, skyline storage",
                 {'mesh': {'nx': '18', 'ny': '12', 'domain': "'full'"},
                  'analysis': {'storage': "'skyline'", 't_end': '1.0e-3'}})),
    # -- plates
    *group('plate',
           scene('thin_a_h_1000', 'a/h = 1000 (h = 0.15 mm)', {'plate': {'h': '1.5e-4'}, 'analysis': {'t_end': '1.0e-3'}}),
           scene('thick_a_h_5', 'a/h = 5 (h = 30 mm)', {'plate': {'h': '0.03'}, 'analysis': {'t_end': '1.0e-3'}}),
           scene('e1_e2_100', 'E1/E2 = 100 (E2 = 1.2 GPa)', {'lamina': {'e2': '1.2e9'}})),
    # -- edges and theory
    *group('edges, theory',
           scene('free', 'free edges', {'boundary': {'edges': "'free'"}}),
           scene('ss_immovable', 'simply supported, immovable in-plane',
                 {'boundary': {'edges': "'simply_supported'", 'inplane': "'immovable'"}}),
           scene('ss_movable', 'simply supported, movable in-plane',
                 {'boundary': {'edges': "'simply_supported'", 'inplane': "'movable'"}}),
           scene('linear', 'linear theory', {'analysis': {'theory': "'linear'"}}),
           scene('fast', "scheme = 'fast'", {'analysis': {'scheme': "'fast'"}})),
    # -- repeated contacts
    *group('contacts',
           scene('free_heavy_20kg', 'free plate, 20 kg impactor (10 ms)',
                 {'boundary': {'edges': "'free'"}, 'impactor': {'mass': '20.0'},
                  'analysis': {'t_end': '1.0e-2'}, 'output': {'every': '4'}}),
           scene('free_light_20g', 'free plate, 20 g impactor, dt = 1 us (6 ms)',
                 {'boundary': {'edges': "'free'"}, 'impactor': {'mass': '0.02'},
                  'analysis': {'dt': '1.0e-6', 't_end': '6.0e-3'}, 'output': {'every': '4'}}),
           scene('ss_100g', 'simply supported, 100 g impactor, dt = 1 us (6 ms)',
                 {'boundary': {'edges': "'simply_supported'"}, 'impactor': {'mass': '0.1'},
                  'analysis': {'dt': '1.0e-6', 't_end': '6.0e-3'}, 'output': {'every': '4'}})),
    # -- the paper's Fig. 6(a): a 4 x 6 mesh and time steps from 10 us down
    *group('Fig. 6(a)',
           scene('fig6a_dt10us', '4 x 6, dt = 10 us', {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '1.0e-5'}}),
           scene('fig6a_dt1us', '4 x 6, dt = 1 us', {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '1.0e-6'}}),
           scene('fig6a_dt0.25us', '4 x 6, dt = 0.25 us',
                 {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '2.5e-7'}, 'output': {'every': '4'}}),
           scene('fig6a_dt10us_fp', "4 x 6, dt = 10 us, force_update = 'fixed_point'",
                 {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '1.0e-5', 'force_update': "'fixed_point'"}}),
           scene('fig6a_dt1us_fp', "4 x 6, dt = 1 us, force_update = 'fixed_point'",
                 {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '1.0e-6', 'force_update': "'fixed_point'"}}),
           scene('fig6a_dt0.25us_fp', "4 x 6, dt = 0.25 us, force_update = 'fixed_point'",
                 {'mesh': {'nx': '6', 'ny': '4'}, 'analysis': {'dt': '2.5e-7', 'force_update': "'fixed_point'"},
                  'output': {'every': '4'}})),
    # -- beyond: extremes combined, on purpose past what the model covers
    *group('beyond',
           scene('beyond_thin_50', 'a/h = 1000 at 50 m/s (w/h ~ 100)',
                 {'plate': {'h': '1.5e-4'}, 'impactor': {'velocity': '50.0'}, 'analysis': {'t_end': '1.0e-3'}}),
           scene('beyond_thin_50_fast', "a/h = 1000 at 50 m/s, scheme = 'fast'",
                 {'plate': {'h': '1.5e-4'}, 'impactor': {'velocity': '50.0'},
                  'analysis': {'t_end': '1.0e-3', 'scheme': "'fast'"}}),
           scene('beyond_dt20_v50', 'dt = 20 us at 50 m/s',
                 {'analysis': {'dt': '2.0e-5'}, 'impactor': {'velocity': '50.0'}}), beyond=True),
]


def random_scenes(n, seed):
    """n random extreme scenes: the paper's scene with the impactor's mass
    (1 g - 20 kg), its velocity (0.05 - 50 m/s), the thickness (0.15 - 30 mm,
    a/h 1000 - 5) and the time step (0.25 - 20 us) drawn log-uniformly, the
    quarter mesh (4 x 3 - 18 x 12), the edges and the theory at random, scheme
    'fast' (the default), 400 steps each. The same seed gives the same scenes."""
    rng = random.Random(seed)

    def log_uniform(lo, hi):
        return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))
    scenes = []
    for i in range(n):
        mass, velocity = log_uniform(1.0e-3, 20.0), log_uniform(0.05, 50.0)
        h, dt = log_uniform(1.5e-4, 0.03), log_uniform(2.5e-7, 2.0e-5)
        nx = rng.choice([4, 6, 9, 12, 18])
        edges = rng.choice(['clamped', 'simply_supported', 'free'])
        theory = rng.choice(['nonlinear', 'nonlinear', 'linear'])
        what = 'm %.3g kg, v0 %.3g m/s, h %.3g mm, dt %.3g us, %d x %d, %s, %s' % (
            mass, velocity, h * 1e3, dt * 1e6, nx, 2 * nx // 3, edges, theory)
        scenes.append(dict(scene('random_%03d' % (i + 1), what, {
            'impactor': {'mass': '%.6g' % mass, 'velocity': '%.6g' % velocity},
            'plate': {'h': '%.6g' % h},
            'mesh': {'nx': str(nx), 'ny': str(2 * nx // 3)},
            'boundary': {'edges': "'%s'" % edges},
            'analysis': {'theory': "'%s'" % theory, 'dt': '%.6g' % dt, 't_end': '%.6g' % (400 * dt),
                         'scheme': "'fast'"}}), group='random', beyond=True))
    return scenes


def scene_deck(sc, prefix):
    """The deck of a scene (its groups): the paper's scene with the scene's changes."""
    groups = [[g, [[name, value] for name, value in values.items()]] for g, values in BASE.items()]
    for g, changes in sc['changes'].items():
        for name, value in changes.items():
            imf.set_value(groups, g, name, value)
    imf.set_value(groups, 'output', 'prefix', "'%s'" % prefix)
    return groups


def prepare(sc):
    """Writes the deck of a scene (build/stress/runs/NAME.nml) and removes its
    old results; returns its run for impact_files.run_many."""
    d = os.path.join(WORK, 'runs')
    os.makedirs(d, exist_ok=True)
    prefix = os.path.join(d, sc['name'])
    imf.write_deck(prefix + '.nml', scene_deck(sc, prefix),
                   ['make stress (tools/stress/stress.py), scene %s: %s' % (sc['name'], sc['what'])])
    for suffix in ('_history.dat', '_summary.dat'):
        if os.path.exists(prefix + suffix):
            os.remove(prefix + suffix)
    return {'deck': prefix + '.nml', 'scene': sc, 'prefix': prefix}


def analyse(run):
    """The row of results of a scene (a dict) from its run (run_many)."""
    sc, prefix, stderr = run['scene'], run['prefix'], run['stderr']
    name = sc['name']
    status = 'timeout' if run['timed_out'] else run['exit']
    wall = run['elapsed_s']
    with open(prefix + '.err', 'w') as f:
        f.write(stderr)
    r = {'name': name, 'group': sc['group'], 'what': sc['what'], 'beyond': sc['beyond'],
         'exit': status, 'wall_s': wall, 'problems': []}
    hist = prefix + '_history.dat'
    summ = prefix + '_summary.dat'
    rows = imf.read_columns(hist)[1] if os.path.exists(hist) else []     # a field not a number: NaN
    s = {}                                  # the summary: numbers as floats ('*'s: inf), the rest as text
    for k, v in (imf.read_keys(summ) if os.path.exists(summ) else {}).items():
        n = imf.summary_value(v)
        s[k] = v if n is None else n
    r['rows'] = len(rows)
    r['nan'] = any(not math.isfinite(v) for row in rows for v in row) \
        or any(isinstance(v, float) and not math.isfinite(v) for v in s.values())
    e0 = s.get('initial_energy_J')
    errs = [row[12] for row in rows if len(row) >= 13 and math.isfinite(row[12])]
    if isinstance(e0, float) and e0 > 0 and errs:
        r['lost'] = max(errs) / e0
        r['created'] = max(0.0, -min(errs)) / e0
    else:
        r['lost'] = r['created'] = math.nan
    for key in ('steps', 'peak_force_N', 'contacts', 'max_w_over_h', 'nonlinear_fallback_steps',
                'contact_fallback_steps', 'substepped_steps', 'warnings', 'plate_solves', 'factorizations',
                'cpu_s', 'unconverged_steps'):
        r[key] = s.get(key, math.nan)
    r['status'] = s.get('status', '(no summary)')
    diag = [l for l in stderr.splitlines() if 'time step did not converge' in l]
    r['diagnostic'] = diag[0] if diag else ''
    # -- the verdict
    if r['nan']:
        r['problems'].append('NaN or Inf in the results')
    if status == 'timeout':
        r['problems'].append('no answer within %d s' % TIMEOUT_S)
    elif status == 0:
        if r['status'] != 'completed':
            r['problems'].append('exit 0 but status %s' % r['status'])
    elif status == 1 and diag and re.search(r'failed at step \d+', str(r['status'])) \
            and re.search(r'ratio|residual|F_assum', diag[0]):
        pass                        # stopped with the diagnostic: step, time, residuals
    else:
        r['problems'].append('exit status %s without the diagnostic of a step: %s'
                             % (status, (stderr.strip().splitlines() or [''])[-1][:200]))
    # energy lost or created beyond the bound is a problem unless the run said
    # so itself: the warning on standard error, which names the step (the
    # summary's max_energy_lost_J and max_energy_created_J come from the same
    # rows as r['lost'] and r['created'], so they cannot show a missed warning)
    lost_warned = 'the integration has lost' in stderr
    created_warned = 'the integration has created' in stderr
    r['energy_warned'] = lost_warned or created_warned
    if not (r['lost'] <= ENERGY_LOST) and not lost_warned:
        r['problems'].append('energy lost %.3g E0 > %.3g E0, not warned' % (r['lost'], ENERGY_LOST))
    if not (r['created'] <= ENERGY_CREATED) and not created_warned:
        r['problems'].append('energy created %.3g E0 > %.3g E0, not warned' % (r['created'], ENERGY_CREATED))
    if status == 0 and r['energy_warned']:
        r['outcome'] = 'completed, energy warned'
    elif status == 0:
        r['outcome'] = 'completed'
    elif diag:
        r['outcome'] = 'stopped: diagnostic'
    else:
        r['outcome'] = 'FAILED'
    r['pass'] = not r['problems']
    return r


# results.dat columns: (key, unit, meaning, format)
COLUMNS = [
    ('name', '-', 'scene', '{}'),
    ('pass', '-', '1 when the scene passed every check', '{:d}'),
    ('exit', '-', 'exit status of ./impact', '{}'),
    ('steps', '-', 'time steps done', '{:.0f}'),
    ('nan', '-', '1 when a NaN or Inf was found', '{:d}'),
    ('lost', 'E0', 'largest energy lost by the integration (history column 13 / E0)', '{:.3e}'),
    ('created', 'E0', 'largest energy created (-column 13 / E0, 0 if never negative)', '{:.3e}'),
    ('peak_force_N', 'N', 'peak contact force', '{:.5g}'),
    ('contacts', '-', 'separate contacts', '{:.0f}'),
    ('max_w_over_h', '-', 'largest plate deflection / thickness', '{:.3g}'),
    ('nonlinear_fallback_steps', '-', 'steps where eq. (19) fell back to Anderson mixing', '{:.0f}'),
    ('contact_fallback_steps', '-', 'steps where the contact iteration fell back', '{:.0f}'),
    ('substepped_steps', '-', "steps of scheme 'fast' taken again in sub-steps", '{:.0f}'),
    ('factorizations', '-', 'factorizations of the left-hand matrix', '{:.0f}'),
    ('plate_solves', '-', 'back substitutions', '{:.0f}'),
    ('cpu_s', 's', 'cpu time ./impact reports', '{:.2f}'),
    ('wall_s', 's', 'wall-clock time of the run', '{:.1f}'),
]


def fmt(value, f):
    if isinstance(value, bool):
        value = int(value)
    if isinstance(value, float) and not math.isfinite(value):
        return 'nan'
    try:
        return f.format(value)
    except (ValueError, TypeError):
        return str(value)


def write_results(results, path):
    with open(path, 'w') as f:
        f.write('# make stress: one row per scene (tools/stress/stress.py); E0 = m v0^2/2\n')
        for i, (k, unit, meaning, _) in enumerate(COLUMNS, 1):
            f.write('# %2d %-26s %-4s %s\n' % (i, k, unit, meaning))
        f.write('# ' + ' '.join(k for k, *_ in COLUMNS) + '\n')
        for r in results:
            f.write(' '.join(fmt(r[k], fm) for k, _, _, fm in COLUMNS) + '\n')


def md_table(results):
    head = ('| scene | what changes | outcome | steps | NaN/Inf | energy lost (E0) | energy created (E0) '
            '| peak F (N) | contacts | max w/h | fall-back steps (eq. 19 / contact / sub-stepped) | cpu (s) | check |')
    lines = [head, '|' + '---|' * (head.count('|') - 1)]
    for r in results:
        lines.append('| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s / %s / %s | %s | %s |' % (
            r['name'], r['what'], r['outcome'], fmt(r['steps'], '{:.0f}'), 'yes' if r['nan'] else 'no',
            fmt(r['lost'], '{:.2e}'), fmt(r['created'], '{:.2e}'), fmt(r['peak_force_N'], '{:.4g}'),
            fmt(r['contacts'], '{:.0f}'), fmt(r['max_w_over_h'], '{:.3g}'),
            fmt(r['nonlinear_fallback_steps'], '{:.0f}'), fmt(r['contact_fallback_steps'], '{:.0f}'),
            fmt(r['substepped_steps'], '{:.0f}'), fmt(r['cpu_s'], '{:.1f}'), 'pass' if r['pass'] else 'FAIL: ' + '; '.join(r['problems'])))
    return '\n'.join(lines)


def write_report(results, elapsed, jobs, report):
    """Writes report: docs/STABILITY.md (the template) with its blocks filled
    with the numbers of this run (in place when report is the template)."""
    finite = [r for r in results if math.isfinite(r['lost'])]
    worst_lost = max(finite, key=lambda r: r['lost']) if finite else None
    worst_created = max(finite, key=lambda r: r['created']) if finite else None
    fallbacks = [r for r in results if (r['nonlinear_fallback_steps'] or 0) > 0 or (r['contact_fallback_steps'] or 0) > 0]
    stopped = [r for r in results if r['outcome'].startswith('stopped')]
    failed = [r for r in results if not r['pass']]
    os.makedirs(os.path.dirname(report), exist_ok=True)
    if not (os.path.exists(report) and os.path.samefile(report, TEMPLATE)):
        shutil.copyfile(TEMPLATE, report)
    imf.fill_file(report, {
        'table': md_table(results),
        'nscenes': str(len(results)),
        'npass': str(len(results) - len(failed)),
        'elapsed': '%.0f' % elapsed,
        'jobs': str(jobs),
        'energy_lost': '%g' % ENERGY_LOST,
        'energy_created': '%g' % ENERGY_CREATED,
        'worst_lost': ('%.2e E0 (%s)' % (worst_lost['lost'], worst_lost['name'])) if worst_lost else 'n/a',
        'worst_created': ('%.2e E0 (%s)' % (worst_created['created'], worst_created['name'])) if worst_created else 'n/a',
        'fallbacks': '\n'.join('- `%s` (%s): %s steps fell back to Anderson mixing, %s contact steps fell back'
                                % (r['name'], r['what'], fmt(r['nonlinear_fallback_steps'], '{:.0f}'),
                                   fmt(r['contact_fallback_steps'], '{:.0f}')) for r in fallbacks) or '- none',
        'stopped': '\n'.join('- `%s` (%s): %s' % (r['name'], r['what'], r['diagnostic'].replace('impact: error: ', ''))
                              for r in stopped) or '- none',
        'failed': '\n'.join('- `%s`: %s' % (r['name'], '; '.join(r['problems'])) for r in failed) or '- none',
    })


def report_line(r):
    """The line printed when a scene ends."""
    print('stress: %-22s %-20s lost %-9s created %-9s %s' % (
        r['name'], r['outcome'], fmt(r['lost'], '{:.2e}'), fmt(r['created'], '{:.2e}'),
        'pass' if r['pass'] else 'FAIL: ' + '; '.join(r['problems'])), flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--jobs', type=int, default=2, help='scenes run at once (default 2, at most 2)')
    ap.add_argument('--only', nargs='*', help='run only these scenes (their report never goes to docs/)')
    ap.add_argument('--random', type=int, default=0, metavar='N',
                    help='run N random extreme scenes instead (their report never goes to docs/)')
    ap.add_argument('--seed', type=int, default=1, help='the draw of --random (default 1)')
    ap.add_argument('--impact', default=os.path.join(ROOT, 'impact'), help='the program (default ./impact)')
    ap.add_argument('--docs-dir', default=os.path.join(ROOT, 'out', 'docs'),
                    help='the report is DIR/STABILITY.md (default out/docs; docs: the published one)')
    args = ap.parse_args(argv)
    jobs = max(1, min(args.jobs, 2))
    pool = random_scenes(args.random, args.seed) if args.random > 0 else SCENES
    scenes = [s for s in pool if not args.only or s['name'] in args.only]
    report = os.path.join(os.path.abspath(args.docs_dir), 'STABILITY.md')
    if (args.only or args.random) and os.path.realpath(args.docs_dir) == os.path.realpath(os.path.dirname(TEMPLATE)):
        sys.exit('stress: --only, --random: a report of some scenes is not the published one: not into %s'
                 % os.path.relpath(TEMPLATE, ROOT))
    unknown = sorted(set(args.only or ()) - {s['name'] for s in pool})
    if unknown:
        sys.exit('stress: no scene %s' % ', '.join(unknown))
    if not os.access(args.impact, os.X_OK):
        sys.exit('stress: %s is not there: make impact' % args.impact)
    os.makedirs(WORK, exist_ok=True)
    start = time.time()
    results = {}

    def done(run):
        results[run['scene']['name']] = r = analyse(run)
        report_line(r)

    # the largest scenes first, so that the two workers finish together
    order = sorted(scenes, key=lambda s: 0 if 'mesh_72' in s['name'] else 1)
    imf.run_many([prepare(s) for s in order], jobs=jobs, on_done=done, impact=args.impact, cwd=ROOT,
                 timeout=TIMEOUT_S)
    elapsed = time.time() - start
    ordered = [results[s['name']] for s in scenes]
    write_results(ordered, os.path.join(WORK, 'results.dat'))
    npass = sum(r['pass'] for r in ordered)
    substepped = [r for r in ordered if (r['substepped_steps'] or 0) > 0]
    print('stress: %d completed, %d stopped with a diagnostic; %d took sub-steps (%.0f steps in all)'
          % (sum(r['exit'] == 0 for r in ordered), sum(r['outcome'].startswith('stopped') for r in ordered),
             len(substepped), sum(r['substepped_steps'] for r in substepped)))
    print('stress: %d scenes, %d passed, %d failed, %.0f s; results in %s'
          % (len(ordered), npass, len(ordered) - npass, elapsed, os.path.join(WORK, 'results.dat')))
    write_report(ordered, elapsed, jobs, report)
    print('stress: wrote %s (results in %s)' % (os.path.relpath(report), os.path.relpath(os.path.join(WORK, 'results.dat'))))
    return 0 if npass == len(ordered) else 1


if __name__ == '__main__':
    sys.exit(main())
