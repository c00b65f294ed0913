# lac -- Local Average Contact: a teaching and reference code.
#
#   make demo        set up (Debian packages), build, run a small example
#   make test        set up, build, run the whole test suite
#   make             build build/liblac.a, liblac.so.N, build/lac, its man page
#   make test-asan   the test suite under -fsanitize=address,undefined
#   make test-nomem  out of memory at every allocation of two contact runs
#   make bench       benchmarks (not in CI): sizes, times, memory
#   make figures     regenerate figures/ (pictures of the experiments)
#   make fuzz        libFuzzer harnesses (clang), FUZZ_SECONDS (60) each
#   make doc         the book as HTML in build/doc (pandoc, MathML)
#   make doc-test    make doc, then its pages checked in headless Chromium
#   make doc-snapshots  the book's snapshot tables rerun [UPDATE=1] [TIER=bench]
#   make exercise NAME=x [FROM=chapters/NN-name/skeleton.c]
#                    exercises/x/main.c from a skeleton, built as build/exercises/x
#   make install     bin/lac, the libraries, headers, lac.pc, lac.1 and the
#                    chapters' programs under PREFIX (/usr/local), DESTDIR
#   make uninstall   removes what make install put there
#   make help        all targets
#
# Non-recursive GNU make.  Library flags are plain variables (SuiteSparse 5
# and gmsh 4.8 ship no pkg-config file on Debian 12).

CC       ?= cc
# -O3: the loops over a cell's nodes and quadrature points (the assembly
# of K_T, the pairing) vectorize; the results are those of -O2 (no
# reassociation, no fused multiply-add at the base x86-64 instruction
# set).  bench/README.md, "From chapter 10".
CFLAGS   ?= -std=c11 -O3 -g -Wall -Wextra
CPPFLAGS += -D_POSIX_C_SOURCE=200809L -Isrc -I/usr/include/suitesparse \
            -I/usr/include/freetype2
LDFLAGS  += -Wl,--as-needed
SS_LIBS  ?= -lumfpack -lcholmod -lamd -lcolamd -lsuitesparseconfig
GSL_LIBS ?= -lgsl -lgslcblas
LDLIBS   += -lgmsh $(SS_LIBS) $(GSL_LIBS) -linih -lOSMesa -lfreetype -lpng16 -lm -pthread
# those of them that have a pkg-config file (lac.pc: make install)
PC_REQUIRES := gsl inih osmesa freetype2 libpng16

# Debian 12 packages needed to build, test and draw (man-db: make test
# reads the installed man page with man, tests/cases-install.sh).
DEB_PKGS := gcc make libc6-dev libgsl-dev libsuitesparse-dev gmsh libgmsh-dev \
            libosmesa6-dev libpng-dev pkg-config libopenblas0-pthread \
            libinih-dev gnuplot-nox libfreetype-dev fonts-dejavu-core man-db

# PETSc and Open MPI: the petsc strategy and mpirun (chapter 13), installed
# like the others.  PETSC=no builds without them (and does not install
# them); so does a machine where pkg-config does not find them: lac then
# builds all the same, and --strategy petsc prints the apt-get line.  The
# flags are found after the set-up, in $(B)/config-petsc-*.mk (make reads
# it again once it is made).
PETSC    ?= auto
DEB_PETSC := libpetsc-real-dev openmpi-bin
ifneq ($(PETSC),no)
DEB_PKGS += $(DEB_PETSC)
endif

B        ?= build
# The library, folder by folder in the order data flows (src/README.md);
# the command line (src/cli) is outside it.
LAYERS   := base linalg fem contact solve io render run
LIBSRC   := $(foreach l,$(LAYERS),$(wildcard src/$(l)/*.c))
LIBOBJ   := $(LIBSRC:src/%.c=$(B)/src/%.o)
LIB      := $(B)/liblac.a
# the shared library: liblac.so.VERSION, soname liblac.so.SOVERSION (raised
# when a change of the API headers, src/lac.h, breaks programs linked
# against the previous one); VERSION is lac --version's
LAC_VERSION   := $(shell sed -n 's/^\#define LAC_VERSION "\(.*\)"$$/\1/p' src/cli/main.c)
LAC_SOVERSION := 0
SHLIB    := $(B)/liblac.so.$(LAC_VERSION)
MANPAGE  := $(B)/lac.1
CLISRC   := $(filter-out src/cli/main.c,$(wildcard src/cli/*.c))
CLIOBJ   := $(CLISRC:src/%.c=$(B)/src/%.o)
CLILIB   := $(B)/liblac-cli.a
UNITSRC  := $(sort $(wildcard tests/unit/t*.c))
UNIT     := $(UNITSRC:tests/unit/%.c=$(B)/tests/%)
EXSRC    := $(wildcard chapters/[0-9][0-9]-*/example.c)
EX       := $(EXSRC:chapters/%/example.c=$(B)/chapters/%)
FIGSRC   := $(wildcard figures/*.c)
FIGPROG  := $(FIGSRC:figures/%.c=$(B)/figures/%)
BENCHSRC := $(wildcard bench/*.c)
BENCH    := $(BENCHSRC:bench/%.c=$(B)/bench/%)

all: deps $(LIB) $(SHLIB) $(B)/lac $(MANPAGE) $(EX)

# ---- PETSc's flags, once the packages are there --------------------------
PETSC_MK := $(B)/config-petsc-$(PETSC).mk
ifeq ($(filter clean help uninstall,$(MAKECMDGOALS)),)
-include $(PETSC_MK)
endif
CPPFLAGS += $(PETSC_CPPFLAGS)
LDLIBS   += $(PETSC_LIBS)
$(PETSC_MK): | $(B)/.deps-ok
	@if [ "$(PETSC)" != no ] && pkg-config --exists PETSc mpi-c; then \
	  echo "PETSC_CPPFLAGS := -DLAC_HAVE_PETSC $$(pkg-config --cflags-only-I PETSc mpi-c)"; \
	  echo "PETSC_LIBS := $$(pkg-config --libs PETSc mpi-c)"; \
	else echo "# built without PETSc"; fi > $@

# ---- set-up: install missing Debian packages (root) or say how ----------
deps: $(B)/.deps-ok
$(B)/.deps-ok: Makefile
	@sh tests/deps.sh $(DEB_PKGS) || { [ "$(PETSC)" = no ] || echo \
	  "lac: (or without PETSc and MPI, chapter 13: make PETSC=no)" >&2; exit 1; }
	@mkdir -p $(B) && touch $@

# ---- build ---------------------------------------------------------------
# (made anew: a member of a renamed source would stay in an archive that
# is only updated)
$(LIB): $(LIBOBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(CLILIB): $(CLIOBJ)
	rm -f $@ && $(AR) rcs $@ $^
# One set of objects, position-independent, makes both liblac.a and
# liblac.so: -fPIC costs nothing that matters here (measured: the unit
# tests took 41.3 s of CPU without it, 40.6 s with it; a 3D sphere at
# level 2, 21.8 and 22.1 s), where a second set would compile the library
# twice.  $(B)/.pic: objects of a tree built before were not, and are made
# again once.
$(B)/src/%.o: src/%.c $(B)/.pic | $(B)/.deps-ok
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -fPIC -MMD -MP -c $< -o $@
$(B)/.pic:
	@mkdir -p $(@D) && touch $@
$(SHLIB): $(LIBOBJ)
	$(CC) -shared $(CFLAGS) $(LDFLAGS) -Wl,-soname,liblac.so.$(LAC_SOVERSION) \
	  -Wl,--no-undefined $^ $(LDLIBS) -o $@
# the man page, from the text of lac --help (tools/man.awk)
$(MANPAGE): $(B)/lac tools/man.awk
	$(B)/lac --help > $(B)/lac-help.txt
	awk -v version=$(LAC_VERSION) -f tools/man.awk $(B)/lac-help.txt > $@
$(B)/lac: src/cli/main.c $(CLILIB) $(LIB)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(CLILIB) $(LIB) $(LDLIBS) -o $@
$(B)/tests/check.o: tests/check.c tests/check.h | $(B)/.deps-ok
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS) -c $< -o $@
$(B)/tests/%: tests/unit/%.c $(wildcard tests/unit/*.h) $(B)/tests/check.o $(CLILIB) $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS) $(LDFLAGS) $< $(B)/tests/check.o $(CLILIB) $(LIB) $(LDLIBS) -o $@
$(B)/tests/replay_%: fuzz/replay.c fuzz/fuzz_%.c fuzz/fuzz_check.h $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Ifuzz $(CFLAGS) $(LDFLAGS) fuzz/replay.c fuzz/fuzz_$*.c $(LIB) $(LDLIBS) -o $@
$(B)/tests/lac_main.o: src/cli/main.c | $(B)/.deps-ok
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -MMD -MP -Dmain=lac_cli_main -c $< -o $@
$(B)/tests/nomem_lac: tests/nomem_lac.c $(B)/tests/lac_main.o $(CLILIB) $(LIB)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(B)/tests/lac_main.o $(CLILIB) $(LIB) $(LDLIBS) -o $@
$(B)/tests/nomem_lac_malloc: tests/nomem_lac.c tests/nomem_malloc.c $(B)/tests/lac_main.o $(CLILIB) $(LIB)
	$(CC) $(CPPFLAGS) $(CFLAGS) -DNOMEM_MALLOC $(LDFLAGS) $< tests/nomem_malloc.c $(B)/tests/lac_main.o $(CLILIB) $(LIB) $(LDLIBS) -o $@
# lac with failures on purpose (LAC_TEST_FAIL_RANK, LAC_TEST_FAIL_AFTER:
# on an MPI process; LAC_TEST_SCALE_CELL: a K that is not its cells';
# fem/lac_assembly_dist.h, solve/lac_petsc_serve.c, tests/cases-petsc.sh):
# its objects of the distributed assembly and of the petsc strategy's
# other processes come before the library's.
$(B)/tests/lac_assembly_dist_faults.o: src/fem/lac_assembly_dist.c $(PETSC_MK) | $(B)/.deps-ok
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -MMD -MP -DLAC_TEST_FAULTS -c $< -o $@
$(B)/tests/lac_petsc_serve_faults.o: src/solve/lac_petsc_serve.c $(PETSC_MK) | $(B)/.deps-ok
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -MMD -MP -DLAC_TEST_FAULTS -c $< -o $@
$(B)/tests/lac_faults: src/cli/main.c $(B)/tests/lac_assembly_dist_faults.o $(B)/tests/lac_petsc_serve_faults.o $(CLILIB) $(LIB)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(B)/tests/lac_assembly_dist_faults.o $(B)/tests/lac_petsc_serve_faults.o $(CLILIB) $(LIB) $(LDLIBS) -o $@
$(B)/tests/scene_keys: tests/scene_keys.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@
$(B)/tests/numcmp: tests/numcmp.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $< -lm -o $@
$(B)/chapters/%: chapters/%/example.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@
$(B)/figures/%: figures/%.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@
$(B)/bench/%: bench/%.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@

# The objects that depend on PETSc's presence follow its changes.
$(B)/src/solve/lac_petsc.o $(B)/src/solve/lac_petsc_values.o \
  $(B)/src/solve/lac_petsc_serve.o $(B)/src/linalg/lac_petsc_env.o \
  $(B)/src/linalg/lac_petsc_saddle.o \
  $(B)/src/linalg/lac_petsc_saddle_solve.o $(B)/src/linalg/lac_petsc_mg.o \
  $(B)/src/linalg/lac_petsc_mg_aggregate.o \
  $(B)/src/linalg/lac_petsc_mg_prolong.o \
  $(B)/src/fem/lac_assembly_dist.o: \
  $(PETSC_MK)

-include $(LIBOBJ:.o=.d) $(CLIOBJ:.o=.d)
# main.c for the nomem harness follows the headers too (a stale copy
# read lac_run with the layout of an older lac_run_solution)
-include $(B)/tests/lac_main.d $(B)/tests/lac_assembly_dist_faults.d \
  $(B)/tests/lac_petsc_serve_faults.d

# ---- tests ---------------------------------------------------------------
NUMCMP   := $(if $(wildcard tests/numcmp.c),$(B)/tests/numcmp)
# the harnesses of make fuzz on the inputs that once crashed them
REPLAY   := $(B)/tests/replay_scene $(B)/tests/replay_mesh \
            $(B)/tests/replay_numbers
# the key tables for the book's doc tests (tests/cases-doc.sh)
DOCTEST  := $(B)/tests/scene_keys
test: all $(UNIT) $(NUMCMP) $(FIGPROG) $(REPLAY) $(B)/tests/nomem_lac $(DOCTEST) \
      $(B)/tests/lac_faults
	@B=$(B) sh tests/run.sh $(UNIT)

# The same suite under AddressSanitizer and UBSan (library suppressions only).
# Open MPI leaks at exit inside its plug-ins: they stay loaded (no
# dlclose) and, for the programs that start MPI only (LAC_MPI_ASAN: the
# petsc tests; the slow unwinder hangs OSMesa's threads), the stacks are
# unwound in full, so that the suppressions of tests/lsan.supp name them.
test-asan:
	ASAN_OPTIONS=alloc_dealloc_mismatch=0:detect_leaks=1 \
	LAC_MPI_ASAN=:fast_unwind_on_malloc=0:malloc_context_size=40 \
	OMPI_MCA_mca_base_component_disable_dlclose=1 \
	PMIX_MCA_mca_base_component_disable_dlclose=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1 \
	$(MAKE) B=build/asan LDFLAGS="-fsanitize=address,undefined" \
	  CFLAGS="-std=c11 -O1 -g -Wall -Wextra -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" test

# Out of memory at every allocation of two whole contact runs (the Taylor
# patch tests in 2D and 3D; about 10 minutes; cases-bad.sh does every 15th
# of the 2D one): exit status 1 and one line each time, never a signal.
# lac's own allocations (and the child's), then every malloc of lac's
# process in 2D (tests/nomem_malloc.c; not under AddressSanitizer; in 3D
# OpenBLAS and libgomp end the process with words of their own, chapter
# 01, bad-input.md, section 9).
NOMEM_SCENES := chapters/08-experiments/taylor2d.scene \
                chapters/08-experiments/taylor3d.scene
test-nomem: all $(B)/tests/nomem_lac $(B)/tests/nomem_lac_malloc
	for s in $(NOMEM_SCENES); do sh tests/nomem.sh $(B) 1 500 $$s || exit 1; done
	NOMEM_LAC=nomem_lac_malloc sh tests/nomem.sh $(B) 1 500 \
	  chapters/08-experiments/taylor2d.scene

demo: all
	$(B)/lac run chapters/01-problem/sphere-axi.scene --out $(B)/demo

# The ring on block, coarse and fine hex20 (about 25 minutes; also in bench);
# the fine one alone (about 20 minutes).
bench-ring: all
	sh bench/ring.sh $(B)

bench-ring-fine: all
	sh bench/ring.sh $(B) hex20 1

bench: all $(BENCH)
	@for b in $(BENCH); do echo "== $$b"; ./$$b || exit 1; done
	@for s in bench/*.sh; do echo "== $$s"; sh $$s $(B) || exit 1; done

# Regenerate figures/ (OSMesa pictures, gnuplot curves; no display needed).
figures: all $(FIGPROG)
	sh figures/make-figures.sh $(B)

clean:
	rm -rf build

# ---- make install, make uninstall (README.md, "Using lac as a library") ---
# The GNU conventions: PREFIX (/usr/local) and the directories under it,
# DESTDIR before every path (a staged install).  Installed:
#   bin/lac                     the command (liblac.a linked in)
#   lib/liblac.a, lib/liblac.so.VERSION, liblac.so.SOVERSION -> it,
#   liblac.so -> liblac.so.SOVERSION
#   include/lac/lac.h           the API in one include (src/lac.h), and
#   include/lac/FOLDER/*.h      every header of the library (not
#                               *_internal.h), in its folder of src/: the
#                               flag -I$(includedir)/lac of lac.pc keeps
#                               #include "fem/lac_mesh.h" as in the tree
#   lib/pkgconfig/lac.pc        the flags: a shared link needs -llac -lm;
#                               a static one (--static) also what liblac.a
#                               calls: the packages of PC_REQUIRES, and
#                               SuiteSparse, gmsh (no .pc on Debian 12) and
#                               PETSc + MPI (their Libs only: PETSc's .pc
#                               gives _FORTIFY_SOURCE in Cflags) as -l flags
#   share/man/man1/lac.1        the man page
#   share/doc/lac/examples/NN-name/  each chapter's example.c and scenes
# and share/doc/lac/install-manifest: the files and the directories that
# install made, which uninstall removes (tools/install.sh).  As root and
# without DESTDIR, install and uninstall run $(LDCONFIG) (LDCONFIG= : not).
PREFIX      = /usr/local
bindir      = $(PREFIX)/bin
libdir      = $(PREFIX)/lib
includedir  = $(PREFIX)/include
datarootdir = $(PREFIX)/share
mandir      = $(datarootdir)/man
docdir      = $(datarootdir)/doc/lac
LDCONFIG    = ldconfig
MANIFEST    = $(docdir)/install-manifest
HEADERS  := $(filter-out %_internal.h,$(foreach l,$(LAYERS),$(wildcard src/$(l)/*.h)))
EXDOC    := $(foreach d,$(EXSRC:%/example.c=%),$(d)/example.c \
              $(wildcard $(d)/*.scene $(d)/*.geo))
# lac.pc: paths under ${prefix}; -DLAC_HAVE_PETSC declares the functions
# of the PETSc modules; a library built with sanitizers (make test-asan)
# needs their run-time in the program, first
define LAC_PC
prefix=$(PREFIX)
libdir=$(patsubst $(PREFIX)/%,$${prefix}/%,$(libdir))
includedir=$(patsubst $(PREFIX)/%,$${prefix}/%,$(includedir))

Name: lac
Description: the Local Average Contact method: frictionless contact between elastic bodies with non-matching meshes
Version: $(LAC_VERSION)
Requires.private: $(PC_REQUIRES)
Cflags: $(strip -I$${includedir}/lac $(filter -DLAC_HAVE_PETSC,$(PETSC_CPPFLAGS)))
Libs: $(strip -L$${libdir} -llac -lm $(filter -fsanitize=%,$(LDFLAGS)))
Libs.private: $(strip -lgmsh $(SS_LIBS) -pthread $(PETSC_LIBS))
endef
# "MODE FILE TARGET" and "link VALUE TARGET" lines for tools/install.sh
INSTALL_LIST = \
  echo "755 $(B)/lac $(bindir)/lac"; \
  echo "644 $(LIB) $(libdir)/liblac.a"; \
  echo "644 $(SHLIB) $(libdir)/$(notdir $(SHLIB))"; \
  echo "link $(notdir $(SHLIB)) $(libdir)/liblac.so.$(LAC_SOVERSION)"; \
  echo "link liblac.so.$(LAC_SOVERSION) $(libdir)/liblac.so"; \
  echo "644 src/lac.h $(includedir)/lac/lac.h"; \
  $(foreach h,$(HEADERS),echo "644 $(h) $(includedir)/lac/$(h:src/%=%)";) \
  echo "644 $(B)/lac.pc $(libdir)/pkgconfig/lac.pc"; \
  echo "644 $(MANPAGE) $(mandir)/man1/lac.1"; \
  $(foreach f,$(EXDOC),echo "644 $(f) $(docdir)/examples/$(f:chapters/%=%)";)
RUN_LDCONFIG = $(if $(LDCONFIG),if [ -z "$(DESTDIR)" ] && \
  [ "$$(id -u)" = 0 ]; then $(LDCONFIG); fi,:)
install: all
	@case "$(PREFIX)" in /*) ;; *) echo "lac: PREFIX=$(PREFIX): not an absolute path" >&2; exit 2 ;; esac
	$(file >$(B)/lac.pc,$(LAC_PC))
	@{ $(INSTALL_LIST) } | sh tools/install.sh install "$(DESTDIR)" "$(MANIFEST)"
	@$(RUN_LDCONFIG)
uninstall:
	@sh tools/install.sh uninstall "$(DESTDIR)" "$(MANIFEST)"
	@$(RUN_LDCONFIG)

# ---- the book as HTML (chapters/html/README.md) ---------------------------
# pandoc and chromium are installed like the packages above (as root), or
# their apt-get line is printed; neither is needed by make test.
DEB_DOC     := pandoc
DEB_DOCTEST := chromium
DOC_B    := $(B)/doc
doc:
	@sh tests/deps.sh $(DEB_DOC)
	rm -rf $(DOC_B)
	sh chapters/html/make-html.sh $(DOC_B)

# The pages in headless Chromium: maths rendered, links and images resolve,
# a screenshot of chapter 06 in $(DOC_B)/screenshot.png (about 10 s).
doc-test: doc $(B)/figures/pngcheck
	@sh tests/deps.sh $(DEB_DOCTEST)
	sh tests/doc-browser.sh $(DOC_B) $(B)/figures/pngcheck

# The snapshots of the book rerun (tests/doc-snapshots.sh): every table and
# log excerpt marked <!-- snapshot[...]: COMMAND ... --> against what
# COMMAND prints now, machine-bound values (times) excepted.  make test
# runs the cheap ones (tests/cases-doc-snapshots.sh, or TIER=cheap here);
# this target adds those of minutes (about 20 minutes on 2 cores alone);
# TIER=bench the benchmark records too (hours); UPDATE=1 rewrites each
# snapshot that differs from what its command prints.
doc-snapshots: all $(UNIT) $(NUMCMP) $(FIGPROG)
	@B=$(B) sh tests/doc-snapshots.sh --tier $(or $(TIER),long) $(if $(UPDATE),--update)

# ---- exercises with code (chapters/README.md, "Exercises with code") -----
# make exercise NAME=x [FROM=FILE]: exercises/x/main.c, a copy of FROM (a
# chapter's skeleton; chapters/exercise.c by default), kept if it exists,
# then built as $(B)/exercises/x against the library.  exercises/ is the
# reader's own (.gitignore); make doc and make test do not look into it.
EXERCISE_FROM = $(or $(FROM),chapters/exercise.c)
exercise: all
	@case "$(NAME)" in ''|*/*|*' '*) echo "usage: make exercise NAME=word [FROM=chapters/NN-name/skeleton.c]" >&2; exit 2 ;; esac
	@mkdir -p exercises/$(NAME)
	@if [ -f exercises/$(NAME)/main.c ]; then echo "exercises/$(NAME)/main.c: kept (it exists)"; \
	 else cp $(EXERCISE_FROM) exercises/$(NAME)/main.c && echo "exercises/$(NAME)/main.c: a copy of $(EXERCISE_FROM)"; fi
	@$(MAKE) --no-print-directory $(B)/exercises/$(NAME)
	@echo "run it from here: $(B)/exercises/$(NAME)"
$(B)/exercises/%: exercises/%/main.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@

# ---- fuzzing (chapter 01, bad-input.md; fuzz/README.md) --------------------
# The library again with clang, coverage for libFuzzer and the sanitizers
# (in build/fuzz), the harnesses fuzz/fuzz_*.c linked with libFuzzer, seed
# corpora from the scenes and meshes of the project, then FUZZ_SECONDS of
# fuzzing per harness (FUZZ_HARNESSES: a subset).  Crashes go to
# build/fuzz/crashes/; the status is 1 if there is any.
FUZZ_SECONDS   ?= 60
FUZZ_HARNESSES ?= scene mesh gmsh numbers
FUZZ_B   := build/fuzz
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
FUZZ_PROG := $(patsubst fuzz/%.c,$(FUZZ_B)/bin/%,$(wildcard fuzz/fuzz_*.c))
fuzz: all $(B)/tools/make_seeds
	$(MAKE) B=$(FUZZ_B) CC=clang PETSC=$(PETSC) \
	  CFLAGS="-std=c11 -O1 -g -Wall -Wextra -fsanitize=fuzzer-no-link $(FUZZ_SAN)" \
	  $(FUZZ_PROG)
	ASAN_OPTIONS=alloc_dealloc_mismatch=0:detect_leaks=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	sh fuzz/run.sh $(FUZZ_B) $(FUZZ_SECONDS) $(B) $(FUZZ_HARNESSES)
$(FUZZ_B)/bin/%: fuzz/%.c fuzz/fuzz_check.h $(LIB)
	@mkdir -p $(@D)
	clang $(CPPFLAGS) -Ifuzz -std=c11 -O1 -g -fsanitize=fuzzer $(FUZZ_SAN) \
	  $< $(LIB) $(LDLIBS) -o $@
$(B)/tools/make_seeds: fuzz/make_seeds.c $(LIB)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) $< $(LIB) $(LDLIBS) -o $@

help:
	@sed -n '3,19p' Makefile

.PHONY: all deps install uninstall test test-asan test-nomem demo bench bench-ring bench-ring-fine figures fuzz clean help doc doc-test doc-snapshots exercise
.DELETE_ON_ERROR:
