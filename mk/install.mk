# make install: the program and what a user of it needs, under a prefix, the
# way a cluster's module build or a package build expects:
#
#   make install [PREFIX=/usr/local] [DESTDIR=]
#
#   $(DESTDIR)$(PREFIX)/bin/impact              the program
#   $(DESTDIR)$(PREFIX)/bin/h5export            <prefix>.h5 -> gnuplot grid (tools/h5export.f90)
#   $(DESTDIR)$(PREFIX)/share/impact/postproc/  the gnuplot scripts (history.gp, shape.gp for any
#                                               run; fig*.gp and the rest with this repository's data)
#   $(DESTDIR)$(PREFIX)/share/impact/tools/     sweep and impact_files.py, the module it reads
#                                               decks, schema and summaries with; the installed
#                                               sweep runs $(PREFIX)/bin/impact
#   $(DESTDIR)$(PREFIX)/share/impact/input/     the example decks (clamped, simply supported, free)
#   $(DESTDIR)$(PREFIX)/share/doc/impact/       README.md
#
# PREFIX is where the files will live when used; DESTDIR, empty by default, a
# staging root prepended to every path (packaging: DESTDIR=$(pwd)/stage).
# Nothing outside $(DESTDIR)$(PREFIX) is written. The binaries are the ones
# make builds here (FC, FFLAGS, HDF5_ROOT, ... as for make); cluster HDF5
# libraries are found at run time through the rpath mk/hdf5.mk links in.
# tests/test_install.pf installs into a temporary DESTDIR.

PREFIX  ?= /usr/local
DESTDIR ?=
INSTALL ?= install
install_root = $(DESTDIR)$(PREFIX)
install_share = $(install_root)/share/impact

.PHONY: install
install: impact $(H5EXPORT)
	$(INSTALL) -d '$(install_root)/bin' '$(install_share)/postproc' '$(install_share)/tools' \
	    '$(install_share)/input' '$(install_root)/share/doc/impact'
	$(INSTALL) -m 755 impact '$(install_root)/bin/impact'
	$(INSTALL) -m 755 $(H5EXPORT) '$(install_root)/bin/h5export'
	$(INSTALL) -m 644 $(wildcard postproc/*.gp) '$(install_share)/postproc/'
	$(INSTALL) -m 755 tools/sweep '$(install_share)/tools/sweep'
	$(INSTALL) -m 644 tools/impact_files.py '$(install_share)/tools/impact_files.py'
	$(INSTALL) -m 644 $(wildcard input/*.nml) '$(install_share)/input/'
	$(INSTALL) -m 644 README.md '$(install_root)/share/doc/impact/README.md'
	@echo 'make install: $(PREFIX)/bin/impact, $(PREFIX)/bin/h5export, $(PREFIX)/share/impact' \
	    '$(if $(DESTDIR),(staged under $(DESTDIR)))'
