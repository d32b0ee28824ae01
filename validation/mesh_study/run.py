#!/usr/bin/env python3
"""Mesh study of the paper's impact: how the impact results and the static
point compliance at the impact point change with the mesh.

For every edge condition (--edges), theory (--theories) and quarter-plate mesh
(--meshes, nx x ny with nx along the 150 mm side) it writes an impact deck
from the template input/<edge>.nml of the repository this script belongs to,
keeping everything of the template (plate, lamina, laminate with k4, k5, the
243 g impactor at 3 m/s, contact, dt, t_end, domain = 'quarter') but with
&mesh nx, ny, &analysis theory and scheme (--scheme), its own &output prefix,
overwrite = .true., hdf5 = .false., and the --set values; it runs
`impact deck.nml` (impact_files.run_many, no shell), and reads
<prefix>_summary.dat (key = value) and <prefix>_history.dat (columns found by
name from its '#' header) through tools/impact_files.py.
For every edge and mesh it also runs a static deck (&analysis kind =
'static', theory = 'linear'; &load kind = 'central_force', magnitude = 1 N)
and reads the centre deflection from <prefix>_static.dat (checked against
the node at the impact point in <prefix>_deflection.dat): the point
compliance w/P (m/N).

From each impact run: the first contact's peak force and its time; the end
of the first contact (the first step after the force first became positive
at which it is exactly 0, as the summary's first_contact_ended counts it;
the summary's contact_duration_us, refined, ends inside the step before it;
"not ended" otherwise); the smallest force
between the first-contact peak and the next peak; the overall peak force;
the largest plate deflection (summary max_deflection_mm); the number of
contacts, plate solves and cpu_s.

The first contact is the history from the first F > 0 to the first F = 0
after it. When the force dips to a small positive value and rises again (a
dip below SPLIT_FRACTION = 10 % of the peaks on both sides of it, no F = 0),
the contact has not ended there, but the first-contact peak is taken before
the dip, and the dip is the "min F between contacts"; after an F = 0 end that
minimum is 0, and "–" when no later peak follows.

The report (--report, markdown) has one table per (edge, theory) with a row
per mesh, the change in % between successive meshes of a family (each mesh
against the one with half its nx and ny: 6x4 -> 12x8 -> 24x16, 9x6 -> 18x12
-> 36x24), the compliance table with its growth per mesh halving, and what
looked odd (failed or timed-out runs, warnings, fall-backs, disagreements
between the history and the summary). The raw numbers go to a column file
beside it (same name, .dat; a '#' header names each column and its unit).

Usage (from anywhere; Python 3 standard library only):

    validation/mesh_study/run.py --impact ./impact --out build/mesh_study \\
        --report build/mesh_study/report.md [--jobs 2] \\
        [--meshes 6x4,9x6,12x8,18x12,24x16,36x24] \\
        [--edges simply_supported,clamped] [--theories linear,nonlinear] \\
        [--scheme fast] [--set mesh.shear_rule=mitc9 --set contact.load=hertz] \\
        [--timeout 600] [--no-static]

--set values go into every deck, the static ones too; the variables the
study sets itself (mesh nx, ny, domain; analysis kind, theory, scheme;
boundary edges; output prefix, overwrite, hdf5, every) are refused there.

Decks, logs and results go to OUT/runs/ (<edge>_<theory>_<nx>x<ny>.nml and
static_<edge>_<nx>x<ny>.nml, each with its .log and results). A run longer
than --timeout seconds (default 600; 0: no limit) is stopped (the process
this script started) and reported with its time, its partial history read as
far as it got.
Exit status: 0 when every run completed, 1 otherwise (the report is written
either way), 2 on bad arguments.
"""

import argparse
import math
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, 'tools'))
import impact_files as imf  # noqa: E402

SPLIT_FRACTION = 0.10   # a dip below this fraction of the peaks on both sides splits the pulses
WARNING_RE = re.compile(r'^\s*(impact:\s*)?warning', re.I)
MESH_RE = re.compile(r'^\s*(\d+)\s*[xX]\s*(\d+)\s*$')
SET_RE = re.compile(r'^([A-Za-z]\w*)\.([A-Za-z]\w*)=(.*)$', re.S)
# variables the study itself sets in every deck: --set may not change them
CONTROLLED = {('mesh', 'nx'), ('mesh', 'ny'), ('mesh', 'domain'), ('analysis', 'theory'),
              ('analysis', 'scheme'), ('analysis', 'kind'), ('boundary', 'edges'),
              ('output', 'prefix'), ('output', 'overwrite'), ('output', 'hdf5'),
              ('output', 'every')}


class StudyError(Exception):
    """A problem with the arguments or the template, reported in one line."""


# ------------------------------------------------------------------ decks

def make_deck(template_path, settings, extra):
    """The template's groups with settings [(group, name, value)] and then the
    --set values [(group, name, value)] applied; the blanks of an unquoted
    value written over several lines of the template are joined into one."""
    try:
        groups = imf.read_deck(template_path)
    except imf.DeckError as e:
        raise StudyError('template: %s' % e)
    for _, pairs in groups:
        for pair in pairs:
            if '\'' not in pair[1] and '"' not in pair[1]:
                pair[1] = re.sub(r'\s+', ' ', pair[1])
    for g, n, v in list(settings) + list(extra):
        imf.set_value(groups, g, n, v)
    return groups


# ------------------------------------------------------------------ results

def read_columns(path):
    """A column file as {name: [values]}, {} when it is missing; a row that is
    not all numbers, or is cut short (a stopped run), is left out."""
    return imf.read_history(path, whole_rows=True) if os.path.exists(path) else {}


def first_dip(F, a, b):
    """The bottom of the first deep dip in F[a:b]: a point below SPLIT_FRACTION
    of both the largest force before it (from a) and the largest after it
    (before b), the force not reaching 0 there; None when there is none."""
    if b - a < 3:
        return None
    right = [0.0] * (b - a + 1)
    for i in range(b - 1, a - 1, -1):
        right[i - a] = max(F[i], right[i - a + 1])
    left = 0.0
    for k in range(a, b):
        left = max(left, F[k])
        if F[k] < SPLIT_FRACTION * min(left, right[k - a]):
            # the bottom: the smallest force between here and the next peak
            nxt = max(range(k, b), key=lambda i: F[i])
            return min(range(k, nxt + 1), key=lambda i: F[i])
    return None


def first_contact(t, F):
    """The first contact and what follows it, from a force history (F = 0
    exactly ends a contact, as in the summary)."""
    r = dict(start_us=math.nan, end_us=math.nan, ended=None, F1_N=math.nan, t1_us=math.nan,
             Fmin_N=math.nan, tmin_us=math.nan, F2_N=math.nan, t2_us=math.nan,
             split='none')
    n = len(F)
    if n == 0:
        return r
    i0 = next((i for i in range(n) if F[i] > 0.0), None)
    if i0 is None:
        r['ended'] = True      # no contact at all
        return r
    r['start_us'] = t[i0]
    iend = next((i for i in range(i0 + 1, n) if F[i] <= 0.0), None)
    r['ended'] = iend is not None
    if iend is not None:
        r['end_us'] = t[iend]
        r['last_force_us'] = t[iend - 1]
    hi = iend if iend is not None else n
    dip = first_dip(F, i0, hi)
    if dip is not None:            # a dip without F = 0 ends the first pulse
        p1 = max(range(i0, dip), key=lambda i: F[i])
        r['split'] = 'dip'
        lo = dip
    else:
        p1 = max(range(i0, hi), key=lambda i: F[i])
        r['split'] = 'zero' if iend is not None else 'none'
        lo = iend
    r['F1_N'], r['t1_us'] = F[p1], t[p1]
    if lo is None:
        return r
    # the next pulse: from the rise after lo to its end (F = 0 or a deep dip)
    j0 = next((i for i in range(lo, n) if F[i] > F[lo]), None)
    if j0 is None:
        return r
    j1 = next((i for i in range(j0, n) if F[i] <= 0.0), n)
    d2 = first_dip(F, j0, j1)
    if d2 is not None:
        j1 = d2
    p2 = max(range(j0, j1), key=lambda i: F[i]) if j1 > j0 else j0
    pm = min(range(p1, p2 + 1), key=lambda i: F[i])
    r['F2_N'], r['t2_us'] = F[p2], t[p2]
    r['Fmin_N'], r['tmin_us'] = F[pm], t[pm]
    return r


fnum = imf.summary_number     # a summary value as a number; NaN when missing or not a number


def ival(s, key):
    try:
        return int(s[key])
    except (KeyError, ValueError):
        return None


# ------------------------------------------------------------------ runs

def run_all(jobs, runs_dir, impact, timeout, n_jobs):
    """Runs impact on the deck of every job (impact_files.run_many, n_jobs at
    a time), the largest first; fills each job with rc (None: timed out),
    timed_out, wall_s and log."""
    order = sorted(jobs, key=lambda j: (-j['mesh'][0] * j['mesh'][1], j['kind'] != 'impact',
                                        j['theory'] != 'nonlinear'))
    count = [0]

    def done(run):
        job = run['job']
        job.update(rc=run['exit'], timed_out=run['timed_out'], wall_s=run['elapsed_s'])
        with open(run['log'], encoding='utf-8', errors='replace') as f:
            job['log'] = f.read()
        count[0] += 1
        state = 'timed out' if job['timed_out'] else ('rc %s' % job['rc'])
        print('[%d/%d] %-40s %s, %.1f s' % (count[0], len(order), job['name'], state, job['wall_s']), flush=True)

    imf.run_many([dict(deck=j['name'] + '.nml', log=os.path.join(runs_dir, j['name'] + '.log'), job=j)
                  for j in order], jobs=n_jobs, on_done=done, impact=impact, cwd=runs_dir,
                 timeout=timeout if timeout > 0 else None)


def analyse_impact(job):
    prefix = os.path.join(job['dir'], job['name'])
    summary = prefix + '_summary.dat'
    job['summary'] = imf.read_keys(summary) if os.path.exists(summary) else {}
    cols = read_columns(prefix + '_history.dat')
    job.update(first_contact(cols.get('time_us', []), cols.get('force_N', [])))
    job['rows'] = len(cols.get('time_us', []))
    job['last_time_us'] = cols['time_us'][-1] if job['rows'] else math.nan
    job['hist_peak_N'] = max(cols['force_N']) if job['rows'] else math.nan
    job['hist_wmax_mm'] = max(abs(w) for w in cols['w_plate_mm']) \
        if job['rows'] and 'w_plate_mm' in cols else math.nan
    m = re.search(r'equations\s+(\d+)', job['log'])
    job['equations'] = int(m.group(1)) if m else None


def analyse_static(job):
    prefix = os.path.join(job['dir'], job['name'])
    st = read_columns(prefix + '_static.dat')
    job['wP'] = math.nan
    job['wP_node'] = math.nan
    if st.get('load') and st.get('w_centre_mm'):
        k = max(range(len(st['load'])), key=lambda i: st['load'][i])
        if st['load'][k] != 0.0:
            job['wP'] = st['w_centre_mm'][k] * 1e-3 / st['load'][k]
    de = read_columns(prefix + '_deflection.dat')
    if de.get('x_mm'):
        for i in range(len(de['x_mm'])):
            if abs(de['x_mm'][i]) < 1e-9 and abs(de['y_mm'][i]) < 1e-9:
                job['wP_node'] = de['w_mm'][i] * 1e-3 / job['magnitude']
    m = re.search(r'equations\s+(\d+)', job['log'])
    job['equations'] = int(m.group(1)) if m else None
    job['summary'] = {}


def status_of(job):
    if job.get('timed_out'):
        return 'timeout'
    if job['kind'] == 'impact':
        st = job['summary'].get('status', '')
        if job['rc'] == 0 and st == 'completed':
            return 'completed'
        return 'failed' if st == '' else st.replace(' ', '_')
    return 'completed' if job['rc'] == 0 and not math.isnan(job['wP']) else 'failed'


# ------------------------------------------------------------------ report

def fmt(x, spec):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return '–'
    return format(x, spec)


def pct(a, b):
    """change from a to b in %."""
    if a is None or b is None or math.isnan(a) or math.isnan(b) or a == 0:
        return '–'
    return '%+.2f' % (100.0 * (b - a) / a)


def halvings(meshes):
    """(coarse, fine) pairs of the list where fine has twice the coarse nx and ny."""
    s = set(meshes)
    return [(m, (2 * m[0], 2 * m[1])) for m in meshes if (2 * m[0], 2 * m[1]) in s]


def families(meshes):
    """Chains of successive halvings: [[6x4, 12x8, 24x16], [9x6, 18x12, 36x24]]."""
    s = set(meshes)
    chains = []
    for m in meshes:
        if m[0] % 2 == 0 and m[1] % 2 == 0 and (m[0] // 2, m[1] // 2) in s:
            continue
        chain = [m]
        while (2 * chain[-1][0], 2 * chain[-1][1]) in s:
            chain.append((2 * chain[-1][0], 2 * chain[-1][1]))
        if len(chain) > 1:
            chains.append(chain)
    return chains


def mname(m):
    return '%dx%d' % m


def impact_table(jobs, edge, theory, meshes):
    """Markdown table of one (edge, theory)."""
    rows = [jobs.get(('impact', edge, theory, m)) for m in meshes]
    have_eq = any(j and j.get('equations') for j in rows)
    head = ['mesh'] + (['equations'] if have_eq else []) + [
        'first-contact peak F (N)', 't_peak (μs)', 'first-contact end (μs)',
        'min F between contacts (N)', 'overall peak F (N)', 'w_max (mm)', 'contacts',
        'solves', 'cpu (s)', 'status']
    out = ['| ' + ' | '.join(head) + ' |', '|' + '---|' * len(head)]
    for m, j in zip(meshes, rows):
        if j is None:
            continue
        s = j['summary']
        end = fmt(j['end_us'], '.1f') if j['ended'] else 'not ended'
        if j['ended'] and j['split'] == 'dip':
            end += ' (after a dip)'
        cells = [mname(m)] + ([str(j['equations']) if j['equations'] else '–'] if have_eq else [])
        partial = j['status'] != 'completed' and not (j['ended'] and j['split'] != 'none')
        if j['status'] != 'completed' and not j['ended']:
            end = '–'
        cells += [fmt(math.nan if partial else j['F1_N'], '.1f'),
                  fmt(math.nan if partial else j['t1_us'], '.1f'), end,
                  fmt(math.nan if partial else j['Fmin_N'], '.4g'), fmt(fnum(s, 'peak_force_N'), '.1f'),
                  fmt(fnum(s, 'max_deflection_mm'), '.4f'),
                  s.get('contacts', '–'), s.get('plate_solves', '–'),
                  fmt(fnum(s, 'cpu_s'), '.2f'), j['status']]
        if j['status'] == 'timeout':
            cells[-1] = 'timeout after %.0f s (history to %.1f μs)' % (j['wall_s'], j['last_time_us'])
        out.append('| ' + ' | '.join(cells) + ' |')
    return out


def change_table(jobs, edge, theory, meshes):
    pairs = halvings(meshes)
    if not pairs:
        return []
    head = ['halving', 'first-contact peak F', 't_peak', 'first-contact end',
            'overall peak F', 'w_max']
    out = ['| ' + ' | '.join(head) + ' |', '|' + '---|' * len(head)]
    for a, b in pairs:
        ja, jb = jobs.get(('impact', edge, theory, a)), jobs.get(('impact', edge, theory, b))
        if not ja or not jb or ja['status'] != 'completed' or jb['status'] != 'completed':
            out.append('| %s → %s | – | – | – | – | – |' % (mname(a), mname(b)))
            continue
        ea = ja['end_us'] if ja['ended'] else math.nan
        eb = jb['end_us'] if jb['ended'] else math.nan
        if (ja['split'] == 'dip') != (jb['split'] == 'dip'):
            dend = '– (dip, no F = 0, in %s)' % mname(a if ja['split'] == 'dip' else b)
        else:
            dend = pct(ea, eb)
        out.append('| %s → %s | %s | %s | %s | %s | %s |' % (
            mname(a), mname(b), pct(ja['F1_N'], jb['F1_N']), pct(ja['t1_us'], jb['t1_us']),
            dend, pct(fnum(ja['summary'], 'peak_force_N'), fnum(jb['summary'], 'peak_force_N')),
            pct(fnum(ja['summary'], 'max_deflection_mm'), fnum(jb['summary'], 'max_deflection_mm'))))
    return out


def compliance_table(jobs, edges, meshes):
    head = ['mesh', 'equations']
    for e in edges:
        head += ['%s w/P (m/N)' % e, '%s change vs half nx, ny (%%)' % e]
    out = ['| ' + ' | '.join(head) + ' |', '|' + '---|' * len(head)]
    for m in meshes:
        half = (m[0] // 2, m[1] // 2) if m[0] % 2 == 0 and m[1] % 2 == 0 else None
        eq = next((jobs[('static', e, None, m)].get('equations') for e in edges
                   if ('static', e, None, m) in jobs), None)
        cells = [mname(m), str(eq) if eq else '–']
        for e in edges:
            j = jobs.get(('static', e, None, m))
            jh = jobs.get(('static', e, None, half)) if half else None
            cells += [fmt(j['wP'] if j else math.nan, '.5e'),
                      pct(jh['wP'], j['wP']) if (j and jh) else '–']
        out.append('| ' + ' | '.join(cells) + ' |')
    chains = families(meshes)
    if chains:
        out.append('')
        out.append('Growth of w/P per mesh halving, along each family:')
        out.append('')
        for e in edges:
            for ch in chains:
                vals = [jobs.get(('static', e, None, m)) for m in ch]
                if any(v is None for v in vals):
                    continue
                steps = ', '.join('%s→%s %s %% (%s m/N)' % (
                    mname(ch[i]), mname(ch[i + 1]), pct(vals[i]['wP'], vals[i + 1]['wP']),
                    fmt(vals[i + 1]['wP'] - vals[i]['wP'], '+.3e'))
                    for i in range(len(ch) - 1))
                out.append('- %s, %s: %s' % (e, ' → '.join(mname(m) for m in ch), steps))
    return out


DAT_COLUMNS = [
    ('kind', '-', 'impact or static'), ('edges', '-', ''), ('theory', '-', 'static: linear'),
    ('nx', '-', 'quarter elements along the 150 mm side'), ('ny', '-', 'along the 100 mm side'),
    ('equations', '-', 'from the run log; -1 unknown'), ('status', '-', 'completed, timeout, failed...'),
    ('wall_s', 's', 'wall time of the run'),
    ('F1_N', 'N', 'first-contact peak force'), ('t1_us', 'us', 'its time'),
    ('start_us', 'us', 'first F > 0'), ('end_us', 'us', 'first F = 0 after it; nan: not ended'),
    ('ended', '-', '1 ended, 0 not'), ('split', '-', 'first pulse bounded by zero, dip, none'),
    ('Fmin_N', 'N', 'min force between the first-contact peak and the next peak'),
    ('tmin_us', 'us', 'its time'), ('F2_N', 'N', 'next peak'), ('t2_us', 'us', 'its time'),
    ('peak_force_N', 'N', 'summary: overall peak'), ('time_of_peak_us', 'us', 'summary'),
    ('contact_duration_us', 'us', 'summary'), ('max_deflection_mm', 'mm', 'summary'),
    ('contacts', '-', 'summary'), ('plate_solves', '-', 'summary'), ('cpu_s', 's', 'summary'),
    ('warnings', '-', 'summary'), ('nonlinear_fallback_steps', '-', 'summary'),
    ('contact_fallback_steps', '-', 'summary'), ('max_energy_error_J', 'J', 'summary'),
    ('last_time_us', 'us', 'last history row'),
    ('w_over_P_m_per_N', 'm/N', 'static: centre deflection / central force'),
]


def dat_row(j):
    s = j['summary']
    v = dict(kind=j['kind'], edges=j['edge'], theory=j['theory'] or 'linear',
             nx=j['mesh'][0], ny=j['mesh'][1], equations=j.get('equations') or -1,
             status=j['status'], wall_s=j['wall_s'])
    for k in ('F1_N', 't1_us', 'start_us', 'end_us', 'Fmin_N', 'tmin_us', 'F2_N', 't2_us',
              'last_time_us'):
        v[k] = j.get(k, math.nan)
    v['ended'] = -1 if j.get('ended') is None else int(bool(j['ended']))
    v['split'] = j.get('split', '-')
    for k in ('peak_force_N', 'time_of_peak_us', 'contact_duration_us', 'max_deflection_mm',
              'cpu_s', 'max_energy_error_J'):
        v[k] = fnum(s, k)
    for k in ('contacts', 'plate_solves', 'warnings', 'nonlinear_fallback_steps',
              'contact_fallback_steps'):
        x = ival(s, k)
        v[k] = -1 if x is None else x
    v['w_over_P_m_per_N'] = j.get('wP', math.nan)
    cells = []
    for name, _, _ in DAT_COLUMNS:
        x = v[name]
        if isinstance(x, float):
            cells.append('%.8e' % x if not math.isnan(x) else 'nan')
        else:
            cells.append(str(x))
    return ' '.join(cells)


def oddities(jobs):
    """What looked odd, one line each."""
    notes = []
    warned = {}
    jobs_by_name = {j['name']: j for j in jobs.values()}
    for key in sorted(jobs, key=lambda k: (k[0], k[1], k[2] or '', k[3])):
        j = jobs[key]
        name = j['name']
        if j['status'] == 'timeout':
            notes.append('%s: stopped after %.0f s (timeout), history up to %s μs' % (
                name, j['wall_s'], fmt(j.get('last_time_us', math.nan), '.1f')))
            continue
        if j['status'] != 'completed':
            tail = [l for l in j['log'].splitlines() if 'error' in l.lower()][-1:]
            notes.append('%s: %s (rc %s) %s' % (name, j['status'], j['rc'], ' '.join(tail)))
            continue
        if j['kind'] == 'static':
            if not math.isnan(j['wP_node']) and abs(j['wP_node'] - j['wP']) > 1e-6 * abs(j['wP']):
                notes.append('%s: _static.dat w/P %.6e but the node at the centre in _deflection.dat %.6e'
                             % (name, j['wP'], j['wP_node']))
            continue
        s = j['summary']
        for k in ('warnings', 'nonlinear_fallback_steps', 'contact_fallback_steps',
                  'unconverged_steps'):
            if ival(s, k):
                notes.append('%s: summary %s = %s' % (name, k, s[k]))
        for l in j['log'].splitlines():
            if WARNING_RE.match(l):
                w = re.sub(r'[-+]?\d*\.?\d+(E[-+]?\d+)?', '…', l.strip())
                warned.setdefault(w, []).append((name, l.strip()))
        # the history against the summary
        # (the summary's first contact runs from t = 0 to where alpha - alpha_0 crosses 0,
        # inside the step in which the force returns to 0: docs/OUTPUT.md)
        if j['ended'] and not math.isnan(fnum(s, 'contact_duration_us')):
            d = fnum(s, 'contact_duration_us')
            if not j['last_force_us'] - 1e-3 < d <= j['end_us'] + 1e-3:
                notes.append('%s: first contact ends between %.1f and %.1f μs in the history, summary duration %s μs'
                             % (name, j['last_force_us'], j['end_us'], s['contact_duration_us']))
        fe = s.get('first_contact_ended')
        if fe is not None and (fe == 'true') != bool(j['ended']):
            notes.append('%s: summary first_contact_ended = %s, history says %s'
                         % (name, fe, j['ended']))
        pk = fnum(s, 'peak_force_sampled_N')       # (peak_force_N is refined between the steps)
        if not math.isnan(pk) and abs(j['hist_peak_N'] - pk) > 1e-6 * pk:
            notes.append('%s: largest force in the history %.7e N, summary %.7e N'
                         % (name, j['hist_peak_N'], pk))
        if j['split'] == 'dip':
            notes.append('%s: the force dips to %.4g N at %.1f μs without reaching 0: first pulse split there'
                         % (name, j['Fmin_N'], j['tmin_us']))
    for w, runs in warned.items():
        quiet = [n for n, _ in runs if ival(jobs_by_name[n]['summary'], 'warnings') == 0]
        if len(runs) == 1:
            notes.append('%s: log: %s' % (runs[0][0], runs[0][1]))
            continue
        notes.append('%d runs wrote "%s": %s%s' % (
            len(runs), w, '; '.join('%s (%s)' % (n, ', '.join(re.findall(
                r'[-+]?\d*\.?\d+(?:E[-+]?\d+)?', l)[:2]) or '-') for n, l in runs),
            ('; the summary of %s says warnings = 0' % ('all of them' if len(quiet) == len(runs)
                                                        else ', '.join(quiet))) if quiet else ''))
    return notes


def write_report(path, args, jobs, meshes, template_dir, started, elapsed):
    lines = ['# Mesh study: %s' % ', '.join(args.edges), '',
             'Written by `validation/mesh_study/run.py` on %s (%.0f s of wall time, %d jobs at a time).'
             % (started, elapsed, args.jobs), '',
             '- executable: `%s`' % args.impact,
             '- templates: `%s/<edge>.nml` (everything kept but the mesh, theory, scheme and output)'
             % template_dir,
             '- scheme: `%s`; theories: %s; meshes (quarter plate, nx along the 150 mm side): %s'
             % (args.scheme, ', '.join(args.theories), ', '.join(mname(m) for m in meshes)),
             '- --set: %s' % (', '.join('%s.%s=%s' % x for x in args.set_list) or 'none'),
             '- work directory: `%s`' % os.path.abspath(args.out), '',
             'First contact: from the first F > 0 to the first F = 0 after it (as the summary '
             'counts it); "not ended" when F never returns to 0. The first-contact peak is the '
             'largest force before that end, or before an earlier dip below %d %% of the peaks on '
             'both sides of it (then the end column says "after a dip" or "not ended"). '
             '"min F between contacts" is the smallest force between the first-contact peak and '
             'the next peak (0 after an F = 0 end; – when no later peak follows). Overall peak, '
             'w_max, contacts, solves and cpu are the summary\'s `peak_force_N`, '
             '`max_deflection_mm`, `contacts`, `plate_solves`, `cpu_s`.'
             % round(100 * SPLIT_FRACTION), '']
    for e in args.edges:
        for th in args.theories:
            lines += ['## %s, %s' % (e, th), '']
            lines += impact_table(jobs, e, th, meshes) + ['']
            ch = change_table(jobs, e, th, meshes)
            if ch:
                lines += ['Change between successive meshes of a family (%, finer against coarser):', '']
                lines += ch + ['']
    if any(k[0] == 'static' for k in jobs):
        lines += ['## Static point compliance at the impact point', '',
                  'Linear static analysis, `&load kind = \'central_force\', magnitude = 1.0` (N), '
                  'centre deflection from `_static.dat` (`w_centre_mm` / `load`); the change is '
                  'against the mesh with half the nx and ny.', '']
        lines += compliance_table(jobs, args.edges, meshes) + ['']
    notes = oddities(jobs)
    lines += ['## Notes from the runs', '']
    lines += ['- ' + n for n in notes] if notes else ['- nothing odd: every run completed, no warnings.']
    lines += ['', 'Runs that did not complete are left out of the change tables; their first-contact '
              'figures are shown only when the first pulse ended within the history they wrote.']
    lines += ['', 'Raw numbers: `%s`.' % os.path.basename(os.path.splitext(path)[0] + '.dat'), '']
    with open(path, 'w', encoding='utf-8') as f:
        f.write('\n'.join(lines))
    dat = os.path.splitext(path)[0] + '.dat'
    with open(dat, 'w', encoding='utf-8') as f:
        f.write('# mesh study: %s; impact %s; scheme %s; --set %s\n' % (
            started, args.impact, args.scheme,
            ' '.join('%s.%s=%s' % x for x in args.set_list) or 'none'))
        f.write('# columns:\n')
        for k, (name, unit, what) in enumerate(DAT_COLUMNS, 1):
            f.write('# %2d %-26s (%s) %s\n' % (k, name, unit, what))
        f.write('# ' + ' '.join(n for n, _, _ in DAT_COLUMNS) + '\n')
        order = sorted(jobs.values(), key=lambda j: (j['kind'], j['edge'], j['theory'] or '',
                                                     j['mesh'][0] * j['mesh'][1]))
        for j in order:
            f.write(dat_row(j) + '\n')
    return path, dat


# ------------------------------------------------------------------ main

def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split('\n\n', 1)[1])
    ap.add_argument('--impact', required=True, help='the impact executable')
    ap.add_argument('--out', required=True, help='work directory for the decks and results')
    ap.add_argument('--report', required=True, help='markdown report to write (and .dat beside it)')
    ap.add_argument('--jobs', type=int, default=2, help='runs at a time (default 2)')
    ap.add_argument('--set', action='append', default=[], metavar='GROUP.VAR=VALUE',
                    help='deck setting written into every deck (repeatable)')
    ap.add_argument('--meshes', default='6x4,9x6,12x8,18x12,24x16,36x24',
                    help='quarter meshes NXxNY, nx along the 150 mm side (default: all six)')
    ap.add_argument('--edges', default='simply_supported,clamped',
                    help='edge conditions; the template is input/<edge>.nml')
    ap.add_argument('--theories', default='linear,nonlinear', help='&analysis theory values')
    ap.add_argument('--scheme', default='fast', help="&analysis scheme (default 'fast')")
    ap.add_argument('--timeout', type=float, default=600.0,
                    help='stop a run after this many seconds (0: never; default 600)')
    ap.add_argument('--no-static', action='store_true', help='skip the static compliance runs')
    a = ap.parse_args(argv)
    a.impact = os.path.abspath(a.impact)
    if not (os.path.isfile(a.impact) and os.access(a.impact, os.X_OK)):
        raise StudyError('--impact %s: not an executable file' % a.impact)
    if a.jobs < 1:
        raise StudyError('--jobs must be at least 1')
    meshes = []
    for item in a.meshes.split(','):
        m = MESH_RE.match(item)
        if not m or int(m.group(1)) < 1 or int(m.group(2)) < 1:
            raise StudyError('--meshes: "%s" is not NXxNY (e.g. 9x6)' % item)
        meshes.append((int(m.group(1)), int(m.group(2))))
    a.mesh_list = sorted(set(meshes), key=lambda m: (m[0] * m[1], m))
    a.edges = [e.strip() for e in a.edges.split(',') if e.strip()]
    a.theories = [t.strip() for t in a.theories.split(',') if t.strip()]
    for t in a.theories:
        if t not in ('linear', 'nonlinear', 'auto'):
            raise StudyError('--theories: "%s" is not linear, nonlinear or auto' % t)
    a.set_list = []
    for s in a.set:
        m = SET_RE.match(s.strip())
        if not m:
            raise StudyError('--set %s: give GROUP.VAR=VALUE (e.g. mesh.shear_rule=mitc9)' % s)
        g, n = m.group(1).lower(), m.group(2).lower()
        if (g, n) in CONTROLLED:
            raise StudyError('--set %s: %s.%s is set by the study itself (use its own option)' % (s, g, n))
        a.set_list.append((g, n, imf.fortran_value(m.group(3))))
    return a


def main(argv=None):
    try:
        args = parse_args(sys.argv[1:] if argv is None else argv)
    except StudyError as e:
        print('mesh_study: error: %s' % e, file=sys.stderr)
        return 2
    template_dir = os.path.join(REPO, 'input')
    runs = os.path.join(os.path.abspath(args.out), 'runs')
    os.makedirs(runs, exist_ok=True)
    rep_dir = os.path.dirname(os.path.abspath(args.report))
    os.makedirs(rep_dir, exist_ok=True)
    jobs = {}
    try:
        for e in args.edges:
            tpl = os.path.join(template_dir, e + '.nml')
            if not os.path.exists(tpl):
                raise StudyError('--edges %s: no template %s' % (e, tpl))
            for m in args.mesh_list:
                for th in args.theories:
                    name = '%s_%s_%s' % (e, th, mname(m))
                    settings = [('mesh', 'nx', str(m[0])), ('mesh', 'ny', str(m[1])),
                                ('analysis', 'theory', "'%s'" % th),
                                ('analysis', 'scheme', "'%s'" % args.scheme),
                                ('output', 'prefix', "'%s'" % name),
                                ('output', 'overwrite', '.true.'), ('output', 'hdf5', '.false.')]
                    groups = make_deck(tpl, settings, args.set_list)
                    header = [
                        'written by validation/mesh_study/run.py from %s' % tpl,
                        'mesh %s, theory %s, scheme %s' % (mname(m), th, args.scheme)]
                    jobs[('impact', e, th, m)] = dict(kind='impact', edge=e, theory=th, mesh=m,
                                                      name=name, groups=groups, header=header)
                if not args.no_static:
                    name = 'static_%s_%s' % (e, mname(m))
                    settings = [('mesh', 'nx', str(m[0])), ('mesh', 'ny', str(m[1])),
                                ('analysis', 'kind', "'static'"),
                                ('analysis', 'theory', "'linear'"),
                                ('analysis', 'scheme', "'%s'" % args.scheme),
                                ('load', 'kind', "'central_force'"), ('load', 'magnitude', '1.0'),
                                ('output', 'prefix', "'%s'" % name),
                                ('output', 'overwrite', '.true.'), ('output', 'hdf5', '.false.')]
                    groups = make_deck(tpl, settings, args.set_list)
                    header = [
                        'written by validation/mesh_study/run.py from %s' % tpl,
                        'static point compliance, mesh %s, 1 N at the centre' % mname(m)]
                    jobs[('static', e, None, m)] = dict(kind='static', edge=e, theory=None, mesh=m,
                                                        name=name, groups=groups, header=header,
                                                        magnitude=1.0)
    except StudyError as err:
        print('mesh_study: error: %s' % err, file=sys.stderr)
        return 2
    for j in jobs.values():
        j['dir'] = runs
        imf.write_deck(os.path.join(runs, j['name'] + '.nml'), j['groups'], j['header'])
    started = time.strftime('%Y-%m-%d %H:%M:%S')
    t0 = time.time()
    print('mesh_study: %d runs, %d at a time, in %s' % (len(jobs), args.jobs, runs), flush=True)
    # the largest runs first, so that the last ones to finish are short
    run_all(jobs.values(), runs, args.impact, args.timeout, args.jobs)
    elapsed = time.time() - t0
    for j in jobs.values():
        if j['kind'] == 'impact':
            analyse_impact(j)
        else:
            analyse_static(j)
        j['status'] = status_of(j)
    rep, dat = write_report(os.path.abspath(args.report), args, jobs, args.mesh_list,
                            template_dir, started, elapsed)
    print('mesh_study: report %s, numbers %s' % (rep, dat))
    bad = [j['name'] for j in jobs.values() if j['status'] != 'completed']
    if bad:
        print('mesh_study: not completed: %s' % ', '.join(sorted(bad)), file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
