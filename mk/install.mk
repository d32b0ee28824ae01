# make install: the program and what a user of it needs, under a prefix, the
# way a cluster's module build or a package build expects:
#
#   make install [PREFIX=/usr/local] [DESTDIR=]
#
#   $(DESTDIR)$(PREFIX)/bin/impact              the program
#   $(DESTDIR)$(PREFIX)/bin/impact-sweep        tools/sweep of this install (mk/install/impact-sweep
#                                               runs share/impact/tools/sweep, which runs bin/impact)
#   $(DESTDIR)$(PREFIX)/bin/impact-h5export     <prefix>.h5 -> gnuplot grid (tools/h5export.f90), out of
#                                               HDF5's own h5* names; bin/h5export, a link to it, for
#                                               one release (1.3.x) more
#   $(DESTDIR)$(PREFIX)/bin/impact-damage-map   tools/damage-map (a link into share/impact/tools)
#   $(DESTDIR)$(PREFIX)/share/impact/postproc/  the gnuplot scripts (history.gp, shape.gp,
#                                               damage_map.gp for any run; fig*.gp and the rest
#                                               with this repository's data)
#   $(DESTDIR)$(PREFIX)/share/impact/tools/     sweep, impact_files.py (the module it reads decks,
#                                               schema and summaries with), damage-map (which
#                                               damage_map.gp finds as ../tools/damage-map);
#                                               the installed sweep runs $(PREFIX)/bin/impact
#   $(DESTDIR)$(PREFIX)/share/impact/input/     the example decks (clamped, simply supported, free)
#   $(DESTDIR)$(PREFIX)/share/impact/VERSION    the release, which the tools' --version give
#   $(DESTDIR)$(PREFIX)/share/man/man1/impact.1 the man page: impact --help and --version through
#                                               help2man, with mk/install/impact.h2m and the deck's
#                                               groups and variables from impact --schema
#   $(DESTDIR)$(PREFIX)/share/modulefiles/impact/$(IMPACT_VERSION)
#                                               a modulefile (Tcl: Environment Modules and Lmod):
#                                               PATH, MANPATH, IMPACT_ROOT = $(PREFIX)
#   $(DESTDIR)$(PREFIX)/share/doc/impact/       README.md, LICENSE, CITATION.cff, CHANGELOG.md, and
#                                               docs/*.md: the documents --help and the man page name
#
#   make uninstall [PREFIX=/usr/local] [DESTDIR=]   removes every file make install wrote
#                                                   (the modulefile of this version only)
#
# PREFIX, an absolute path, is where the files will live when used (the
# modulefile names it); DESTDIR, empty by default, a staging root prepended to
# every path (packaging: DESTDIR=$(pwd)/stage). Nothing outside
# $(DESTDIR)$(PREFIX) is written. The binaries are the ones make builds here
# (FC, FFLAGS, HDF5_ROOT, ... as for make); cluster HDF5 libraries are found
# at run time through the rpath mk/hdf5.mk links in. The man page needs
# help2man (Debian: tools/setup-debian installs it). On a cluster:
#
#   make install PREFIX=/apps/impact/$(IMPACT_VERSION)
#   module use /apps/impact/$(IMPACT_VERSION)/share/modulefiles   (or copy the modulefile
#   module load impact                                     into the site's tree)
#
# tests/test_install.pf installs into a temporary DESTDIR, and into a
# temporary PREFIX where the modulefile is loaded with Lmod.

PREFIX  ?= /usr/local
DESTDIR ?=
INSTALL ?= install
install_root = $(DESTDIR)$(PREFIX)
install_share = $(install_root)/share/impact
install_doc = $(install_root)/share/doc/impact
install_modulefile = $(install_root)/share/modulefiles/impact/$(IMPACT_VERSION)
MAN_PAGE := $(BUILD)/man/impact.1

# PREFIX goes into the modulefile and every path into a shell's quotes.
install_problem = $(strip $(if $(PREFIX),,PREFIX is empty) \
    $(if $(filter-out /%,$(firstword $(PREFIX))),PREFIX=$(PREFIX): an absolute path is needed) \
    $(if $(word 2,$(PREFIX))$(word 2,$(DESTDIR)),PREFIX and DESTDIR may not hold spaces) \
    $(foreach c,' " | & \ { } $$,$(if $(findstring $(c),$(PREFIX)$(DESTDIR)),PREFIX and DESTDIR may not hold $(c))))

.PHONY: install uninstall man
install: impact $(H5EXPORT) $(MAN_PAGE)
	$(if $(install_problem),$(error make install: $(install_problem)))
	$(INSTALL) -d '$(install_root)/bin' '$(install_share)/postproc' '$(install_share)/tools' \
	    '$(install_share)/input' '$(install_root)/share/man/man1' '$(install_doc)' \
	    '$(dir $(install_modulefile))'
	$(INSTALL) -m 755 impact '$(install_root)/bin/impact'
	$(INSTALL) -m 755 $(H5EXPORT) '$(install_root)/bin/impact-h5export'
	ln -sf impact-h5export '$(install_root)/bin/h5export'
	$(INSTALL) -m 755 mk/install/impact-sweep '$(install_root)/bin/impact-sweep'
	$(INSTALL) -m 644 $(wildcard postproc/*.gp) '$(install_share)/postproc/'
	$(INSTALL) -m 755 tools/sweep '$(install_share)/tools/sweep'
	$(INSTALL) -m 644 tools/impact_files.py '$(install_share)/tools/impact_files.py'
	$(INSTALL) -m 755 tools/damage-map '$(install_share)/tools/damage-map'
	ln -sf ../share/impact/tools/damage-map '$(install_root)/bin/impact-damage-map'
	$(INSTALL) -m 644 $(wildcard input/*.nml) '$(install_share)/input/'
	$(INSTALL) -m 644 VERSION '$(install_share)/VERSION'
	$(INSTALL) -m 644 $(MAN_PAGE) '$(install_root)/share/man/man1/impact.1'
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(IMPACT_VERSION)|g' mk/install/modulefile.tcl \
	    > '$(install_modulefile).tmp' && mv '$(install_modulefile).tmp' '$(install_modulefile)'
	chmod 644 '$(install_modulefile)'
	$(INSTALL) -m 644 README.md LICENSE CITATION.cff CHANGELOG.md '$(install_doc)/'
	$(INSTALL) -d '$(install_doc)/docs'
	$(INSTALL) -m 644 $(wildcard docs/*.md) '$(install_doc)/docs/'
	@echo 'make install: impact $(IMPACT_VERSION) in $(PREFIX): bin/impact, bin/impact-sweep, bin/impact-h5export,' \
	    'bin/impact-damage-map, share/impact, share/man/man1/impact.1,' \
	    'share/modulefiles/impact/$(IMPACT_VERSION)$(if $(DESTDIR), (staged under $(DESTDIR)))'

# make uninstall: what make install wrote, and only that (share/impact and
# share/doc/impact are impact's own; of share/modulefiles/impact, this
# version's file only, the directory if it is left empty).
uninstall:
	$(if $(install_problem),$(error make uninstall: $(install_problem)))
	rm -f '$(install_root)/bin/impact' '$(install_root)/bin/impact-h5export' '$(install_root)/bin/h5export' \
	    '$(install_root)/bin/impact-sweep' '$(install_root)/bin/impact-damage-map' \
	    '$(install_root)/share/man/man1/impact.1' '$(install_modulefile)'
	rm -rf '$(install_share)' '$(install_doc)'
	-rmdir '$(dir $(install_modulefile))' 2> /dev/null
	@echo 'make uninstall: impact removed from $(PREFIX)$(if $(DESTDIR), (staged under $(DESTDIR)))'

# ---- the man page impact.1 (make man: only the page, $(MAN_PAGE)): the
#      options and usage of impact --help, the version of --version, the
#      sections of mk/install/impact.h2m, and the deck's groups and variables
#      from impact --schema (mk/install/deck-man-section; included first, so
#      that DECK comes before the other sections help2man does not order)
man: $(MAN_PAGE)
$(MAN_PAGE): impact mk/install/impact.h2m mk/install/deck-man-section mk/install.mk
	@command -v help2man > /dev/null 2>&1 || { echo 'make install: help2man is needed for the man page' \
	    'impact.1 (Debian: apt-get install help2man, or make setup)' >&2; exit 1; }
	@mkdir -p '$(BUILD)/man'
	./impact --schema > '$(BUILD)/man/schema.tsv'
	$(PYTHON) mk/install/deck-man-section < '$(BUILD)/man/schema.tsv' > '$(BUILD)/man/deck.h2m'
	help2man --no-info --include='$(BUILD)/man/deck.h2m' --include=mk/install/impact.h2m \
	    --output='$@.tmp' ./impact && mv '$@.tmp' '$@'
