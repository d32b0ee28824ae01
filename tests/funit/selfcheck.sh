#!/bin/sh
# Self-check of the test framework (make test-funit), quick and quiet:
#  1. pf2f90.py refuses every file of tests/funit/reject/ at the line and with
#     the words its first line expects, and its command line says
#     "file:line: error: ..." with exit status 1 and writes nothing;
#  2. the suite tests/funit/selfcheck/test_selfcheck.pf, translated and built
#     in a temporary directory, gives the PASS/FAIL lines, failure locations
#     and "N passed, N failed" line of selfcheck/expected.txt, exits non-zero,
#     and its generated code compiles without a warning;
#  3. pfunit.mk (make test PFUNIT_DIR=...) refuses a pFUnit older than 4.13
#     and takes 4.13, given stand-in installs whose PFUNIT.mk sets only
#     PFUNIT_VERSION.
#
# Usage: sh tests/funit/selfcheck.sh PYTHON FC "FLAGS" MODDIR FUNIT_OBJECT
#   MODDIR holds funit.mod, FUNIT_OBJECT is the compiled tests/funit/funit.f90.

set -u
python=$1 fc=$2 flags=$3 moddir=$4 funit_obj=$5
here=$(cd "$(dirname "$0")" && pwd)
moddir=$(cd "$moddir" && pwd)
funit_obj=$(cd "$(dirname "$funit_obj")" && pwd)/$(basename "$funit_obj")

fail() {
    echo "test-funit: $*" >&2
    exit 1
}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/funit-selfcheck.XXXXXX") || fail "no temporary directory"
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' HUP INT TERM

# 1. Refusals.
"$python" "$here/pf2f90.py" --check-rejects "$here"/reject/*.pf >"$tmp/rejects" ||
    fail "pf2f90.py accepted input outside the subset (above)"
reject="$here/reject/unknown_directive.pf"
line=$(sed -n '1s/^! expect-error: \([0-9]*\):.*/\1/p' "$reject")
if "$python" "$here/pf2f90.py" "$reject" -o "$tmp/refused.F90" 2>"$tmp/stderr"; then
    fail "pf2f90.py exited 0 on $reject"
fi
grep -q "^$reject:$line: error: unknown directive @assertExceptionRaised" "$tmp/stderr" ||
    fail "pf2f90.py did not name $reject:$line: $(cat "$tmp/stderr")"
[ ! -e "$tmp/refused.F90" ] || fail "pf2f90.py wrote output for a refused file"

# 2. A suite with deliberate failures.
cp "$here/selfcheck/test_selfcheck.pf" "$tmp/"
cd "$tmp" || fail "cannot enter $tmp"
if ! { "$python" "$here/pf2f90.py" test_selfcheck.pf -o test_selfcheck.F90 &&
       "$python" "$here/pf2f90.py" --driver driver.f90 test_selfcheck.pf; }; then
    fail "pf2f90.py refused tests/funit/selfcheck/test_selfcheck.pf"
fi
# shellcheck disable=SC2086  # $fc and $flags are lists of words
if ! { $fc $flags -I"$moddir" -J. -c test_selfcheck.F90 -o test_selfcheck.o 2>compile.log &&
       $fc $flags -I"$moddir" -J. driver.f90 test_selfcheck.o "$funit_obj" -o run_selfcheck \
           2>>compile.log; }; then
    cat compile.log >&2
    fail "the self-check suite does not build"
fi
[ ! -s compile.log ] || { cat compile.log >&2; fail "warnings in the generated code"; }

./run_selfcheck >output
status=$?
[ "$status" -ne 0 ] || fail "the driver exited 0 although tests failed"
# Status, name and location of each test, and the summary line.
awk '$1 == "FAIL" { print $1, $2, $3; next } { print }' output >summary
if ! diff "$here/selfcheck/expected.txt" summary >diff.txt; then
    cat output >&2
    cat diff.txt >&2
    fail "the driver's report differs from tests/funit/selfcheck/expected.txt (above)"
fi
grep -q '^FAIL test_selfcheck.test_fails_then_returns  test_selfcheck.pf:[0-9]*  deliberate: expected <1> but found <2>$' output ||
    fail "the failure line lacks the message: $(grep fails_then_returns output)"

# 3. The pFUnit version (make in the environment of none that runs this).
mkdir -p "$tmp/pfunit/old/PFUNIT-4.12/include" "$tmp/pfunit/new/PFUNIT-4.13/include" ||
    fail "no stand-in pFUnit installs"
echo 'PFUNIT_VERSION := 4.12' >"$tmp/pfunit/old/PFUNIT-4.12/include/PFUNIT.mk"
echo 'PFUNIT_VERSION := 4.13' >"$tmp/pfunit/new/PFUNIT-4.13/include/PFUNIT.mk"
if env MAKEFLAGS= MAKELEVEL= make -s -f "$here/pfunit.mk" pfunit-version PFUNIT_DIR="$tmp/pfunit/old" \
        >"$tmp/pfunit/old.log" 2>&1; then
    fail "pfunit.mk took pFUnit 4.12, which exits 0 when tests fail"
fi
env MAKEFLAGS= MAKELEVEL= make -s -f "$here/pfunit.mk" pfunit-version PFUNIT_DIR="$tmp/pfunit/new" \
    >"$tmp/pfunit/new.log" 2>&1 || fail "pfunit.mk refused pFUnit 4.13: $(cat "$tmp/pfunit/new.log")"

echo "test-funit: framework self-check passed ($(sed -n 's/^pf2f90 self-check: \([0-9]*\).*/\1/p' "$tmp/rejects") inputs refused; deliberate failures reported: $(tail -n 1 output); pFUnit 4.12 refused, 4.13 taken)"
