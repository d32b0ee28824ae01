#!/usr/bin/env python3
"""The ply damage study (make validate-damage; docs/validation/damage.md).

The paper's clamped plate with ply damage (tests/data/decks/damage_plate.nml,
IM7/8552 interlaminar toughness g1c = 277, g2c = 788 J/m^2 for the
delamination threshold), to 1.5 ms:
1 impact energies 1, 3, 6, 10 J (the paper's 0.243 kg impactor, v =
  sqrt(2E/m)), &damage model 'none' against 'hashin': peak force,
  dissipated energy, energy balance, exit status, the force at the first
  drop of the force history against the Davies-Zhang threshold;
2 mesh objectivity at 6 J: quarters 6 x 4 : 9 x 6 and 12 x 8 : 18 x 12
  (element sizes 1.5 : 1), with the crack band, and without it: the length
  of every Gauss point held at the coarse mesh's. The kernel uses the
  fracture energy only as G/L (src/strength/ply_damage.f90), so the fine
  mesh with L held at 1.5 times its own is the fine mesh with the four ply
  energies divided by 1.5, exactly.
Writes the tables (markdown) to build/validation/damage/tables.md and to
standard output. Usage: python3 validation/damage/run.py [--jobs N]
(from the repository root, ./impact built).
"""
import argparse
import math
import os
import sys

ROOT = os.getcwd()
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), '..', 'tools'))
import impact_files as imf  # noqa: E402

WORK = os.path.join(ROOT, 'build', 'validation', 'damage')
DECK = 'tests/data/decks/damage_plate.nml'
MASS = 0.243
ENERGIES = (1.0, 3.0, 6.0, 10.0)
MESHES = ((6, 4), (9, 6), (12, 8), (18, 12))
G = (133300.0, 47500.0, 277.0, 788.0)          # gft, gfc, gmt, gmc of the deck
COMMON = ('strength.g1c=277', 'strength.g2c=788', 'analysis.t_end=1.5e-3', 'output.hdf5=.false.')


def plan():
    """The runs: {name: settings}."""
    runs = {}
    for e in ENERGIES:
        v = f'{math.sqrt(2.0 * e / MASS):.4f}'
        for model in ('none', 'hashin'):
            runs[f'e{e:g}_{model}'] = (f'impactor.velocity={v}', f'damage.model={model}')
    v6 = f'{math.sqrt(12.0 / MASS):.4f}'
    for nx, ny in MESHES:
        runs[f'm{nx}x{ny}'] = (f'impactor.velocity={v6}', f'mesh.nx={nx}', f'mesh.ny={ny}')
    for nx, ny in MESHES[1::2]:     # the fine mesh of each pair, L held at the coarse mesh's
        runs[f'm{nx}x{ny}_fixed'] = (f'impactor.velocity={v6}', f'mesh.nx={nx}', f'mesh.ny={ny}') + tuple(
            f'strength.{k}={g / 1.5:.6g}' for k, g in zip(('gft', 'gfc', 'gmt', 'gmc'), G))
    return runs


def first_drop(d, e):
    """(time us, force N) where the damaged force d first falls below the
    elastic one e by 1 % of e's peak, and the damaged force's largest
    value up to then (the load the drop starts from)."""
    f, g, t = d['force_N'], e['force_N'], d['time_us']
    for n in range(len(f)):
        if g[n] - f[n] > 0.01 * max(g):
            return t[n], max(f[:n + 1])
    return math.nan, math.nan


def force_at(h, t_us):
    """The history's force at time t_us (N)."""
    return min(zip(h['time_us'], h['force_N']), key=lambda r: abs(r[0] - t_us))[1]


def onset(text):
    """A summary time to one decimal, or its words ('not reached')."""
    v = imf.summary_value(text or '')
    return text if v is None else f'{v:.1f}'


def points(text):
    """damaged_ply_points as 'ft/fc/mt/mc, reduced'."""
    n = [w for w in (text or '').replace(',', ' ').split() if w.isdigit()]
    return '/'.join(n[:4]) + f', {n[4]}' if len(n) == 5 else text


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--jobs', type=int, default=None)
    p.add_argument('--tables-only', action='store_true', help='the tables of the runs already made')
    args = p.parse_args()
    os.makedirs(WORK, exist_ok=True)
    runs = plan()
    todo = [dict(deck=DECK, name=n, sets=COMMON + s + (f'output.prefix={WORK}/{n}',), log=f'{WORK}/{n}.log',
                 options=('--overwrite',)) for n, s in runs.items()]
    if args.tables_only:
        done = {r['name']: dict(r, exit=0, cpu_s=math.nan) for r in todo}
    else:
        done = {r['name']: r for r in imf.run_many(todo, jobs=args.jobs, impact=os.path.join(ROOT, 'impact'))}
    s = {n: imf.read_keys(f'{WORK}/{n}_summary.dat') for n in runs}
    h = {n: imf.read_history(f'{WORK}/{n}_history.dat') for n in runs}
    num = imf.summary_number
    out = ['| impact | v (m/s) | peak force elastic (N) | peak force damaged (N) | dissipated (J) '
           '| energy balance error | status, exit | NaN in history | cpu (s) |', '|' + '---|' * 9]
    for e in ENERGIES:
        a, b = f'e{e:g}_none', f'e{e:g}_hashin'
        nan = any(math.isnan(x) for col in h[b].values() for x in col)
        err = num(s[b], 'max_energy_error_J') / num(s[b], 'initial_energy_J')
        out.append(f'| {e:g} J | {math.sqrt(2 * e / MASS):.3f} | {num(s[a], "peak_force_N"):.0f} '
                   f'| {num(s[b], "peak_force_N"):.0f} | {num(s[b], "damage_dissipated_J"):.4f} | {100 * err:.3f} % '
                   f'| {s[b].get("status")}, {done[b]["exit"]} | {"yes" if nan else "no"} '
                   f'| {done[a]["cpu_s"]:.1f} + {done[b]["cpu_s"]:.1f} |')
    out += ['', '| impact | first ply failure: t (us), F (N) | force drops: t (us), from F (N) '
            '| P_c Davies-Zhang (N) | 1.213 P_c (N) | F passes P_c (us) |', '|' + '---|' * 6]
    for e in ENERGIES:
        a, b = f'e{e:g}_none', f'e{e:g}_hashin'
        tb, fb = first_drop(h[b], h[a])
        t0 = num(s[b], 'failure_onset_us')
        out.append(f'| {e:g} J | {t0:.1f}, {force_at(h[b], t0):.0f} | {tb:.1f}, {fb:.0f} '
                   f'| {num(s[b], "delamination_threshold_N"):.0f} | {num(s[b], "delamination_threshold_dynamic_N"):.0f} '
                   f'| {onset(s[b].get("delamination_onset_us"))} |')
    out += ['', '| quarter mesh | crack band: dissipated (J) | L held at the coarse mesh\'s: dissipated (J) '
            '| damaged ply points ft/fc/mt/mc, strengths reduced | peak force (N) | energy balance error |', '|' + '---|' * 6]
    for nx, ny in MESHES:
        n = f'm{nx}x{ny}'
        fx = num(s[n + '_fixed'], 'damage_dissipated_J') if n + '_fixed' in s else num(s[n], 'damage_dissipated_J')
        out.append(f'| {nx} x {ny} | {num(s[n], "damage_dissipated_J"):.4f} | {fx:.4f} '
                   f'| {points(s[n].get("damaged_ply_points"))} | {num(s[n], "peak_force_N"):.0f} '
                   f'| {100 * num(s[n], "max_energy_error_J") / num(s[n], "initial_energy_J"):.3f} % |')
    text = '\n'.join(out) + '\n'
    with open(f'{WORK}/tables.md', 'w', encoding='utf-8') as f:
        f.write(text)
    print(text)
    return 0 if all(r['exit'] == 0 for r in done.values()) else 1


if __name__ == '__main__':
    sys.exit(main())
