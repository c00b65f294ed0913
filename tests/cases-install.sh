# tests/cases-install.sh -- lac installed like a library (sourced by
# tests/run.sh; same conventions as tests/cases.sh: $B, pass, fail)
#
# make install into a fresh prefix $P under $B (with the make variables of
# this run: under make test-asan, a library built with the sanitizers,
# whose lac.pc then asks for their run-time), then, against $P alone
# (PKG_CONFIG_PATH, nothing of src/):
#   install-files      bin/lac, liblac.a, liblac.so.N with its soname and
#                      links, include/lac/lac.h and every header in its
#                      folder, lib/pkgconfig/lac.pc, share/man/man1/lac.1,
#                      the chapters' programs and scenes; lac --version;
#                      nothing compiled again;
#   install-headers    every installed header compiles alone, lac.h also
#                      with -std=c11 -pedantic -Werror; lac.h includes the
#                      API that README.md lists, no more, no less;
#   install-ex01       the line of chapter 01's head comment,
#                      cc example.c $(pkg-config --cflags --libs lac), on
#                      the installed example.c; run with LD_LIBRARY_PATH, it
#                      prints what build/chapters/01-problem prints;
#   install-ex08       chapter 08's program (contact, the Taylor patch
#                      tests) the same way, on the installed scenes;
#   install-static     chapter 01's program with liblac.a (pkg-config
#                      --static): no liblac.so needed, the same output;
#   install-man        man -l lac.1 renders without a warning, with every
#                      word of lac --help, in order;
#   install-uninstall  make uninstall: nothing left under $P but the
#                      directories that were there before;
#   install-destdir    DESTDIR=D: everything under D, lac.pc's prefix
#                      without D; uninstall empties it again.
# About 15 s.

B=${B:-build}
I="$B/cases-install"
rm -rf "$I"
mkdir -p "$I/cc"
P="$(pwd)/$I/prefix"                 # absolute: the paths of lac.pc
mkdir -p "$P/share/man/man1"          # there before: uninstall keeps it

ins_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
ins_fail () { fail=$((fail+1)); echo "FAIL case $1"; printf '%s\n' "$2" | head -20 | sed 's/^/     /'; }

# make TARGET [VAR=VALUE...] with this run's variables (make test passes
# them in MAKEFLAGS; B for a run by hand), without the jobs of make test
# (whose job server this shell does not have: nothing is built anyway)
# and without ldconfig of the machine
ins_make () {
  MAKEFLAGS=$(printf ' %s' "${MAKEFLAGS:-}" | sed 's/ --jobserver-[a-z]*=[^ ]*//g; s/ -j[0-9]*//g') \
    ${MAKE:-make} -s --no-print-directory B="$B" LDCONFIG= "$@" > "$I/make.out" 2>&1
}

# the words of a text, one a line, lower case ("usage" aside: the man
# page's SYNOPSIS stands for it)
ins_words () {
  LC_ALL=C tr -c 'A-Za-z0-9_\n' ' ' | LC_ALL=C tr 'A-Z' 'a-z' | tr -s ' ' '\n' |
    sed -e '/^$/d' -e '/^usage$/d'
}

: > "$I/stamp"
if ! ins_make install PREFIX="$P"; then
  ins_fail install "make install PREFIX=$P: $(tail -5 "$I/make.out")"
else
  EXD="$P/share/doc/lac/examples"
  # pkg-config and the programs against $P only (not exported: the
  # later cases files run as before)
  ins_pc () { PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config "$@"; }
  ins_run () { LD_LIBRARY_PATH="$P/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$@"; }

  # ---- install-files ------------------------------------------------------
  msg=""
  for f in bin/lac lib/liblac.a lib/liblac.so lib/liblac.so.0 \
           include/lac/lac.h include/lac/fem/lac_mesh.h \
           include/lac/contact/lac_contact.h lib/pkgconfig/lac.pc \
           share/man/man1/lac.1 $(cd chapters && ls [0-9][0-9]-*/example.c \
           [0-9][0-9]-*/*.scene [0-9][0-9]-*/*.geo | sed 's|^|share/doc/lac/examples/|'); do
    [ -e "$P/$f" ] || msg="$msg $f is missing;"
  done
  for h in $(cd src && ls */lac_*.h); do
    case $h in cli/*|*_internal.h) [ -e "$P/include/lac/$h" ] && msg="$msg $h is installed;" ;;
               *) [ -e "$P/include/lac/$h" ] || msg="$msg $h is missing;" ;; esac
  done
  so=$(readelf -d "$P/lib/liblac.so" 2>&1 | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
  [ "$so" = liblac.so.0 ] || msg="$msg the soname of lib/liblac.so is '$so', not liblac.so.0;"
  [ -L "$P/lib/liblac.so" ] && [ -L "$P/lib/liblac.so.0" ] ||
    msg="$msg liblac.so and liblac.so.0 are not links;"
  # the build of this run, installed as it is
  o=$(find "$B/src" -name '*.o' -newer "$I/stamp" | head -3)
  [ -z "$o" ] || msg="$msg make install compiled again: $o;"
  v=$("$P/bin/lac" --version 2>&1)
  [ "$v" = "$("$B/lac" --version 2>&1)" ] || msg="$msg bin/lac --version says '$v';"
  if [ -z "$msg" ]; then ins_ok install-files; else ins_fail install-files "$msg"; fi

  # ---- install-headers ----------------------------------------------------
  msg=""
  cflags=$(ins_pc --cflags lac 2>&1) || msg="pkg-config --cflags lac: $cflags"
  for h in $(cd "$P/include/lac" && find . -name '*.h' | sed 's|^\./||' | sort); do
    printf '#include "%s"\n' "$h" > "$I/cc/h.c"
    out=$(cc $cflags -Wall -Wextra -Werror -fsyntax-only "$I/cc/h.c" 2>&1) ||
      msg="$msg
$h alone: $(printf '%s\n' "$out" | head -3)"
  done
  out=$(cc $cflags -std=c11 -pedantic -Wall -Wextra -Werror -fsyntax-only \
        -x c "$P/include/lac/lac.h" 2>&1) ||
    msg="$msg
lac.h under -std=c11 -pedantic: $(printf '%s\n' "$out" | head -3)"
  sed -n 's/^#include "\([a-z]*\/lac_[a-z0-9_]*\.h\)".*/\1/p' src/lac.h | sort > "$I/api-lac.h"
  awk '/^## Using lac as a library/ { on = 1; next } /^## / { on = 0 } on' README.md |
    grep -o '`[a-z]*/lac_[a-z0-9_]*\.h`' | tr -d '`' | sort -u > "$I/api-readme"
  [ -s "$I/api-readme" ] || msg="$msg
README.md lists no API header (section \"Using lac as a library\")"
  d=$(diff "$I/api-readme" "$I/api-lac.h") || msg="$msg
the API of README.md (<) and the includes of src/lac.h (>):
$d"
  if [ -z "$msg" ]; then ins_ok install-headers; else ins_fail install-headers "$msg"; fi

  # ---- install-ex01, install-ex08, install-static -------------------------
  # the compile line of chapter 01's head comment, run on the installed copy
  line=$(sed -n '1,/\*\//p' chapters/01-problem/example.c | grep -o 'cc example\.c .*lac)')
  mkdir -p "$I/cc/ex01" "$I/cc/ex08"
  cp "$EXD/01-problem/example.c" "$I/cc/ex01/"
  if [ "$line" != 'cc example.c $(pkg-config --cflags --libs lac)' ]; then
    ins_fail install-ex01 "the head comment of chapters/01-problem/example.c has '$line'"
  elif ! out=$(cd "$I/cc/ex01" && PKG_CONFIG_PATH="$P/lib/pkgconfig" sh -c "$line" 2>&1); then
    ins_fail install-ex01 "$line: $out"
  elif ! ins_run "$I/cc/ex01/a.out" > "$I/ex01.out" 2> "$I/ex01.err"; then
    ins_fail install-ex01 "the program failed: $(head -3 "$I/ex01.err")"
  elif ! "$B/chapters/01-problem" > "$I/ex01.ref" 2> "$I/ex01.err" ||
       ! d=$(diff "$I/ex01.ref" "$I/ex01.out"); then
    ins_fail install-ex01 "output (>) unlike $B/chapters/01-problem's (<): $d"
  else ins_ok install-ex01; fi

  if ! out=$(cc "$EXD/08-experiments/example.c" $(ins_pc --cflags --libs lac) \
               -o "$I/cc/ex08/prog" 2>&1); then
    ins_fail install-ex08 "cc: $out"
  elif ! ins_run "$I/cc/ex08/prog" "$EXD/08-experiments" > "$I/ex08.out" 2> "$I/ex08.err"; then
    ins_fail install-ex08 "the program failed: $(head -3 "$I/ex08.err")"
  elif ! "$B/chapters/08-experiments" > "$I/ex08.ref" 2> "$I/ex08.err" ||
       ! d=$(diff "$I/ex08.ref" "$I/ex08.out"); then
    ins_fail install-ex08 "output (>) unlike $B/chapters/08-experiments' (<): $d"
  else ins_ok install-ex08; fi

  # liblac.a by name (-l:): -llac would take liblac.so
  libs=$(ins_pc --static --libs lac | sed 's/-llac /-l:liblac.a /')
  if ! out=$(cc "$EXD/01-problem/example.c" $(ins_pc --cflags lac) $libs \
               -o "$I/cc/ex01/static" 2>&1); then
    ins_fail install-static "cc ... $libs: $out"
  elif readelf -d "$I/cc/ex01/static" | grep -q 'liblac\.so'; then
    ins_fail install-static "the program linked with liblac.a needs liblac.so"
  elif ! "$I/cc/ex01/static" > "$I/static.out" 2> "$I/static.err" ||
       ! d=$(diff "$I/ex01.ref" "$I/static.out"); then
    ins_fail install-static "output (>) unlike $B/chapters/01-problem's (<): $d"
  else ins_ok install-static; fi

  # ---- install-man ----------------------------------------------------------
  if ! command -v man > /dev/null; then
    ins_fail install-man "no man command (the Debian package man-db: make deps)"
  elif ! LC_ALL=C MANWIDTH=80 man --warnings -l "$P/share/man/man1/lac.1" \
         > "$I/man.txt" 2> "$I/man.err" || [ -s "$I/man.err" ]; then
    ins_fail install-man "man -l lac.1: $(head -5 "$I/man.err")"
  else
    ins_words < "$I/man.txt" > "$I/man.words"
    "$B/lac" --help 2>&1 | ins_words > "$I/help.words"
    msg=$(awk 'NR == FNR { m[++nm] = $0; next }
      { while (++j <= nm && m[j] != $0) ; }
      j > nm { print "word " FNR " of lac --help, " $0 ", is not in the page in its place"; exit }' \
      "$I/man.words" "$I/help.words")
    grep -q '^LAC(1) ' "$I/man.txt" || msg="$msg no LAC(1) header"
    if [ -z "$msg" ]; then ins_ok install-man; else ins_fail install-man "$msg"; fi
  fi

  # ---- install-uninstall ----------------------------------------------------
  if ! ins_make uninstall PREFIX="$P"; then
    ins_fail install-uninstall "make uninstall: $(tail -5 "$I/make.out")"
  else
    left=$(cd "$P" && find . | sort | tr '\n' ' ')
    if [ "$left" = ". ./share ./share/man ./share/man/man1 " ]; then ins_ok install-uninstall
    else ins_fail install-uninstall "left under $P: $left"; fi
  fi

  # ---- install-destdir ------------------------------------------------------
  S="$(pwd)/$I/stage"
  mkdir -p "$S"
  if ! ins_make install DESTDIR="$S" PREFIX=/opt/lac; then
    ins_fail install-destdir "make install DESTDIR=$S: $(tail -5 "$I/make.out")"
  else
    msg=""
    [ -f "$S/opt/lac/lib/liblac.a" ] || msg="$msg no $S/opt/lac/lib/liblac.a;"
    grep -q '^prefix=/opt/lac$' "$S/opt/lac/lib/pkgconfig/lac.pc" ||
      msg="$msg lac.pc: $(grep '^prefix' "$S/opt/lac/lib/pkgconfig/lac.pc");"
    ins_make uninstall DESTDIR="$S" PREFIX=/opt/lac || msg="$msg make uninstall: $(tail -3 "$I/make.out");"
    left=$(cd "$S" && find . -mindepth 1 | head -5)
    [ -z "$left" ] || msg="$msg left under $S: $left"
    if [ -z "$msg" ]; then ins_ok install-destdir; else ins_fail install-destdir "$msg"; fi
  fi
fi
