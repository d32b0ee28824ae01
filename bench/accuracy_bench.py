#!/usr/bin/env python3
"""make bench-accuracy: what an accuracy run costs.

Runs `impact --accuracy TOL` on the paper's scenes, input/clamped.nml and
input/simply_supported.nml (243 g at 3 m/s, 3 ms, nonlinear, 6x9 quarter
mesh, 2.5 us to start from), at the accuracy levels TOL = 0.05, 0.01 and
0.002, each with the ladder's own cap (100 times its first run; --cap S
sets &accuracy max_cpu_s instead), with the default targets and every
result estimated (TARGETED below), beside one plain run of each deck (the
price in plain runs), and writes

  --results FILE          one row per scene and level: the outcome (met or
                          the cap reached), the runs of the ladder, their
                          total cpu and wall time, the run chosen (dt,
                          mesh) and each result's relative error
                          (out/bench/accuracy.dat; bench/accuracy.dat
                          with --docs-dir docs)
  --docs-dir DIR/PERFORMANCE.md
                          a copy of docs/PERFORMANCE.md (out/docs by
                          default; docs itself when DIR is docs, as make
                          docs and make bench-accuracy DOCS_DIR=docs do)
                          with the block between the bench-accuracy:begin
                          and bench-accuracy:end markers filled

Every run's files are in build/bench/accuracy/<scene>_<level>* (the ladder
in <scene>_<level>_acc/). The accuracy runs use every CPU the process may
use (the runs of a ladder that do not depend on each other run at once):
the wall time is that of this machine at the time, the cpu time the sum
of the runs'. The program is ./impact, or the one $IMPACT_EXE names.
Usage: bench/accuracy_bench.py [--cap S] [--levels 0.05,0.01] [--docs-dir DIR] [--results FILE]
"""
import argparse
import os
import shutil
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import impact_files as imf  # noqa: E402  (the one reader of summaries)

EXE = os.environ.get('IMPACT_EXE') or os.path.join(ROOT, 'impact')   # ./impact, or $IMPACT_EXE
RUN_DIR = os.path.join(ROOT, 'build', 'bench', 'accuracy')
PUBLISHED_DOCS = os.path.join(ROOT, 'docs')                       # make docs: the published documents
PUBLISHED_RESULTS = os.path.join(ROOT, 'bench', 'accuracy.dat')
SCENES = [('clamped', 'input/clamped.nml'), ('simply_supported', 'input/simply_supported.nml')]
RESULT_KEYS = ['peak_force_N', 'max_deflection_mm', 'contact_duration_us', 'time_of_peak_us',
               'max_strain_y_back']
SHORT = ['F', 'w', 'T', 't_F', 'eps']
# What each accuracy run must meet (&accuracy results): the default targets
# (F, w, T: the others still get their errors; 'all' would target them too).
TARGETED = [('default', 'default')]


def run_level(name, deck, tol, cap, targeted):
    """impact --accuracy tol on the deck, targeted (&accuracy results); its summary's keys."""
    prefix = os.path.join(RUN_DIR, f"{name}_{tol:g}_{targeted.split('+')[0]}")
    os.makedirs(RUN_DIR, exist_ok=True)
    cap_set = [f'accuracy.max_cpu_s={cap:g}'] if cap else []
    imf.run_impact(EXE, os.path.join(ROOT, deck),
                   sets=[f"output.prefix='{prefix}'", f'accuracy.results={targeted}'] + cap_set,
                   options=['--overwrite', '--accuracy', f'{tol:g}'], cwd=ROOT, log=prefix + '.log')
    return imf.read_keys(prefix + '_summary.dat')


def plain_cpu(name, deck):
    """The cpu time of one plain run of the deck (s)."""
    prefix = os.path.join(RUN_DIR, f'{name}_plain')
    os.makedirs(RUN_DIR, exist_ok=True)
    imf.run_impact(EXE, os.path.join(ROOT, deck), sets=[f"output.prefix='{prefix}'"],
                   options=['--overwrite'], cwd=ROOT, log=prefix + '.log')
    return imf.summary_number(imf.read_keys(prefix + '_summary.dat'), 'cpu_s')


def row(name, tol, label, s, plain):
    """The row of one scene, targeted set and level; plain: the cpu of its plain run."""
    num = lambda k: imf.summary_number(s, k)  # noqa: E731
    status = s.get('accuracy_status', 'failed').split(':')[0].replace(' ', '_')
    rel = [num(k + '_relative_error') for k in RESULT_KEYS]
    return [name, label.replace(' ', ''), f'{tol:g}', status, f"{num('accuracy_runs'):.0f}", f"{num('accuracy_cpu_s'):.1f}",
            f"{num('accuracy_cpu_s') / plain:.0f}", f"{num('accuracy_cpu_in_chosen_runs'):.1f}",
            f"{num('accuracy_wall_s'):.1f}", f"{num('chosen_dt_us'):g}",
            f"{num('chosen_nx'):.0f}x{num('chosen_ny'):.0f}"] + [f'{r:.2e}' for r in rel]


def markdown(rows, cap):
    """The generated block of docs/PERFORMANCE.md."""
    lines = [
             f'`make bench-accuracy` (bench/accuracy_bench.py), cap {cap_text(cap)} per accuracy run; '
             'relative errors as the run estimates them (time part + mesh part + their interaction; '
             'F peak force, w max deflection, T contact duration, t_F time of the peak, eps max back-face '
             'strain). Targeted: the default (F, w, T; the others still get their errors). '
             'Price: the cpu time in plain runs of the deck, and in runs of the settings chosen.', '',
             '| scene | targeted | target | outcome | runs | cpu (s) | in plain runs | in chosen runs '
             '| wall (s) | chosen dt (μs) | chosen mesh | ' + ' | '.join(f'err {k}' for k in SHORT) + ' |',
             '|' + '---|' * (11 + len(SHORT))]
    for r in rows:
        lines.append('| ' + ' | '.join(r[:3] + [r[3].replace('_', ' ')] + r[4:]) + ' |')
    return '\n'.join(lines)


def cap_text(cap):
    """The cap as the table says it."""
    return f'{cap:g} s of cpu' if cap else "the ladder's own (100 times its first run's cpu)"


def write_doc(docs_dir, block):
    """Fills the bench-accuracy block of docs_dir/PERFORMANCE.md, a copy of
    the committed docs/PERFORMANCE.md unless docs_dir is docs; returns its path."""
    doc = os.path.join(docs_dir, 'PERFORMANCE.md')
    template = os.path.join(PUBLISHED_DOCS, 'PERFORMANCE.md')
    os.makedirs(docs_dir, exist_ok=True)
    if not (os.path.exists(doc) and os.path.samefile(doc, template)):
        shutil.copyfile(template, doc)
    if 'bench-accuracy' not in imf.fill_file(doc, {'bench-accuracy': block}, keep_others=True):
        sys.exit(f'bench-accuracy: {template} has no bench-accuracy block')
    return doc


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--cap', type=float, default=None, help='&accuracy max_cpu_s of each run (s)')
    parser.add_argument('--levels', default='0.05,0.01,0.002', help='the targets, comma-separated')
    parser.add_argument('--docs-dir', default=os.path.join(ROOT, 'out', 'docs'),
                        help='where PERFORMANCE.md is written (docs: the published one)')
    parser.add_argument('--results', default=None,
                        help='the table (out/bench/accuracy.dat; bench/accuracy.dat with --docs-dir docs)')
    args = parser.parse_args()
    published = os.path.realpath(args.docs_dir) == os.path.realpath(PUBLISHED_DOCS)
    results = os.path.abspath(args.results or (PUBLISHED_RESULTS if published
                                               else os.path.join(ROOT, 'out', 'bench', 'accuracy.dat')))
    os.makedirs(os.path.dirname(results), exist_ok=True)
    levels = [float(x) for x in args.levels.split(',')]
    rows = []
    plain = {name: plain_cpu(name, deck) for name, deck in SCENES}
    for label, targeted in TARGETED:
        for name, deck in SCENES:
            for tol in levels:
                s = run_level(name, deck, tol, args.cap, targeted)
                rows.append(row(name, tol, label, s, plain[name]))
                print('bench-accuracy: ' + ' '.join(rows[-1]), flush=True)
    with open(results, 'w', encoding='utf-8') as f:
        f.write('# make bench-accuracy (bench/accuracy_bench.py): impact --accuracy on the paper\'s scenes\n')
        f.write(f'# cap {cap_text(args.cap)} per accuracy run; plain runs (cpu s): '
                + ' '.join(f'{n} {c:.3g}' for n, c in plain.items()) + '\n')
        f.write('# scene targeted target outcome runs cpu_s in_plain_runs in_chosen_runs wall_s '
                'chosen_dt_us chosen_mesh '
                + ' '.join(k + '_relative_error' for k in RESULT_KEYS) + '\n')
        for r in rows:
            f.write(' '.join(r) + '\n')
    doc = write_doc(os.path.abspath(args.docs_dir), markdown(rows, args.cap))
    print(f'bench-accuracy: wrote {os.path.relpath(results, ROOT)} and {os.path.relpath(doc, ROOT)}')


if __name__ == '__main__':
    main()
