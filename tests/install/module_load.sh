#!/bin/bash
# The modulefile of make install, loaded with Lmod as a user loads it
# (tests/test_install.pf):
#
#   bash tests/install/module_load.sh PREFIX OUT
#
# PREFIX is an install prefix (make install PREFIX=...); OUT receives one
# key=value line per fact, which the test compares:
#   prefix        PREFIX as given
#   lmod          Lmod's version line, or 'missing'
#   load          exit status of `module load impact`
#   loaded        the module as `module -t list` names it
#   impact        `command -v impact` after the load
#   man           `man -w impact` after the load
#   version       the first line of `impact --version` after the load
#   root          IMPACT_ROOT after the load
#   man_kept      yes when `man -w man` finds the same page as before the
#                 load (the modulefile keeps man's own search path)
#   unload        exit status of `module unload impact`
#   impact_after  `command -v impact` after the unload
# Lmod is Debian's (package lmod, installed by tools/setup-debian); without
# it the script says so and exits 1: the test then fails, it is not skipped.
set -u
prefix=$1
out=$2
: > "$out" || exit 1
say() { printf '%s=%s\n' "$1" "$2" >> "$out"; }
say prefix "$prefix"

init=/usr/share/lmod/lmod/init/bash
if [ ! -r "$init" ]; then
    say lmod missing
    echo "module_load.sh: no Lmod ($init): make setup installs the Debian package lmod" >&2
    exit 1
fi
# A fresh login: no module loaded, man's own search path.
unset MANPATH LOADEDMODULES _LMFILES_ MODULEPATH
man_before=$(man -w man 2>/dev/null)
# shellcheck disable=SC1090  # Lmod's own init script
. "$init"
say lmod "$(module --version 2>&1 | grep -m 1 -o 'Version [^ ]*')"

module use "$prefix/share/modulefiles"
module load impact
say load $?
say loaded "$(module -t list 2>&1 | grep '^impact/')"
say impact "$(command -v impact)"
say man "$(man -w impact 2>/dev/null)"
say version "$(impact --version 2>&1 | head -n 1)"
say root "${IMPACT_ROOT-}"
if [ "$(man -w man 2>/dev/null)" = "$man_before" ]; then say man_kept yes; else say man_kept no; fi
module unload impact
say unload $?
say impact_after "$(command -v impact)"
exit 0
