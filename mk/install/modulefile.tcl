#%Module1.0
## impact @VERSION@: nonlinear low-velocity impact of composite laminates
## (Choi, Hong & Lee 1991). Written by make install (mk/install.mk) from
## mk/install/modulefile.tcl; Environment Modules and Lmod read it:
##   module use @PREFIX@/share/modulefiles
##   module load impact
## puts bin/ (impact, impact-sweep, impact-h5export, impact-damage-map) on PATH and
## the man page impact(1) on MANPATH; IMPACT_ROOT is the install prefix
## (the gnuplot scripts: $IMPACT_ROOT/share/impact/postproc).

proc ModulesHelp { } {
    puts stderr "impact @VERSION@: nonlinear low-velocity impact of composite laminates"
    puts stderr "(Choi, Hong & Lee 1991). impact --help, man impact;"
    puts stderr "gnuplot scripts and example decks under \$IMPACT_ROOT/share/impact."
}
module-whatis "impact @VERSION@: nonlinear low-velocity impact of composite laminates (Choi, Hong & Lee 1991)"

conflict impact

set root {@PREFIX@}
setenv IMPACT_ROOT $root
prepend-path PATH $root/bin
prepend-path MANPATH $root/share/man
# An empty element keeps man's own search path when MANPATH was not set
# before (man-db and Lmod: "dir::"), so that other man pages still open.
append-path MANPATH {}
