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
  (cd "$DOC_TMP/run" && sh -c "$cmd")
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
  /^<!-- output: .* -->$/ { c = $0; sub (/^<!-- output: /, "", c); sub (/ -->$/, "", c)
                            cmd = c; at = FILENAME ":" FNR; next }
  /^```/ { if (inb) { if (cmd != "") print "@@end"; inb = 0; cmd = ""; next }
           inb = 1; if (cmd != "") print "@@cmd\t" at "\t" cmd; first = 1; next }
  inb && cmd != "" { if (first && /^\$ /) { first = 0; next } first = 0; print }
  !inb && cmd != "" && !/^$/ { print "@@cmd\t" at "\t" cmd; print "@@end"; cmd = "" }' \
  $DOC_MD > "$DOC_TMP/output-blocks"
n=0; : > "$DOC_TMP/exp"
while IFS= read -r line; do
  case $line in
    "@@cmd	"*)
      at=$(printf '%s' "$line" | cut -f2); cmd=$(printf '%s' "$line" | cut -f3-)
      : > "$DOC_TMP/exp" ;;
    "@@end")
      n=$((n+1))
      doc_run "$cmd" > "$DOC_TMP/act" 2>&1; st=$?
      if [ "$st" -gt 1 ]; then
        doc_fail "doc-output $at" "$cmd: exit status $st
$(tail -5 "$DOC_TMP/act")"
      elif [ ! -s "$DOC_TMP/exp" ]; then
        doc_fail "doc-output $at" "the marker is not followed by a fenced block"
      elif d=$("$DOC_NUMCMP" --rtol 1e-6 --atol 1e-9 "$DOC_TMP/exp" "$DOC_TMP/act" 2>&1); then
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
