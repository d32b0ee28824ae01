"""impact_files: the files of ./impact, read and written in one place.

One module for every Python tool of the project (tools/sweep,
tools/paper-numbers, tools/stress/stress.py, tools/readme-deck-table,
bench/run_bench.py, validation/model_choice/run.py,
validation/mesh_study/run.py):

  decks       parse_deck, split_assignments, set_value, deck_text,
              fortran_value, with_settings, groups_of (a deck is a list of
              [group, [[name, value], ...]], values as written; the
              program's own reader is src/deck/input_deck.f90)
  schema      schema(impact): the deck's variables, their kind, unit,
              default, range and meaning, from `impact --schema`
              (src/deck/deck_schema.f90, the one list)
  summaries   read_keys, keys_in, write_keys, summary_number, summary_value,
              table_text ('key = value' lines after the '#' echo; 'none' is
              NaN, 'true'/'false' are 1/0)
  columns     read_columns, read_history (column files: the names on the
              last '#' line before the rows; a field that is not a number
              is NaN, or its row left out: whole_rows=True)
  running     run_impact: ./impact on a deck, never through a shell;
              run_many: ./impact on many decks, at most `jobs` at a time
              (cpu_count(): the CPUs this process may use); diagnostic;
              no run outlives the tool: each gets SIGTERM when the tool
              ends, however it ends (a parent-death signal), and
              stop_runs_on_signals passes a stop signal on to the runs
  version     version_text(tool): a tool's --version (VERSION, the licence)
  documents   fill_blocks, fill_file: the blocks between
              <!-- name:begin --> and <!-- name:end --> of a Markdown file,
              rewritten in place (the one template mechanism of the docs)

Python 3's standard library only. Import it from a tool with

    sys.path.insert(0, os.path.join(ROOT, 'tools'))
    import impact_files as imf

or run it: `python3 tools/impact_files.py fill DOC DIR` fills every block
NAME of DOC with the file DIR/NAME.md (make validate).
"""

import concurrent.futures
import ctypes
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time

FORTRAN_NUMBER = re.compile(r'^[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?$')
FORTRAN_LOGICAL = re.compile(r'^\.?(true|false|t|f)\.?$', re.I)


class DeckError(Exception):
    """A deck that cannot be parsed."""


# ------------------------------------------------------------------ decks

def parse_deck(text):
    """The namelist groups of a deck: a list of [group, [[name, value], ...]],
    names in lower case, values as written (comments removed, lines joined).
    A group starts at &name and ends at '/' (or &end) outside a quoted
    string; '!' starts a comment."""
    groups = []
    body = None
    quote = None
    i = 0
    n = len(text)
    while i < n:
        c = text[i]
        if quote:
            body.append(c)
            if c == quote:
                quote = None
        elif c == '!':
            while i < n and text[i] != '\n':
                i += 1
            continue
        elif body is not None and c in '\'"':
            quote = c
            body.append(c)
        elif body is not None and c == '/':
            groups[-1][1] = split_assignments(''.join(body))
            body = None
        elif c in '&$':
            m = re.match(r'[A-Za-z]\w*', text[i + 1:])
            if m and body is not None and m.group(0).lower() == 'end':
                groups[-1][1] = split_assignments(''.join(body))
                body = None
                i += 1 + m.end()
                continue
            if m:
                if body is not None:
                    raise DeckError(f'namelist &{groups[-1][0]}: no closing /')
                groups.append([m.group(0).lower(), []])
                body = []
                i += 1 + m.end()
                continue
            if body is not None:
                body.append(c)
        elif body is not None:
            body.append(' ' if c == '\n' else c)
        i += 1
    if body is not None:
        raise DeckError(f'namelist &{groups[-1][0]}: no closing /')
    return groups


def split_assignments(body):
    """'a = 1, b = 2, 3' -> [['a', '1'], ['b', '2, 3']]: an assignment runs from
    the name before an '=' (outside quotes) to the next such name."""
    starts = []
    quote = None
    for i, c in enumerate(body):
        if quote:
            if c == quote:
                quote = None
        elif c in '\'"':
            quote = c
        elif c == '=':
            j = i - 1
            while j >= 0 and body[j] == ' ':
                j -= 1
            k = j
            while k >= 0 and (body[k].isalnum() or body[k] == '_'):
                k -= 1
            if k < j:
                starts.append((k + 1, i))
    pairs = []
    for s, (name_at, eq_at) in enumerate(starts):
        end = starts[s + 1][0] if s + 1 < len(starts) else len(body)
        name = body[name_at:eq_at].strip().lower()
        value = body[eq_at + 1:end].strip().rstrip(',').strip()
        pairs.append([name, value])
    return pairs


def set_value(groups, group, name, value):
    """Sets group.name = value (as written in a deck), replacing an
    assignment of the same name, adding the group when it is missing."""
    for g in groups:
        if g[0] == group:
            for pair in g[1]:
                if pair[0] == name:
                    pair[1] = value
                    return
            g[1].append([name, value])
            return
    groups.append([group, [[name, value]]])


def deck_text(groups, header=()):
    """The deck as text: '! ' header lines, then one group a block."""
    lines = [f'! {h}' for h in header]
    for group, pairs in groups:
        lines.append(f'&{group}')
        for k, (name, value) in enumerate(pairs):
            lines.append(f'   {name} = {value}' + (',' if k + 1 < len(pairs) else ''))
        lines.append('/')
    return '\n'.join(lines) + '\n'


def fortran_value(text):
    """A value as a deck needs it: numbers and logicals as given, anything
    else as a quoted string."""
    t = str(text).strip()
    if FORTRAN_NUMBER.match(t) or FORTRAN_LOGICAL.match(t):
        return t
    if len(t) >= 2 and t[0] == t[-1] and t[0] in '\'"':
        return t
    return "'" + t.replace("'", "''") + "'"


def read_deck(path):
    """The groups of the deck at path (parse_deck)."""
    with open(path, encoding='utf-8') as f:
        return parse_deck(f.read())


def with_settings(template_path, settings, header=()):
    """The text of the deck at template_path with settings {'group.name':
    value} applied (values as written, or plain words, quoted as needed)."""
    groups = read_deck(template_path)
    for key, value in settings.items():
        group, name = key.split('.', 1)
        set_value(groups, group, name, fortran_value(value))
    return deck_text(groups, header)


def open_text(path, mode='w'):
    """A text file opened for writing, never through a symbolic link: 'w'
    removes what has the name (a link itself, never what it points to) and
    creates the file exclusively; 'a' appends to it; both with O_NOFOLLOW,
    so a link put there in between is refused (OSError)."""
    if mode == 'w':
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass
    flags = os.O_WRONLY | os.O_CREAT | os.O_NOFOLLOW | (os.O_APPEND if mode == 'a' else os.O_EXCL)
    return open(os.open(path, flags, 0o666), mode, encoding='utf-8')


def write_deck(path, groups, header=()):
    """Writes the groups as a deck (deck_text) to path; returns path."""
    with open_text(path) as f:
        f.write(deck_text(groups, header))
    return path


# ----------------------------------------------------------------- schema

def schema(impact):
    """The deck's variables from `impact --schema`: {'group.name': {'kind',
    'unit', 'default', 'range', 'meaning'}}, in the schema's order."""
    out = subprocess.run([impact, '--schema'], capture_output=True, text=True, check=True).stdout
    variables = {}
    for line in out.splitlines():
        if line.startswith('#') or not line.strip():
            continue
        group, name, kind, unit, default, rng, meaning = (line.split('\t') + [''] * 7)[:7]
        variables[f'{group}.{name}'] = dict(kind=kind, unit=unit, default=default, range=rng, meaning=meaning)
    return variables


# -------------------------------------------------------------- summaries

def read_keys(path):
    """'key = value' lines of a summary (or status) file, the '#' lines left out."""
    with open(path, encoding='utf-8', errors='replace') as f:
        return keys_in(f)


def keys_in(lines):
    """{key: value} of the 'key = value' lines among lines (text lines, or a
    text split here); '#' lines and lines without '=' are left out."""
    if isinstance(lines, str):
        lines = lines.splitlines()
    values = {}
    for line in lines:
        if line.startswith('#') or '=' not in line:
            continue
        key, value = line.split('=', 1)
        values[key.strip()] = value.strip()
    return values


def write_keys(path, values, comment=''):
    """Writes {key: value} as 'key = value' lines (after '# comment') to path,
    whole or not at all (a temporary file renamed)."""
    tmp = path + '.tmp'
    with open_text(tmp) as f:
        if comment:
            f.write(f'# {comment}\n')
        f.write(''.join(f'{key} = {value}\n' for key, value in values.items()))
    os.replace(tmp, path)


def overflowed(text):
    """True for a Fortran field of '*'s (a value too wide for its format)."""
    return bool(text) and set(text) == {'*'}


def summary_value(text):
    """A summary value as a float when it is a number (NaN and Infinity as
    Fortran writes them; a field of '*'s is inf), else None ('completed',
    'none', 'true', ...)."""
    try:
        return float(text)
    except ValueError:
        return math.inf if overflowed(text) else None


def table_text(text):
    """A summary value as the text of a numeric table: as written, flags as
    1 / 0, a time that never came ('none', 'not reached'), a value not
    computed and a field of '*'s as NaN."""
    if overflowed(text) or text in ('none', 'not reached', 'not computed'):
        return 'NaN'
    if text in ('true', 'false'):
        return '1' if text == 'true' else '0'
    return text


def summary_number(values, key):
    """A summary value as a number: 'none' (a time that never came) is NaN,
    'true' / 'false' are 1 / 0; a key that is missing is NaN."""
    text = values.get(key, 'none')
    if text in ('none', ''):
        return math.nan
    if text in ('true', 'false'):
        return 1.0 if text == 'true' else 0.0
    try:
        return float(text)
    except ValueError:
        return math.nan


# ---------------------------------------------------------------- columns

def read_columns(path, whole_rows=False):
    """A column file: (names, rows), the names from the last '#' line before
    the first row, the rows as lists of floats. A field that is not a number
    is NaN: the '*'s of a Fortran field too narrow for its value, or the
    value a stopped run cut short. whole_rows: leave out, instead, a row with
    such a field or with another number of fields than the first row (the
    last row of a run stopped while writing it)."""
    names, rows, last = [], [], None
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            if line.startswith('#'):
                last = line[1:].split()
                continue
            values = [_number(x) for x in line.split()]
            if not values:
                continue
            if whole_rows and (None in values or (rows and len(values) != len(rows[0]))):
                continue
            if not rows and last:
                names = last
            rows.append([math.nan if v is None else v for v in values])
    return names, rows


def _number(text):
    """float(text) (NaN, Infinity as Fortran writes them too), None when it is
    not a number."""
    try:
        return float(text)
    except ValueError:
        return None


def read_history(path, whole_rows=False):
    """A history (or any column file) as {column name: [values]}
    (read_columns)."""
    names, rows = read_columns(path, whole_rows)
    return {name: [r[i] for r in rows if i < len(r)] for i, name in enumerate(names)}


# ---------------------------------------------------------------- running

def cpu_count():
    """The CPUs this process may use: its affinity mask, or Slurm's
    allocation (SLURM_CPUS_ON_NODE, SLURM_CPUS_PER_TASK) when that is smaller."""
    n = len(os.sched_getaffinity(0))
    for var in ('SLURM_CPUS_ON_NODE', 'SLURM_CPUS_PER_TASK'):
        try:
            given = int(os.environ.get(var, ''))
        except ValueError:
            continue
        if 0 < given < n:
            n = given
    return max(1, n)


# No run outlives the tool that started it. Each run is started with a
# parent-death signal, SIGTERM (prctl PR_SET_PDEATHSIG: sent by the kernel
# when the thread that started it ends, however the tool ends, kill -9
# too): impact then stops after its step, its results written. The C
# library is loaded here, before any fork: the child only calls it.
PR_SET_PDEATHSIG = 1
try:
    _LIBC = ctypes.CDLL(None, use_errno=True)
except OSError:
    _LIBC = None
_RUNNING = set()       # the runs going (Popen), for stop_runs_on_signals
_STOPPED = []          # the stop signal caught


def _end_with_parent(parent):
    """What a run does before impact starts: SIGTERM when its parent ends
    (and at once if it has ended already)."""
    def set_up():
        if _LIBC is not None:
            _LIBC.prctl(PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0)
        if os.getppid() != parent:
            os._exit(128 + int(signal.SIGTERM))
    return set_up


def stop_runs_on_signals():
    """From here SIGTERM, SIGINT or SIGHUP to this process is passed on to
    the runs going (each stops after its step, its results written) and no
    other run starts (run_many leaves them out). Returns a function that
    gives the signal caught, 0 when none."""
    def handler(signum, frame):
        _STOPPED.append(signum)
        for p in list(_RUNNING):
            try:
                p.send_signal(signum)
            except OSError:
                pass
    for s in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(s, handler)
    return lambda: _STOPPED[0] if _STOPPED else 0


def run_impact(impact, deck, sets=(), cwd=None, timeout=None, log=None, options=(), env=None,
               log_header=''):
    """Runs `impact [options] [--set g.v=x ...] deck` (an argument list, no
    shell; options such as '--check' or '--overwrite'; standard input
    empty); standard output and error go to the file log, after the text
    log_header (or are captured). Returns the CompletedProcess; past the
    timeout the run is killed and subprocess.TimeoutExpired raised."""
    args = [impact] + list(options)
    for s in sets:
        args += ['--set', s]
    args.append(deck)
    if log is None:
        return subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env,
                              stdin=subprocess.DEVNULL, preexec_fn=_end_with_parent(os.getpid()))
    with open_text(log) as f:
        f.write(log_header)
        f.flush()
        p = subprocess.Popen(args, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=env,
                             stdin=subprocess.DEVNULL, preexec_fn=_end_with_parent(os.getpid()))
        _RUNNING.add(p)
        try:
            code, cpu, rss = wait_usage(p, timeout)
        finally:
            _RUNNING.discard(p)
        if code is None:
            raise subprocess.TimeoutExpired(args, timeout)
        done = subprocess.CompletedProcess(args, code)
        done.cpu_s, done.max_rss_mib = cpu, rss
        return done


def wait_usage(p, timeout=None):
    """Waits for the process p (a subprocess.Popen; killed past timeout
    seconds); returns its exit status (None when it was killed at its
    timeout; -N for a signal, as subprocess gives it), the CPU time (user +
    system, s) it and the children it waited for used, and its peak
    resident memory (MiB; the largest of it and those children), from
    os.wait4."""
    timer = None
    killed = []
    if timeout is not None:
        def kill():
            killed.append(True)
            p.kill()
        timer = threading.Timer(timeout, kill)
        timer.start()
    try:
        while True:
            try:
                _, status, usage = os.wait4(p.pid, 0)
                break
            except InterruptedError:
                continue
    finally:
        if timer:
            timer.cancel()
    p.returncode = os.waitstatus_to_exitcode(status)
    return (None if killed else p.returncode), usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


RUN_ARGUMENTS = ('impact', 'deck', 'sets', 'cwd', 'timeout', 'log', 'options', 'env', 'log_header')


def run_many(runs, jobs=None, on_done=None, **common):
    """Runs ./impact on many decks, at most `jobs` at a time (default
    cpu_count()). runs: deck paths, or dicts of run_impact's arguments
    ('deck' and any of impact, sets, options, cwd, log, log_header, timeout,
    env), each over `common` (impact=... is needed in one of them); a dict
    may carry other keys of its own. Returns one result per run, in the
    order of runs: the run's dict with
      exit       its exit status; None when it was killed at its timeout;
                 127 when it could not start
      timed_out  True when it was killed at its timeout
      stdout, stderr   what it wrote ('' when it went to its log)
      diagnostic its error lines (diagnostic()), from stderr or the log
      elapsed_s  its wall-clock time (s)
      cpu_s      the CPU time (user + system, s) its process used, for a
                 run with a log (os.wait4); None otherwise
      max_rss_mib  its peak resident memory (MiB), likewise
    on_done(result), when given, is called in this thread as each run ends;
    with jobs = 1 the runs are made one after the other in this thread, and
    on_done sees each before the next one starts. After a stop signal
    (stop_runs_on_signals) the runs not yet started are left out: their
    result has not_started = True, and on_done does not see them."""
    runs = [dict(common, **({'deck': r} if isinstance(r, str) else r)) for r in runs]
    jobs = max(1, jobs or cpu_count())
    if jobs == 1 or len(runs) <= 1:
        results = []
        for r in runs:
            results.append(_run_one(r))
            if on_done and not results[-1]['not_started']:
                on_done(results[-1])
        return results
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(_run_one, r): k for k, r in enumerate(runs)}
        results = [None] * len(runs)
        for future in concurrent.futures.as_completed(futures):
            results[futures[future]] = future.result()
            if on_done and not results[futures[future]]['not_started']:
                on_done(results[futures[future]])
    return results


def _run_one(run):
    """One run of run_many: the run's dict with its outcome."""
    result = dict(run, exit=None, timed_out=False, stdout='', stderr='', cpu_s=None, max_rss_mib=None,
                  not_started=bool(_STOPPED), elapsed_s=0.0, diagnostic='')
    if _STOPPED:
        return result
    start = time.time()
    try:
        p = run_impact(**{k: run[k] for k in RUN_ARGUMENTS if k in run})
        result.update(exit=p.returncode, stdout=p.stdout or '', stderr=p.stderr or '',
                      cpu_s=getattr(p, 'cpu_s', None), max_rss_mib=getattr(p, 'max_rss_mib', None))
    except subprocess.TimeoutExpired as e:
        result.update(timed_out=True, stdout=_text(e.stdout), stderr=_text(e.stderr))
    except OSError as e:
        result.update(exit=127, stderr=f'impact_files: cannot run {run.get("impact")}: {e}\n')
        if run.get('log'):
            try:
                with open_text(run['log'], 'a') as f:
                    f.write(result['stderr'])
            except OSError:
                pass
    result['elapsed_s'] = time.time() - start
    result['diagnostic'] = diagnostic(result['stderr'] or _log_text(run.get('log')))
    return result


def _text(output):
    """Output of a killed run as text (subprocess may give bytes)."""
    if isinstance(output, bytes):
        return output.decode(errors='replace')
    return output or ''


def _log_text(path):
    """The text of a run's log ('' without one)."""
    if not path or not os.path.isfile(path):
        return ''
    with open(path, encoding='utf-8', errors='replace') as f:
        return f.read()


def diagnostic(text):
    """The error of a run from its messages: its last three lines naming an
    error (not gfortran's 'ERROR STOP'), else its last line."""
    lines = [line.rstrip('\n') for line in text.splitlines() if line.strip()]
    errors = [line for line in lines if 'error' in line.lower() and not re.match(r'\s*ERROR STOP', line)]
    return ' / '.join(errors[-3:]) if errors else (lines[-1] if lines else '')


# -------------------------------------------------------------- documents

BLOCK = re.compile(r'<!-- ([\w.:+-]+):begin -->(.*?)<!-- \1:end -->', re.S)


class TemplateError(Exception):
    """A block of a document that nothing fills."""



def version_text(tool):
    """`tool --version`, as GNU tools say it: the release of the impact the
    tool belongs to (the file VERSION beside tools/: the checkout's, or
    <prefix>/share/impact/VERSION once installed) and the licence."""
    path = os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, 'VERSION')
    try:
        with open(path, encoding='utf-8') as f:
            release = f.read().strip()
    except OSError:
        release = '(no VERSION file)'
    return f'{tool} (impact) {release}\nLicense MIT: <https://opensource.org/licenses/MIT>.'

def fill_blocks(text, value, keep_others=False):
    """text with every block <!-- NAME:begin -->...<!-- NAME:end --> filled
    with value(NAME) (value: a function, or a dict). A block whose begin
    marker ends its line gets the value on lines of its own, one written
    inline stays inline. A name value does not know (KeyError) is a
    TemplateError, or, with keep_others, a block left as it is (a study
    that fills only its own blocks). Returns (text, the names filled, in
    order)."""
    lookup = value.__getitem__ if isinstance(value, dict) else value
    names = []

    def fill(m):
        name = m.group(1)
        try:
            new = lookup(name)
        except KeyError:
            if keep_others:
                return m.group(0)
            raise TemplateError(f'nothing fills the block {name}') from None
        names.append(name)
        if m.group(2).startswith('\n'):
            new = '\n' + new + '\n'
        return f'<!-- {name}:begin -->{new}<!-- {name}:end -->'

    return BLOCK.sub(fill, text), names


def fill_file(path, value, keep_others=False):
    """Fills the blocks of the file at path in place (fill_blocks; the file
    is replaced whole or not at all); returns the names filled."""
    with open(path, encoding='utf-8') as f:
        text, names = fill_blocks(f.read(), value, keep_others)
    tmp = path + '.tmp'
    with open_text(tmp) as f:
        f.write(text)
    os.replace(tmp, path)
    return names


def file_blocks(directory):
    """A value for fill_blocks: block NAME is the file directory/NAME.md, its
    lines right-trimmed; a missing file says the check did not run."""
    def value(name):
        path = os.path.join(directory, name + '.md')
        if not os.path.isfile(path):
            return f'(table {name} missing: the check did not run)'
        with open(path, encoding='utf-8', errors='replace') as f:
            return '\n'.join(line.rstrip() for line in f.read().splitlines())
    return value


def main(argv):
    """python3 tools/impact_files.py fill DOC DIR: every block NAME of DOC
    filled with DIR/NAME.md."""
    if len(argv) != 3 or argv[0] != 'fill':
        print('usage: impact_files.py fill DOC DIR', file=sys.stderr)
        return 2
    try:
        names = fill_file(argv[1], file_blocks(argv[2]))
    except (OSError, TemplateError) as e:
        print(f'impact_files: {argv[1]}: {e}', file=sys.stderr)
        return 1
    print(f'impact_files: {argv[1]}: {len(names)} blocks filled from {argv[2]}')
    return 0


def h5_problem(path):
    """What is wrong with the HDF5 file at path, '' when nothing is seen: not
    an HDF5 file, or shorter than the end of file its superblock records (a
    file cut by a full disk or a copy; versions 2 and 3 of the superblock,
    which impact writes, record it). Reads 48 bytes; no HDF5 library needed.
    Damage inside a dataset is the checksums' to find (h5py, h5export)."""
    try:
        with open(path, 'rb') as f:
            head = f.read(48)
        size = os.path.getsize(path)
    except OSError as e:
        return f'cannot read it ({e.strerror})'
    if head[:8] != b'\x89HDF\r\n\x1a\n':
        return 'not an HDF5 file'
    if len(head) > 12 and head[8] in (2, 3):
        width = head[9]
        start = 12 + 2 * width
        if width in (4, 8) and len(head) >= start + width:
            end = int.from_bytes(head[start:start + width], 'little')
            if size < end:
                return f'truncated: {size} bytes of the {end} its superblock records'
    return ''


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
