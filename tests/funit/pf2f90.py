#!/usr/bin/env python3
"""Translate impact's pFUnit tests (tests/test_*.pf) into plain Fortran 2008.

The .pf files use a small subset of pFUnit 4's syntax, so that they build
unchanged against real pFUnit (make test PFUNIT_DIR=...).  Without pFUnit,
this script turns each one into a .F90 file that runs on tests/funit/funit.f90
and writes the driver program that runs them all.  Anything outside the subset
is refused with "file:line: error: ..." and exit status 1, so that a test
which would not build with pFUnit does not pass here either.

The subset:
  * one module per file, named after the file (test_x.pf holds module
    test_x: pFUnit's PFUNIT.mk names the suite after the file), with
    `use funit` and its tests after `contains`;
  * no module-level name (a variable, constant, type, interface, procedure,
    or a name taken from another module by `use ..., only:`) that real
    pFUnit's funit module also makes public (FUNIT_PUBLIC_NAMES below: run,
    initialize, finalize, stub, test, is, every, disable, ...): with
    `use funit` the two would clash and pFUnit would not compile the file;
  * `@test` before `subroutine name()`, a module procedure without arguments
    (blank and comment lines may come between, as pFUnit allows);
  * at most one `@before` and one `@after` per module, before a subroutine
    of the same form: they run before and after every test of the module;
  * one assertion per line, never continued with `&`, no comment after it:
      @assertEqual(expected, actual [, tolerance=t] [, message=m])
      @assertRelativelyEqual(expected, actual, tolerance=t [, message=m])
      @assertLessThan(lhs, rhs)  @assertLessThanOrEqual(lhs, rhs)
      @assertGreaterThan(lhs, rhs)  @assertGreaterThanOrEqual(lhs, rhs)
          (passes when lhs < rhs, lhs <= rhs, ...; tolerance=t for reals)
      @assertTrue(condition)  @assertFalse(condition)  @assertIsFinite(x)
          (each with an optional message=m)
    message= and tolerance= by keyword only;
  * every `call execute_command_line(...)` gives cmdstat=: without it a
    command that cannot run (a tool not installed, exit status 127) ends
    the whole suite ("EXECUTE_COMMAND_LINE: Invalid command line"); with it
    exitstat= says 127 and only that test fails, by its name.

An assertion becomes, as in pFUnit,
    call assertEqual(<arguments>, location=SourceLocation('<file>', <line>))
    if (anyExceptions()) return
between `#line` directives, so that compiler messages, run-time errors and
failed assertions all name the .pf file and line.

Usage:
  pf2f90.py TEST.pf -o TEST.F90         translate one file
  pf2f90.py --driver DRIVER.f90 TEST.pf...
                                        write the program running every test
  pf2f90.py --check-rejects FILE.pf...  self-check (make test-funit): each
                                        file must be refused at the line and
                                        with the words its first line gives:
                                        "! expect-error: LINE: WORDS"
"""

import argparse
import os
import re
import sys

# Assertion directives: lower-case name -> (name in funit, number of
# positional arguments, keywords allowed, keywords required).
ASSERTIONS = {
    'assertequal': ('assertEqual', 2, {'message', 'tolerance'}, set()),
    'assertrelativelyequal': ('assertRelativelyEqual', 2, {'message', 'tolerance'}, {'tolerance'}),
    'assertlessthan': ('assertLessThan', 2, {'message', 'tolerance'}, set()),
    'assertlessthanorequal': ('assertLessThanOrEqual', 2, {'message', 'tolerance'}, set()),
    'assertgreaterthan': ('assertGreaterThan', 2, {'message', 'tolerance'}, set()),
    'assertgreaterthanorequal': ('assertGreaterThanOrEqual', 2, {'message', 'tolerance'}, set()),
    'asserttrue': ('assertTrue', 1, {'message'}, set()),
    'assertfalse': ('assertFalse', 1, {'message'}, set()),
    'assertisfinite': ('assertIsFinite', 1, {'message'}, set()),
}
# Directives that mark the next subroutine.
MARKERS = ('test', 'before', 'after')

# The public names of real pFUnit 4's funit module (module FUnit,
# src/funit/FUnit.F90), which a test module gets with `use funit`. FUnit has
# no PRIVATE statement, so it passes on, besides its own procedures, all that
# the modules it uses make public: FUnit_Core and PF_Assert (explicit public
# lists), fHamcrest (everything of its matcher modules) and OUTPUT_UNIT of
# iso_fortran_env. Collected from pFUnit 4.x (4.13 and later included);
# names of both older and newer matchers are listed. Lower case.
FUNIT_PUBLIC_NAMES = frozenset('''
    initialize run generic_run finalize loadtests_interface stub get_context output_unit
    sourcelocation test testsuite testmethod testresult testrunner basetestrunner
    remoterunner robustrunner testlistener testlistenervector listenerpointer
    resultprinter xmlprinter debuglistener namefilter testcase abstracttestparameter
    parameterizedtestcase parallelcontext serialcontext throw catchnext catch
    anyexceptions expectation subject predicate wascalled wasnotcalled wascalledonce
    testannotation stringtestannotationmap disable timeoutannotation taplistener
    assertfail asserttrue assertfalse assertequal assertexceptionraised assertsameshape
    assertany assertall assertnone assertnotall assertnotequal assertlessthan
    assertlessthanorequal assertgreaterthan assertgreaterthanorequal
    assertrelativelyequal assertapprox assertisnan assertisfinite assertisinfinite
    whitespaceoptions ignore_all trim_all keep_all ignore_differences
    matcherdescription stringdescription assert_that abstractmatcher basematcher
    is isnot not isequal equal_to isgreater greater_than isgreaterorequal
    greater_than_or_equal_to isless less_than islessorequal less_than_or_equal_to
    istrueorfalse true false isnear isnear_32 isnear_64 near isrelativelynear
    relatively_near anyof any_of allof all_of every every_item stringcontains
    contains_string stringstartswith starts_with stringendswith ends_with
    isarraywithsize array_with_size empty_array matchable
'''.split())

# Words that may precede FUNCTION in a function statement.
FUNCTION_PREFIX_WORDS = {
    'pure', 'impure', 'elemental', 'recursive', 'non_recursive', 'module',
    'integer', 'real', 'logical', 'character', 'complex', 'double', 'precision',
    'type', 'class',
}
# Words that may precede SUBROUTINE in a subroutine statement.
SUBROUTINE_PREFIX_WORDS = {
    'pure', 'impure', 'elemental', 'recursive', 'non_recursive', 'module',
}

# The statement pFUnit's own parser recognises after @test, @before, @after.
PFUNIT_SUBROUTINE_LINE = re.compile(r'\s*subroutine\s+(\w+)\s*(\(\s*\))?\s*(!.*)?$', re.I)


class Refusal(Exception):
    """A .pf file uses something outside the subset."""

    def __init__(self, path, line, text):
        super().__init__(text)
        self.path = path
        self.line = line
        self.text = text

    def __str__(self):
        return '%s:%d: error: %s' % (self.path, self.line, self.text)


# ----------------------------------------------------------------------
# Lexical helpers
# ----------------------------------------------------------------------

def strip_comment(line, quote=None):
    """Return (code, quote): line without its ! comment, and the quote left
    open at its end (a character literal continued on the next line)."""
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in '\'"':
            quote = c
        elif c == '!':
            return line[:i], None
    return line, quote


def split_top(text, sep):
    """Split text at sep outside parentheses, brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in '\'"':
            quote = c
        elif c in '([':
            depth += 1
        elif c in ')]':
            depth -= 1
        elif c == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def closing_paren(text, start):
    """Index of the parenthesis closing the one at text[start], or -1."""
    depth, quote = 0, None
    for i in range(start, len(text)):
        c = text[i]
        if quote:
            if c == quote:
                quote = None
        elif c in '\'"':
            quote = c
        elif c == '(':
            depth += 1
        elif c == ')':
            depth -= 1
            if depth == 0:
                return i
    return -1


def without_parens(text):
    """text with every parenthesised part removed."""
    out, depth = [], 0
    for c in text:
        if c == '(':
            depth += 1
        elif c == ')':
            depth -= 1
        elif depth == 0:
            out.append(c)
    return ''.join(out)


# ----------------------------------------------------------------------
# Parsing one .pf file
# ----------------------------------------------------------------------

class Unit:
    """A scoping unit open at some point of the file."""

    def __init__(self, kind, name, line):
        self.kind = kind          # module, subroutine, function, interface, type
        self.name = name
        self.line = line
        self.contains = False     # past its CONTAINS statement


class PfFile:
    """A parsed .pf file: its module, its tests and the translation plan."""

    def __init__(self, path, text):
        self.path = path
        self.lines = text.splitlines()
        self.stem = os.path.splitext(os.path.basename(path))[0]
        self.module = None
        self.tests = []           # (name, line)
        self.before = None        # name
        self.after = None
        self._before_at = (None, 0)   # (name, line of @before)
        self._after_at = (None, 0)
        self.uses_funit = False
        self._default_private = False
        self._public = set()
        self._private = set()
        # line number -> ('marker', kind) or ('assert', name, args)
        self.directives = {}
        self._stack = []
        self._pending = None      # (kind, line) of a marker waiting for its subroutine
        self._parse()

    def refuse(self, line, text):
        raise Refusal(self.path, line, text)

    # -- the pass over the lines ---------------------------------------

    def _parse(self):
        quote = None
        statement = None          # [first line, [pieces]] while continued
        for n, raw in enumerate(self.lines, 1):
            stripped = raw.strip()
            if statement is None:
                if stripped.startswith('@'):
                    self._directive(n, raw)
                    continue
                if stripped.startswith('#'):
                    continue      # preprocessor line, passed through
            else:
                rest = stripped[1:].lstrip() if stripped.startswith('&') else stripped
                if rest.startswith('@'):
                    self.refuse(n, 'a directive cannot be part of a continued statement '
                                '(the statement begun on line %d)' % statement[0])
            code, quote = strip_comment(raw, quote)
            code = code.strip()
            if not code:
                continue          # blank or comment line (also inside a continuation)
            continued = code.endswith('&')
            if continued:
                code = code[:-1].rstrip()
            if statement is None:
                statement = [n, []]
            elif code.startswith('&'):
                code = code[1:].lstrip()
            statement[1].append(code)
            if not continued:
                text = ' '.join(statement[1])
                for part in split_top(text, ';'):
                    if part.strip():
                        self._statement(statement[0], n, part.strip())
                statement = None
        end = len(self.lines)
        if statement is not None:
            self.refuse(statement[0], 'statement continued past the end of the file')
        if self._pending:
            kind, line = self._pending
            self.refuse(line, '@%s is not followed by a subroutine' % kind)
        if self._stack:
            unit = self._stack[-1]
            self.refuse(unit.line, '%s %s is not ended' % (unit.kind, unit.name))
        if self.module is None:
            self.refuse(max(end, 1), 'no module: the subset needs "module %s" holding the '
                        'tests' % self.stem)
        if not self.uses_funit:
            self.refuse(self.module[1], 'module %s does not "use funit"' % self.module[0])
        marked = [(name, line) for name, line in self.tests]
        marked += [(name, line) for name, line in (self._before_at, self._after_at) if name]
        for name, line in marked:
            if name in self._private or (self._default_private and name not in self._public):
                self.refuse(line, '%s is private to module %s: the driver (like pFUnit\'s suite) '
                            'calls it from outside, so make it public' % (name, self.module[0]))

    # -- directives ----------------------------------------------------

    def _directive(self, n, raw):
        m = re.match(r'\s*@(\w+)(.*)$', raw)
        if not m:
            self.refuse(n, 'not a directive of the subset: %s' % raw.strip())
        word, rest = m.group(1), m.group(2)
        key = word.lower()
        rest_code, _ = strip_comment(rest)
        if rest.rstrip().endswith('&') or rest_code.rstrip().endswith('&'):
            self.refuse(n, 'directive @%s continued with "&": the subset (and pFUnit\'s '
                        'parser) takes one directive per line' % word)

        if key in MARKERS:
            if rest.strip():
                if rest.strip().startswith('!'):
                    self.refuse(n, 'comment after @%s: pFUnit would not recognise the '
                                'directive' % word)
                self.refuse(n, '@%s%s: options of @%s are outside the subset'
                            % (word, rest.strip(), word))
            self._marker(n, key)
            return

        if key not in ASSERTIONS:
            self.refuse(n, 'unknown directive @%s: the subset has @test, @before, @after, '
                        '@%s' % (word, ', @'.join(v[0] for v in ASSERTIONS.values())))
        name, npos, allowed, required = ASSERTIONS[key]
        self._inside_procedure(n, '@' + word)
        body = rest.lstrip()
        if not body.startswith('('):
            self.refuse(n, '@%s needs its arguments in parentheses' % word)
        close = closing_paren(body, 0)
        if close < 0:
            self.refuse(n, 'unbalanced parentheses in @%s' % word)
        trailing = body[close + 1:].strip()
        if trailing.startswith('!'):
            self.refuse(n, 'comment after @%s(...): pFUnit would not recognise the directive'
                        % word)
        if trailing:
            self.refuse(n, 'text after @%s(...): %s' % (word, trailing))
        inner = body[1:close].strip()
        args = [a.strip() for a in split_top(inner, ',')] if inner else []
        if any(not a for a in args):
            self.refuse(n, 'empty argument in @%s' % word)
        positional, keywords = [], {}
        for arg in args:
            km = re.match(r'([A-Za-z]\w*)\s*=(?![=>])', arg)
            if km:
                kw = km.group(1).lower()
                if kw not in allowed:
                    self.refuse(n, 'keyword %s= of @%s is outside the subset (allowed: %s)'
                                % (km.group(1), word,
                                   ', '.join(sorted(k + '=' for k in allowed))))
                if kw in keywords:
                    self.refuse(n, '%s= given twice in @%s' % (kw, word))
                keywords[kw] = arg
            else:
                if keywords:
                    self.refuse(n, 'positional argument after a keyword in @%s' % word)
                positional.append(arg)
        if len(positional) > npos:
            self.refuse(n, '@%s takes %d positional argument%s; give %s by keyword '
                        '(extra: %s)'
                        % (word, npos, '' if npos == 1 else 's',
                           ' and '.join(sorted(k + '=' for k in allowed)),
                           ', '.join(positional[npos:])))
        if len(positional) < npos:
            self.refuse(n, '@%s takes %d positional argument%s, %d given'
                        % (word, npos, '' if npos == 1 else 's', len(positional)))
        for kw in sorted(required - set(keywords)):
            self.refuse(n, '@%s needs %s=' % (word, kw))
        self.directives[n] = ('assert', name, inner)

    def _marker(self, n, kind):
        if self._pending:
            self.refuse(n, '@%s follows @%s (line %d) with no subroutine between'
                        % (kind, self._pending[0], self._pending[1]))
        if kind == 'before' and self.before is not None:
            self.refuse(n, 'second @before in the module: the subset allows one')
        if kind == 'after' and self.after is not None:
            self.refuse(n, 'second @after in the module: the subset allows one')
        self._pending = (kind, n)
        self.directives[n] = ('marker', kind)

    def _inside_procedure(self, n, what):
        kinds = [u.kind for u in self._stack]
        if len(kinds) < 2 or kinds[0] != 'module' or kinds[-1] not in ('subroutine', 'function'):
            self.refuse(n, '%s outside a procedure of the test module' % what)

    # -- statements ----------------------------------------------------

    def _statement(self, first, last, text):
        low = re.sub(r'\s+', ' ', text.lower())
        if self._pending:
            self._marked_subroutine(first, last, low)
        if re.match(r'call execute_command_line\b', low) and not re.search(r'\bcmdstat ?=', low):
            self.refuse(first, 'execute_command_line without cmdstat=: a command that cannot run (a tool '
                        'not installed) would end the whole suite; give cmdstat= (exitstat= then says 127)')

        m = re.match(r'end ?(subroutine|function|module|submodule|interface|type|program)\b', low)
        if m or low == 'end':
            self._end(first, m.group(1) if m else None)
            return
        m = re.match(r'module (?!procedure\b|subroutine\b|function\b)(\w+)$', low)
        if m:
            if self._stack or self.module is not None:
                self.refuse(first, 'second module in the file: the subset takes one module '
                            'per .pf file')
            name = m.group(1)
            if not re.match(r'\s*module\s+\w+\s*$', self.lines[first - 1], re.I):
                self.refuse(first, 'write "module %s" alone on its line (no comment, no '
                            'continuation): pFUnit recognises the module only so' % name)
            if name != self.stem.lower():
                self.refuse(first, 'module %s is in %s: the module must be named after the '
                            'file (%s), as pFUnit\'s PFUNIT.mk names the suite after the file'
                            % (name, os.path.basename(self.path), self.stem))
            self.module = (name, first)
            self._stack.append(Unit('module', name, first))
            return
        if re.match(r'(submodule|program|block ?data)\b', low):
            self.refuse(first, 'only a module may hold the tests (found: %s)' % text)
        if low == 'contains':
            if self._stack:
                self._stack[-1].contains = True
            return
        if re.match(r'(abstract )?interface\b', low):
            m = re.match(r'interface (\w+)$', low)
            if m and len(self._stack) == 1:
                self._module_name(first, m.group(1), 'interface')
            self._stack.append(Unit('interface', '', first))
            return
        if re.match(r'type ?(,[^:]*)?::', low) or re.match(r'type (?!is\b)\w+$', low):
            m = re.match(r'type ?(?:,[^:]*)?(?:::)? ?(\w+)', low)
            if m and len(self._stack) == 1:
                self._module_name(first, m.group(1), 'type')
            self._stack.append(Unit('type', '', first))
            return
        if len(self._stack) == 1 and not self._stack[0].contains:
            m = re.match(r'(public|private)\b ?(:: ?)?(.*)$', low)
            if m:
                names = {n.strip() for n in m.group(3).split(',') if n.strip()}
                if m.group(1) == 'private':
                    self._default_private |= not names
                    self._private |= names
                else:
                    self._public |= names
                return
        m = re.match(r'use ?(, ?non_intrinsic ?)?(:: ?)?funit\b', low)
        if m and self._stack:
            self.uses_funit = True
            return
        kind, name = self._procedure_start(low)
        if kind:
            if not self._stack:
                self.refuse(first, '%s %s outside a module: the subset keeps the tests in one '
                            'module' % (kind, name))
            if len(self._stack) == 1:
                self._module_name(first, name, kind)
            self._stack.append(Unit(kind, name, first))
            return
        if len(self._stack) == 1 and not self._stack[0].contains:
            for what, name in self._declared_names(low):
                self._module_name(first, name, what)

    def _module_name(self, line, name, what):
        """Refuses a module-level name that real pFUnit's funit exports."""
        if name.lower() in FUNIT_PUBLIC_NAMES:
            self.refuse(line, 'module %s declares %s %s, a name that real pFUnit\'s funit module '
                        'makes public: with "use funit" the two clash and pFUnit does not compile '
                        'the module; rename it' % (self.module[0], what, name))

    @staticmethod
    def _declared_names(low):
        """[(what, name)] that a specification statement of the module
        declares: entities of a type declaration, names a USE ..., ONLY:
        makes local, a namelist group."""
        m = re.match(r'use\b.*?\bonly ?:(.*)$', low)
        if m:
            names = []
            for item in split_top(m.group(1), ','):
                item = item.strip()
                if not item or re.match(r'(operator|assignment)\b', item):
                    continue
                names.append(('the use-associated name', item.split('=>')[0].strip()))
            return names
        m = re.match(r'namelist ?/ ?(\w+) ?/', low)
        if m:
            return [('namelist group', m.group(1))]
        m = re.match(r'(integer|real|logical|complex|character|double ?precision|type ?\(|class ?\(|'
                     r'procedure ?\()', low)
        if not m:
            return []
        parts = low.split('::', 1)
        if len(parts) != 2:
            return []
        names = []
        for entity in split_top(parts[1], ','):
            em = re.match(r' ?(\w+)', entity)
            if em:
                names.append(('variable' if 'parameter' not in parts[0] else 'constant', em.group(1)))
        return names

    @staticmethod
    def _procedure_start(low):
        """('subroutine'|'function', name) if low opens a procedure."""
        m = re.match(r'(.*?)\b(subroutine|function) (\w+)', low)
        if not m:
            return None, None
        prefix, kind, name = m.groups()
        words = without_parens(prefix).replace('*', ' ').split()
        allowed = SUBROUTINE_PREFIX_WORDS if kind == 'subroutine' else FUNCTION_PREFIX_WORDS
        if any(w not in allowed for w in words):
            return None, None
        rest = low[m.end():].strip()
        if kind == 'function' and not rest.startswith('('):
            return None, None
        return kind, name

    def _marked_subroutine(self, first, last, low):
        kind, line = self._pending
        self._pending = None
        stack_ok = (len(self._stack) == 1 and self._stack[0].kind == 'module'
                    and self._stack[0].contains)
        raw = self.lines[first - 1]
        m = PFUNIT_SUBROUTINE_LINE.match(raw)
        if not stack_ok:
            where = ('before the module\'s CONTAINS' if len(self._stack) == 1
                     else 'inside %s %s' % (self._stack[-1].kind, self._stack[-1].name)
                     if self._stack else 'outside the module')
            self.refuse(line, '@%s marks a procedure %s: tests, @before and @after must be '
                        'module procedures' % (kind, where))
        if first != last or not m:
            self.refuse(line, '@%s must be followed by "subroutine name()" on one line, a '
                        'module procedure without arguments or prefixes (found: %s)'
                        % (kind, raw.strip()))
        name = m.group(1).lower()
        if kind == 'test':
            if any(t == name for t, _ in self.tests):
                self.refuse(line, 'second test named %s' % name)
            self.tests.append((name, line))
        elif kind == 'before':
            self.before = name
            self._before_at = (name, line)
        else:
            self.after = name
            self._after_at = (name, line)

    def _end(self, line, kind):
        if not self._stack:
            self.refuse(line, 'END without an open module or procedure')
        unit = self._stack.pop()
        if kind and kind != unit.kind:
            self.refuse(line, 'end %s closes %s %s (line %d)'
                        % (kind, unit.kind, unit.name, unit.line))

    # -- output ----------------------------------------------------------

    def translate(self):
        """The .F90 text: the .pf file with its directives replaced."""
        path = self.path
        fortran_path = path.replace("'", "''")
        cpp_path = path.replace('\\', '\\\\').replace('"', '\\"')

        def at(n):
            return '#line %d "%s"\n' % (n, cpp_path)

        out = ['! Generated from %s by tests/funit/pf2f90.py: do not edit.\n' % path, at(1)]
        for n, raw in enumerate(self.lines, 1):
            d = self.directives.get(n)
            indent = raw[:len(raw) - len(raw.lstrip())]
            if d is None:
                out.append(raw + '\n')
            elif d[0] == 'marker':
                out.append('%s!@%s\n' % (indent, d[1]))
            else:
                _, name, inner = d
                out += [at(n), '%scall %s( &\n' % (indent, name),
                        at(n), '%s   %s, &\n' % (indent, inner),
                        at(n), "%s   location=SourceLocation('%s', %d))\n"
                        % (indent, fortran_path, n),
                        at(n), '%sif (anyExceptions()) return\n' % indent,
                        at(n + 1)]
        return ''.join(out)


def read_pf(path):
    try:
        with open(path, encoding='utf-8') as f:
            return PfFile(path, f.read())
    except OSError as e:
        raise Refusal(path, 0, 'cannot read: %s' % e.strerror)
    except UnicodeDecodeError:
        raise Refusal(path, 0, 'not UTF-8 text')


def write_file(path, text):
    """Write text to path through a temporary file, so that an interrupted
    run leaves no half-written file for make to trust."""
    tmp = path + '.tmp'
    with open(tmp, 'w', encoding='utf-8') as f:
        f.write(text)
    os.replace(tmp, path)


def driver_text(pf_files):
    """The program that runs every test of every file, in order."""
    uses, calls = [], []
    count = 0
    for j, pf in enumerate(pf_files, 1):
        module = pf.module[0]
        before = after = ''
        if pf.before:
            uses.append('   use %s, only: funit_b%d => %s\n' % (module, j, pf.before))
            before = ', before=funit_b%d' % j
        if pf.after:
            uses.append('   use %s, only: funit_a%d => %s\n' % (module, j, pf.after))
            after = ', after=funit_a%d' % j
        for name, _ in pf.tests:
            count += 1
            uses.append('   use %s, only: funit_t%d => %s\n' % (module, count, name))
            calls.append("   call funit_run('%s', &\n      '%s', &\n      funit_t%d%s%s)\n"
                         % (module, name, count, before, after))
    return ''.join(
        ['! Generated by tests/funit/pf2f90.py from %d .pf file%s: do not edit.\n'
         % (len(pf_files), '' if len(pf_files) == 1 else 's'),
         '!> Runs every @test, each between the @before and @after of its module,\n',
         '!> printing PASS or FAIL per test and "N passed, N failed" last.\n',
         '!> Arguments, if any, select the tests whose module.name contains one.\n',
         'program funit_driver\n',
         '   use funit, only: funit_run, funit_summary\n'] + uses +
        ['   implicit none\n', '\n'] + calls +
        ['   call funit_summary()\n', 'end program funit_driver\n'])


def check_rejects(paths):
    """Each file must be refused where its "! expect-error: LINE: WORDS"
    first line says; return the number of files that were not."""
    bad = 0
    for path in paths:
        with open(path, encoding='utf-8') as f:
            first = f.readline()
        m = re.match(r'\s*!\s*expect-error:\s*(\d+):\s*(.+?)\s*$', first)
        if not m:
            print('%s:1: no "! expect-error: LINE: WORDS" first line' % path, file=sys.stderr)
            bad += 1
            continue
        line, words = int(m.group(1)), m.group(2)
        try:
            read_pf(path)
        except Refusal as e:
            if e.line == line and words.lower() in e.text.lower():
                continue
            print('%s: refused as "%s", expected line %d with "%s"' % (path, e, line, words),
                  file=sys.stderr)
            bad += 1
            continue
        print('%s: accepted, but should be refused at line %d' % (path, line), file=sys.stderr)
        bad += 1
    return bad


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('inputs', nargs='*', metavar='FILE.pf')
    ap.add_argument('-o', dest='output', help='translate the one input into OUTPUT')
    ap.add_argument('--driver', help='write the driver program running every test')
    ap.add_argument('--check-rejects', action='store_true',
                    help='check that every input is refused as its first line expects')
    args = ap.parse_args(argv)

    if args.check_rejects:
        if not args.inputs:
            ap.error('--check-rejects needs files')
        bad = check_rejects(args.inputs)
        if bad:
            print('pf2f90 self-check: %d of %d unsupported inputs not refused as expected'
                  % (bad, len(args.inputs)), file=sys.stderr)
            return 1
        print('pf2f90 self-check: %d unsupported inputs refused with file and line'
              % len(args.inputs))
        return 0

    if bool(args.output) == bool(args.driver):
        ap.error('give exactly one of -o OUTPUT and --driver DRIVER')
    if args.output and len(args.inputs) != 1:
        ap.error('-o translates one file')
    try:
        files = [read_pf(p) for p in args.inputs]
        if args.driver:
            seen = {}
            for pf in files:
                if pf.module[0] in seen:
                    raise Refusal(pf.path, pf.module[1], 'module %s also in %s'
                                  % (pf.module[0], seen[pf.module[0]]))
                seen[pf.module[0]] = pf.path
            write_file(args.driver, driver_text(files))
        else:
            write_file(args.output, files[0].translate())
    except Refusal as e:
        print(e, file=sys.stderr)
        return 1
    for pf in files if args.output else []:
        if not pf.tests:
            print('%s: warning: no @test in module %s' % (pf.path, pf.module[0]),
                  file=sys.stderr)
    return 0


if __name__ == '__main__':
    sys.exit(main())
