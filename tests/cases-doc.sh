# tests/cases-doc.sh -- the book against the code (sourced by tests/run.sh)
#
# The chapters (chapters/, README.md) show commands, outputs, files,
# functions and scene keys; these cases fail as soon as one of them no
# longer matches the code:
#   doc-paths     no file of the repository points out of it (a path to a
#                 folder beside the clone, notes that are not in it);
#   doc-output    every fenced block marked by an HTML comment
#                     <!-- output: COMMAND -->
#                 on the line before it is what COMMAND prints (stdout and
#                 stderr), number by number within rtol 1e-6 (tests/numcmp;
#                 integers and words exactly); COMMAND is an example program
#                 build/chapters/NN-name [ARGS] or a lac command;
#   doc-commands  every lac command of a fenced block (a line that starts
#                 with `lac`, `build/lac`, `$ lac` or `(ulimit ...; lac`),
#                 and every run of an example (`build/chapters/NN-name ...`;
#                 synopsis lines with SCENE, DIR, [...] are not commands)
#                 runs and exits with 0, or with 1 where the block shows
#                 its 'lac: ...' error; a block after
#                     <!-- short: ARGS -->
#                 runs its commands with ARGS added (a later --set wins: a
#                 smaller mesh for a run of minutes);
#   doc-names     every file a chapter names in backquotes (src/..., tests/...,
#                 chapters/..., bench/..., figures/..., or a file of the
#                 chapter's own folder) exists, and every name of the
#                 "function" column of a chapter's "function | file" table
#                 is a word of one of the files of its "file" column;
#   doc-tables    every table of numbers is checked (output), a snapshot
#                 whose checksum still holds and that names the command
#                 that prints it (make doc-snapshots reruns it:
#                 tests/doc-snapshots.sh), or quoted (tests/doc-tables.awk);
#   doc-functions every lac_xxx name in backquotes exists in a source file;
#   doc-values    a constant of the text followed by <!-- value V: COMMAND -->
#                 is what COMMAND prints;
#   doc-headers   the head comment of each chapter's example.c builds and
#                 runs build/chapters/NN-name of its own folder;
#   doc-keys      the keys of each section in the table of
#                 chapters/01-problem/scene-format.md, and in the section
#                 list of `lac --help`, are exactly those of the key tables
#                 of src/io/lac_scene_keys.c (printed by tests/scene_keys.c).
# The commands run in $B/cases-doc/run, where chapters/ and tests/ are
# links to the repository's, so that their output files stay in $B.

B=${B:-build}
DOC_TMP="$B/cases-doc"
DOC_ROOT=$(pwd)
DOC_LAC="$DOC_ROOT/$B/lac"
DOC_NUMCMP="$DOC_ROOT/$B/tests/numcmp"
DOC_MD="README.md chapters/README.md $(ls chapters/*/*.md)"
rm -rf "$DOC_TMP"
mkdir -p "$DOC_TMP/run/tmp" "$DOC_TMP/out"
ln -s "$DOC_ROOT/chapters" "$DOC_TMP/run/chapters"
ln -s "$DOC_ROOT/tests" "$DOC_TMP/run/tests"
ln -s "$DOC_ROOT/$B" "$DOC_TMP/run/build"      # the scripts' default build-dir

doc_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
doc_fail () { fail=$((fail+1)); echo "FAIL case $1"; printf '%s\n' "$2" | head -40 | sed 's/^/     /'; }

# A command of the book, run in $DOC_TMP/run: build/lac and lac become
# this build's lac, build/chapters/X this build's example, /tmp/ a folder
# of $DOC_TMP.
doc_run () {
  # /tmp/ first: the paths put in next may themselves lie under /tmp
  cmd=$(printf '%s\n' "$1" | sed -e "s# /tmp/# $DOC_ROOT/$DOC_TMP/run/tmp/#g" \
    -e "s#^\([ (;]*\)\(build/\)\{0,1\}lac #\1$DOC_LAC #" \
    -e "s#\([ (;]\)\(build/\)\{0,1\}lac #\1$DOC_LAC #g" \
    -e "s#^build/chapters/#$DOC_ROOT/$B/chapters/#")
  # a command that may start MPI (petsc, mpirun, or auto under a
  # --max-memory that takes petsc) unwinds in full under make test-asan,
  # as in cases-petsc.sh: else the leak checker cannot see that the
  # start-up data it reports are Open MPI's (tests/lsan.supp)
  case $1 in
    *petsc*|*mpirun*|*--max-memory*) da="${ASAN_OPTIONS:-}${LAC_MPI_ASAN:-}" ;;
    *) da="${ASAN_OPTIONS:-}" ;;
  esac
  (cd "$DOC_TMP/run" && ASAN_OPTIONS="$da" sh -c "$cmd")
}

# ---- doc-paths -------------------------------------------------------------
# The patterns are split so that this file does not match them itself.
p1='\.\./sha''red'; p2='sha''red/'; p3='NOT''ES\.md'; p4='reading no''tes'
p5='paper-tab''les'; p6='des''ign\.md'; p7='/wo''rk/'
msg=$(git ls-files | grep -v '^tests/bad/' | while read -r f; do
  [ -f "$f" ] && grep -n -I -E "$p1|$p2|$p3|$p4|$p5|$p6|$p7" "$f" /dev/null
done)
if [ -z "$msg" ]; then doc_ok doc-paths
else doc_fail doc-paths "paths out of the repository:
$msg"; fi

# ---- doc-output ------------------------------------------------------------
# "FILE:LINE<TAB>COMMAND" then the block, then a line "@@end"
awk 'FNR == 1 { cmd = ""; inb = 0 }
  /^<!-- output(\[[^]]*\])?: .* -->$/ {
    c = $0; t = ""; if (match (c, /^<!-- output\[[^]]*\]/)) t = substr (c, 13, RLENGTH - 13)
    sub (/^<!-- output(\[[^]]*\])?: /, "", c); sub (/ -->$/, "", c)
    cmd = c; tol = t; at = FILENAME ":" FNR; next }
  /^```/ { if (inb) { if (cmd != "") print "@@end"; inb = 0; cmd = ""; next }
           inb = 1; if (cmd != "") print "@@cmd\t" at "\t" tol "\t" cmd; first = 1; next }
  inb && cmd != "" { if (first && /^\$ /) { first = 0; next } first = 0; print }
  !inb && cmd != "" && !/^$/ { print "@@cmd\t" at "\t" tol "\t" cmd; print "@@end"; cmd = "" }' \
  $DOC_MD > "$DOC_TMP/output-blocks"
n=0; : > "$DOC_TMP/exp"
while IFS= read -r line; do
  case $line in
    "@@cmd	"*)
      at=$(printf '%s' "$line" | cut -f2); cmd=$(printf '%s' "$line" | cut -f4-)
      # <!-- output[atol=A,rtol=R]: ... -->: these tolerances, else 1e-6, 1e-9
      tol=$(printf '%s' "$line" | cut -f3)
      rt=$(printf '%s' "$tol" | sed -n 's/.*rtol=\([^,]*\).*/\1/p'); rt=${rt:-1e-6}
      az=$(printf '%s' "$tol" | sed -n 's/.*atol=\([^,]*\).*/\1/p'); az=${az:-1e-9}
      : > "$DOC_TMP/exp" ;;
    "@@end")
      n=$((n+1))
      doc_run "$cmd" > "$DOC_TMP/act" 2>&1; st=$?
      if [ "$st" -gt 1 ]; then
        doc_fail "doc-output $at" "$cmd: exit status $st
$(tail -5 "$DOC_TMP/act")"
      elif [ ! -s "$DOC_TMP/exp" ]; then
        doc_fail "doc-output $at" "the marker is not followed by a fenced block"
      elif d=$("$DOC_NUMCMP" --as-written --rtol "$rt" --atol "$az" "$DOC_TMP/exp" "$DOC_TMP/act" 2>&1); then
        doc_ok "doc-output $at"
      else
        doc_fail "doc-output $at" "$cmd prints what the block does not show (expected: the block):
$d"
      fi ;;
    *) printf '%s\n' "$line" >> "$DOC_TMP/exp" ;;
  esac
done < "$DOC_TMP/output-blocks"
[ "$n" -ge 8 ] || doc_fail doc-output-count "only $n marked output blocks"

# ---- doc-commands ----------------------------------------------------------
# "FILE:LINE<TAB>EXPECTED STATUS<TAB>SHORT ARGS<TAB>COMMAND"
awk 'function flush () { if (cmd != "") print at "\t" (err ? 1 : 0) "\t" (short == "" ? "-" : short) "\t" cmd; cmd = "" }
  FNR == 1 { inb = 0; short = ""; cmd = "" }
  /^<!-- short: .* -->$/ { s = $0; sub (/^<!-- short: /, "", s); sub (/ -->$/, "", s); short = s; next }
  /^```/ { if (inb) { flush(); short = "" } inb = !inb; cont = 0; next }
  !inb { next }
  cont { l = $0; cont = sub (/\\$/, "", l); cmd = cmd " " l; next }
  /^lac: / && cmd != "" && prompt { err = 1; next }
  { l = $0; prompt = sub (/^\$ /, "", l)
    if (l !~ /^(\([^;]*; *)?(build\/)?lac (run|infsup|render|--help|--version)( |$)/ \
        && l !~ /^build\/chapters\/[0-9][0-9]-[a-z0-9-]*( |$)/) next
    flush(); err = 0
    if (l ~ /SCENE|RESULT_DIR|DIR[] ]|\[|\.\.\.|…/) next
    sub (/[ \t]+#.*$/, "", l); cont = sub (/\\$/, "", l)
    at = FILENAME ":" FNR; cmd = l }' $DOC_MD > "$DOC_TMP/commands"
n=0
while IFS='	' read -r at want short cmd; do
  n=$((n+1))
  case $cmd in
    *"lac run"*|*"lac infsup"*) [ "$short" = - ] || cmd="$cmd $short" ;;
  esac
  # AddressSanitizer reserves terabytes of address space at start: under
  # make test-asan a command limited by `ulimit -v` cannot start at all
  # (make test runs it)
  case "$cmd:${ASAN_OPTIONS:-}" in
    *"ulimit -v"*:?*) continue ;;
  esac
  doc_run "$cmd" > "$DOC_TMP/act" 2>&1; st=$?
  if [ "$st" = "$want" ]; then doc_ok "doc-commands $at"
  else doc_fail "doc-commands $at" "$cmd: exit status $st, the book shows $want
$(tail -5 "$DOC_TMP/act")"; fi
done < "$DOC_TMP/commands"
[ "$n" -ge 10 ] || doc_fail doc-commands-count "only $n commands found"

# ---- doc-names -------------------------------------------------------------
# files named in backquotes
msg=""
for md in $DOC_MD; do
  dir=$(dirname "$md")
  for f in $(grep -o '`[A-Za-z0-9_./-]*\.\(c\|h\|sh\|md\|geo\|scene\|msh\|py\|supp\|csv\|png\|svg\)`' "$md" | tr -d '`' | sort -u); do
    case $f in
      src/*|tests/*|chapters/*|bench/*|figures/*|fuzz/*) [ -e "$f" ] || msg="$msg
$md: $f does not exist" ;;
      */*) ;;                       # a path of an output folder, ../..
      *) ;;
    esac
  done
done
# "function | file" tables: every function is a word of a file of its row
tab=$(awk -F'|' 'FNR == 1 { fc = 0 }
  /^\|/ { if (!fc) { for (i = 2; i < NF; i++) { h = $i; gsub (/ /, "", h)
                       if (h == "function") fc = i; if (h == "file") lc = i }
                     if (!lc) fc = 0; next }
          if ($fc ~ /^ *-+ *$/) next
          print FILENAME ":" FNR "\t" $fc "\t" $lc; next }
  { fc = 0; lc = 0 }' $DOC_MD)
nfun=0
while IFS='	' read -r at funs files; do
  [ -n "$at" ] || continue
  fl=""
  for f in $(printf '%s\n' "$files" | grep -o '`[^`]*`' | tr -d '`'); do
    case $f in
      *.\[ch\]) fl="$fl ${f%.\[ch\]}.c ${f%.\[ch\]}.h" ;;
      src/*/) fl="$fl $(ls "$f"*.[ch] | tr '\n' ' ')" ;;
      src/*) fl="$fl $f" ;;
    esac
  done
  [ -n "$fl" ] || continue
  printf '%s\n' "$funs" | grep -o '`[^`]*`' | tr -d '`' | sed 's/()$//' \
    > "$DOC_TMP/funs"
  while IFS= read -r w; do
    case $w in _*|*' '*|*'('*|*/*|'') continue ;; esac
    for part in $(printf '%s' "$w" | tr '.' ' '); do
      nfun=$((nfun+1))
      found=""
      for f in $fl; do
        [ -f "$f" ] && grep -q -w -- "$part" "$f" && found=1
      done
      [ -n "$found" ] || msg="$msg
$at: \`$part\` is in none of$fl"
    done
  done < "$DOC_TMP/funs"
done <<EOF
$tab
EOF
[ "$nfun" -ge 100 ] || msg="$msg
only $nfun names in function tables"
if [ -z "$msg" ]; then doc_ok doc-names
else doc_fail doc-names "$msg"; fi

# ---- doc-tables ------------------------------------------------------------
# Every table of numbers of the book (tests/doc-tables.awk: a pipe table or
# a plain fenced block with 3 rows of 2 numbers or more) is checked (an
# output marker, above), or a snapshot whose lines still have the checksum
# of its marker (tests/doc-snapshot.sh renews it), or quoted from outside
# lac.
awk -f tests/doc-tables.awk $DOC_MD > "$DOC_TMP/tables"
msg=$(awk -F'\t' -v tmp="$DOC_TMP/snap" '
  /^@@end$/ { if (kind == "snapshot") { close (tmp); cmd = "sha256sum < " tmp; cmd | getline s; close (cmd)
                s = substr (s, 1, 12); if (s != want) printf "%s: snapshot changed by hand (sha %s, the marker says %s): make doc-snapshots UPDATE=1 renews it from its command\n", at, s, want }
              kind = ""; next }
  /^\t/ { if (kind == "snapshot") print substr ($0, 2) > tmp; next }
  { at = $1; kind = $2
    if (kind == "none") printf "%s: a table of numbers without a marker (output, snapshot or quoted: tests/doc-tables.awk)\n", at
    if (kind == "snapshot") { want = $3; sub (/.*; sha /, "", want); sub (/ -->$/, "", want); printf "" > tmp } }' \
  "$DOC_TMP/tables")
# every snapshot names the command that prints it (tests/doc-snapshots.sh
# reruns it): after VAR=VALUE words, `sh FILE` of the repository or a
# program of the build (build/lac, build/tests/tNNN-x of tests/unit,
# build/chapters/NN-x of chapters/)
msg="$msg$(grep -n '^<!-- snapshot' $DOC_MD /dev/null | while IFS= read -r l; do
  at=${l%%:<!--*}; c=$(printf '%s' "$l" | sed 's/^[^<]*<!-- snapshot\(\[[^]]*\]\)\{0,1\}: //; s/ @ [^@]*$//')
  set -f; set -- $c; set +f
  while [ $# -gt 0 ] && case $1 in [A-Za-z_]*=*) true ;; *) false ;; esac; do shift; done
  case $1:${2:-} in
    sh:*) [ -f "${2:-}" ] ;;
    build/lac:*) true ;;
    build/tests/t*) [ -f "tests/unit/${1#build/tests/}.c" ] ;;
    build/chapters/*) [ -f "chapters/${1#build/chapters/}/example.c" ] ;;
    *) false ;;
  esac || printf '\n%s: the snapshot names no command of the repository (sh FILE, build/lac, build/tests/..., build/chapters/...): %s' "$at" "$c"
done)"
ntab=$(grep -c '^[^@	]' "$DOC_TMP/tables")
[ "$ntab" -ge 20 ] || msg="$msg
only $ntab tables of numbers found"
if [ -z "$msg" ]; then doc_ok doc-tables
else doc_fail doc-tables "$msg"; fi

# ---- doc-functions ---------------------------------------------------------
# Every name lac_xxx the book shows in backquotes (`lac_x`, `lac_x ()`,
# `lac_x()`) is a word of a source file of the repository: no function,
# type or constant that does not exist.
grep -rhoE --include='*.[ch]' --include='*.sh' --include='*.lua' '\blac_[A-Za-z0-9_]+' \
  src tests chapters figures bench fuzz | sort -u > "$DOC_TMP/idents"
# (a name an exercise proposes to write, "for instance `lac_x`", is not)
for md in $DOC_MD; do
  grep -v 'for instance `lac_' "$md" | grep -oE '`lac_[A-Za-z0-9_]+( ?\(\))?`' |
    sed "s|^|$md:|; s/\`//g; s/ *()\$//"
done | sort -u > "$DOC_TMP/named"
msg=$(awk -F: 'NR == FNR { id[$0] = 1; next } !($2 in id) { print $1 ": `" $2 "` is in no source file" }' \
  "$DOC_TMP/idents" "$DOC_TMP/named")
# the functions an <!-- include: FILE FUNCTION --> marker shows (make doc
# reads them from the source) are defined in FILE
msg="$msg$(grep -n '^<!-- include: ' $DOC_MD /dev/null | while IFS= read -r l; do
  f=$(printf '%s' "$l" | sed 's/.*include: \([^ ]*\) .*/\1/'); fn=$(printf '%s' "$l" | sed 's/.*include: [^ ]* \([^ ]*\) -->$/\1/')
  grep -q "^$fn (" "$f" 2>/dev/null || printf '\n%s: %s is not defined in %s' "${l%%:<!--*}" "$fn" "$f"
done)"
nnamed=$(wc -l < "$DOC_TMP/named")
[ "$nnamed" -ge 100 ] || msg="$msg
only $nnamed names lac_xxx found in the book"
if [ -z "$msg" ]; then doc_ok doc-functions
else doc_fail doc-functions "$msg"; fi

# ---- doc-values ------------------------------------------------------------
# A constant stated in the text, followed by a marker
#     <!-- value V: COMMAND -->
# is what COMMAND prints (V and the output equal as words, or as numbers
# within 1e-6, a fraction N/M read as a number), and V is written in the
# paragraph just above the marker: the sentence and the code cannot part.
awk 'FNR == 1 { para = "" }
  /^[ \t]*<!-- value [^:]*: .* -->$/ { v = $0; sub (/^[ \t]*<!-- value /, "", v); c = v; sub (/:.*/, "", v)
    sub (/^[^:]*: /, "", c); sub (/ -->$/, "", c)
    printf "%s:%d\t%s\t%s\t%s\n", FILENAME, FNR, v, (index (para, v) ? "in" : "out"), c; next }
  /^[ \t]*$/ { para = ""; next }
  { para = para " " $0 }' $DOC_MD > "$DOC_TMP/values"
msg=""; nval=0
while IFS='	' read -r at v where cmd; do
  nval=$((nval+1))
  [ "$where" = in ] || { msg="$msg
$at: $v is not in the paragraph above the marker"; continue; }
  got=$(doc_run "$cmd" 2>&1 | tr -d '\n' | sed 's/^ *//; s/ *$//')
  if ! awk -v a="$v" -v b="$got" 'function num (x,  p) { if (x ~ /^-?[0-9]+\/[0-9]+$/) { split (x, p, "/"); return p[1] / p[2] } return x + 0 }
         BEGIN { if (a == b) exit 0; x = num(a); y = num(b); exit !(b != "" && (x - y) ^ 2 <= 1e-12 * (1 + x * x)) }'; then
    msg="$msg
$at: the text says $v, \`$cmd\` prints '$got'"
  fi
done < "$DOC_TMP/values"
[ "$nval" -ge 3 ] || msg="$msg
only $nval value markers"
if [ -z "$msg" ]; then doc_ok doc-values
else doc_fail doc-values "$msg"; fi

# ---- doc-headers -----------------------------------------------------------
# The head comment of each chapter's program names the commands that build
# and run it: build/chapters/NN-name of its own folder (or build/lac), no
# other program or build folder.
msg=$(for f in chapters/[0-9][0-9]-*/example.c; do
  d=$(basename "$(dirname "$f")")
  sed -n '1,/\*\//p' "$f" | grep -o 'build/[A-Za-z0-9_/.-]*' |
    grep -v -x -e "build/chapters/$d" -e build/lac | sed "s|^|$f: names |"
done)
if [ -z "$msg" ]; then doc_ok doc-headers
else doc_fail doc-headers "$msg"; fi

# ---- doc-keys --------------------------------------------------------------
"$B/tests/scene_keys" | sort > "$DOC_TMP/keys-code"
# scene-format.md: rows `key` `key` | ... under | **`[section ...]`** |
awk -F'|' '/^\| \*\*`\[/ { s = $2; sub (/^ *\*\*`\[/, "", s); sub (/[] ].*/, "", s); next }
  /^## / { s = "" }
  s != "" && /^\| `/ { n = split ($2, w, "`"); for (i = 2; i <= n; i += 2) print s, w[i] }' \
  chapters/01-problem/scene-format.md | sort -u > "$DOC_TMP/keys-md"
# lac --help: the section list, every word of a section's lines that is a
# key of that section, and every "word =" that is not
"$B/lac" --help > "$DOC_TMP/help" 2>&1
awk 'NR == FNR { key[$1 " " $2] = 1; next }
  /^scene sections and keys/ { on = 1; next }
  on && /^$/ { on = 0 }
  !on { next }
  /^  \[/ { s = $0; sub (/^  \[/, "", s); sub (/[] ].*/, "", s); sub (/^[^]]*\] */, "") }
  { t = $0; gsub (/[^A-Za-z0-9_=]/, " ", t); n = split (t, w, " ")
    for (i = 1; i <= n; i++) if ((s " " w[i]) in key) print s, w[i]
    t = $0; while (match (t, /[A-Za-z_][A-Za-z0-9_]* =/)) {
      k = substr (t, RSTART, RLENGTH - 2); t = substr (t, RSTART + RLENGTH)
      if (!((s " " k) in key)) print s, k, "(not a key)" } }' \
  "$DOC_TMP/keys-code" "$DOC_TMP/help" | sort -u > "$DOC_TMP/keys-help"
for w in md help; do
  if d=$(diff "$DOC_TMP/keys-code" "$DOC_TMP/keys-$w"); then doc_ok "doc-keys-$w"
  else doc_fail "doc-keys-$w" "keys of the program (<) and of $w (>):
$d"; fi
done
