#!/bin/sh
# The README's two commands on a machine that has none of the libraries yet.
#
# Why this exists: on a fresh Debian 12, HDF5, pkg-config and python3 come
# only with make setup, which make run and make test call first. A make that
# looks for them while it reads the Makefile stops before the set-up can
# install them; CI's machine has them all, so CI alone cannot see it.
#
# In a clean copy of the tree (no build/, no out/), with h5fc, pkg-config and
# python3 hidden from PATH (a directory of links to everything else) and no
# HDF5_ROOT, it runs make -n run, make -n test, make -n setup, make version
# and make clean, and writes to $1, one `name=value` a line: each one's exit
# status, and for make -n run the line of the set-up and of the first
# compilation (0 when absent).
set -u
out=$(realpath -m "$1")
here=$(pwd)
work=$(dirname "$out")/hidden
rm -rf "$work" && mkdir -p "$work/tree" "$work/bin" || exit 1
tar -C "$here" --exclude=./.git --exclude=./build --exclude=./out -cf - . | tar -C "$work/tree" -xf - || exit 1

# Every command on PATH but those hidden, as a link in one directory.
IFS=:
for d in $PATH; do
    [ -d "$d" ] || continue
    for f in "$d"/*; do
        name=${f##*/}
        case $name in
            h5fc | h5pfc | h5cc | pkg-config | pkgconf | *-pkg-config | python3* | python) continue ;;
        esac
        [ -x "$f" ] && [ ! -e "$work/bin/$name" ] && ln -s "$f" "$work/bin/$name"
    done
done
unset IFS

run_make() {
    (cd "$work/tree" && env -u HDF5_ROOT -u MAKEFLAGS -u MAKELEVEL -u MFLAGS PATH="$work/bin" \
        make --no-print-directory "$@")
}
{
    run_make -n run > "$work/run.txt" 2>&1; echo "dry_run=$?"
    run_make -n test > "$work/test.txt" 2>&1; echo "dry_test=$?"
    run_make -n setup > "$work/setup.txt" 2>&1; echo "dry_setup=$?"
    run_make version > "$work/version.txt" 2>&1; echo "version=$?"
    run_make clean > "$work/clean.txt" 2>&1; echo "clean=$?"
    setup=$(grep -n -m1 'tools/setup-debian' "$work/run.txt" | cut -d: -f1)
    compile=$(grep -n -m1 -e ' -c .*\.f90 ' -e ' -c .*\.c ' "$work/run.txt" | cut -d: -f1)
    echo "setup_line=${setup:-0}"
    echo "compile_line=${compile:-0}"
} > "$out"
