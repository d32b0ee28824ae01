#!/usr/bin/env python3
"""make bench-accuracy: what an accuracy run costs (issue 22).

Runs `impact --accuracy TOL` on the paper's scenes, input/clamped.nml and
input/simply_supported.nml (243 g at 3 m/s, 3 ms, nonlinear, 6x9 quarter
mesh, 2.5 us to start from), at the accuracy levels TOL = 0.05, 0.01 and
0.002, each with the cap &accuracy max_cpu_s = --cap (default 600 s), and
writes

  bench/accuracy.dat      one row per scene and level: the outcome (met or
                          the cap reached), the runs of the ladder, their
                          total cpu and wall time, the run chosen (dt,
                          mesh) and each result's relative error
  docs/PERFORMANCE.md     the block between the bench-accuracy:begin and
                          bench-accuracy:end markers

Every run's files are in build/bench/accuracy/<scene>_<level>* (the ladder
in <scene>_<level>_acc/). The accuracy runs use every CPU the process may
use (the runs of a ladder that do not depend on each other run at once):
the wall time is that of this machine at the time, the cpu time the sum
of the runs'. The program is ./impact, or the one $IMPACT_EXE names.
Usage: bench/accuracy_bench.py [--cap S] [--levels 0.05,0.01]
"""
import argparse
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import impact_files as imf  # noqa: E402  (the one reader of summaries)

EXE = os.environ.get('IMPACT_EXE') or os.path.join(ROOT, 'impact')   # ./impact, or $IMPACT_EXE
RUN_DIR = os.path.join(ROOT, 'build', 'bench', 'accuracy')
RESULTS = os.path.join(ROOT, 'bench', 'accuracy.dat')
DOC = os.path.join(ROOT, 'docs', 'PERFORMANCE.md')
BEGIN, END = '<!-- bench-accuracy:begin -->', '<!-- bench-accuracy:end -->'
SCENES = [('clamped', 'input/clamped.nml'), ('simply_supported', 'input/simply_supported.nml')]
RESULT_KEYS = ['peak_force_N', 'max_deflection_mm', 'contact_duration_us', 'time_of_peak_us',
               'max_strain_y_back']
SHORT = ['F', 'w', 'T', 't_F', 'eps']


def run_level(name, deck, tol, cap):
    """impact --accuracy tol on the deck; its summary's keys."""
    prefix = os.path.join(RUN_DIR, f'{name}_{tol:g}')
    os.makedirs(RUN_DIR, exist_ok=True)
    imf.run_impact(EXE, os.path.join(ROOT, deck),
                   sets=[f"output.prefix='{prefix}'", f'accuracy.max_cpu_s={cap:g}'],
                   options=['--overwrite', '--accuracy', f'{tol:g}'], cwd=ROOT, log=prefix + '.log')
    return imf.read_keys(prefix + '_summary.dat')


def row(name, tol, s):
    """The row of one scene and level."""
    num = lambda k: imf.summary_number(s, k)  # noqa: E731
    status = s.get('accuracy_status', 'failed').split(':')[0].replace(' ', '_')
    rel = [num(k + '_relative_error') for k in RESULT_KEYS]
    return [name, f'{tol:g}', status, f"{num('accuracy_runs'):.0f}", f"{num('accuracy_cpu_s'):.1f}",
            f"{num('accuracy_wall_s'):.1f}", f"{num('chosen_dt_us'):g}",
            f"{num('chosen_nx'):.0f}x{num('chosen_ny'):.0f}"] + [f'{r:.2e}' for r in rel]


def markdown(rows, cap):
    """The generated block of docs/PERFORMANCE.md."""
    lines = [BEGIN, '',
             f'`make bench-accuracy` (bench/accuracy_bench.py), cap {cap:g} s of cpu per accuracy run; '
             'relative errors as the run estimates them (time part + mesh part + their interaction; '
             'F peak force, w max deflection, T contact duration, t_F time of the peak, eps max back-face '
             'strain). Every result is targeted (&accuracy results = \'all\').', '',
             '| scene | target | outcome | runs | cpu (s) | wall (s) | chosen dt (μs) | chosen mesh | '
             + ' | '.join(f'err {k}' for k in SHORT) + ' |',
             '|' + '---|' * (8 + len(SHORT))]
    for r in rows:
        lines.append('| ' + ' | '.join(r[:2] + [r[2].replace('_', ' ')] + r[3:]) + ' |')
    lines += ['', END]
    return '\n'.join(lines)


def write_doc(block):
    """Replaces the block in docs/PERFORMANCE.md (appended when absent)."""
    with open(DOC, encoding='utf-8') as f:
        text = f.read()
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + block + text[text.index(END) + len(END):]
    else:
        text = text.rstrip('\n') + '\n\n' + block + '\n'
    with open(DOC, 'w', encoding='utf-8') as f:
        f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--cap', type=float, default=600.0, help='&accuracy max_cpu_s of each run (s)')
    parser.add_argument('--levels', default='0.05,0.01,0.002', help='the targets, comma-separated')
    args = parser.parse_args()
    levels = [float(x) for x in args.levels.split(',')]
    rows = []
    for name, deck in SCENES:
        for tol in levels:
            s = run_level(name, deck, tol, args.cap)
            rows.append(row(name, tol, s))
            print('bench-accuracy: ' + ' '.join(rows[-1]), flush=True)
    with open(RESULTS, 'w', encoding='utf-8') as f:
        f.write('# make bench-accuracy (bench/accuracy_bench.py): impact --accuracy on the paper\'s scenes\n')
        f.write(f'# cap (&accuracy max_cpu_s) {args.cap:g} s per accuracy run\n')
        f.write('# scene target outcome runs cpu_s wall_s chosen_dt_us chosen_mesh '
                + ' '.join(k + '_relative_error' for k in RESULT_KEYS) + '\n')
        for r in rows:
            f.write(' '.join(r) + '\n')
    write_doc(markdown(rows, args.cap))
    print(f'bench-accuracy: {RESULTS}, {DOC}')


if __name__ == '__main__':
    main()
