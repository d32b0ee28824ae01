"""impact_files: the files of ./impact, read and written in one place.

One module for every Python tool of the project (tools/sweep,
tools/paper-numbers, tools/stress/stress.py, bench/run_bench.py,
validation/model_choice/run.py, validation/mesh_study/run.py):

  decks       parse_deck, split_assignments, set_value, deck_text,
              fortran_value, with_settings (a deck is a list of [group,
              [[name, value], ...]], values as written; the program's own
              reader is src/deck/input_deck.f90)
  schema      schema(impact): the deck's variables, their kind, unit,
              default, range and meaning, from `impact --schema`
              (src/deck/deck_schema.f90, the one list)
  summaries   read_keys, summary_number ('key = value' lines after the
              '#' echo; 'none' is NaN, 'true'/'false' are 1/0)
  columns     read_columns, read_history (column files: the names on the
              last '#' line before the rows; a field that is not a number
              is NaN, or its row left out: read_columns(whole_rows=True))
  running     run_impact: ./impact on a deck, never through a shell

Python 3's standard library only. Import it from a tool with

    sys.path.insert(0, os.path.join(ROOT, 'tools'))
    import impact_files as imf
"""

import math
import os
import re
import subprocess

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


def with_settings(template_path, settings, header=()):
    """The text of the deck at template_path with settings {'group.name':
    value} applied (values as written, or plain words, quoted as needed)."""
    with open(template_path, encoding='utf-8') as f:
        groups = parse_deck(f.read())
    for key, value in settings.items():
        group, name = key.split('.', 1)
        set_value(groups, group, name, fortran_value(value))
    return deck_text(groups, header)


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
    values = {}
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            if line.startswith('#') or '=' not in line:
                continue
            key, value = line.split('=', 1)
            values[key.strip()] = value.strip()
    return values


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


def read_history(path):
    """A history (or any column file) as {column name: [values]}."""
    names, rows = read_columns(path)
    return {name: [r[i] for r in rows if i < len(r)] for i, name in enumerate(names)}


# ---------------------------------------------------------------- running

def run_impact(impact, deck, sets=(), cwd=None, timeout=None, log=None, options=()):
    """Runs `impact [options] [--set g.v=x ...] deck` (an argument list, no
    shell; options such as '--check' or '--overwrite'); standard output and
    error go to the file log (or are captured). Returns the
    CompletedProcess; past the timeout the run is killed and
    subprocess.TimeoutExpired raised."""
    args = [impact] + list(options)
    for s in sets:
        args += ['--set', s]
    args.append(deck)
    if log is None:
        return subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    with open(log, 'w') as f:
        return subprocess.run(args, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout)
