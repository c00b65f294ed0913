# tests/cases-layout.sh -- the shape of src/ (sourced by tests/run.sh)
#
# src/ is cut into folders by layer, in the order data flows (src/README.md):
#
#   base < linalg < fem < contact < solve < io < render < run < cli
#
# Checked here, on the sources and on the compiled objects of $B:
#   layout-readme     every folder of src/ has a README.md, and no source
#                     lies outside the folders (but src/lac.h, the
#                     umbrella header of the installed library);
#   layout-includes   a file includes only headers of its own folder or of
#                     a lower layer, always written "folder/lac_x.h";
#   layout-calls      an object file calls only functions defined in its
#                     own folder or a lower one (nm: what it needs, U, is
#                     found among what the others define, T/D/B/R);
#   layout-circles    no circle between files: with A -> B when A includes
#                     B's header or calls a function that B defines, no file
#                     reaches itself again (a file and its header are one);
#   layout-functions  the median length of the functions of src/ stays at
#                     20 lines or less (GNU style: the body between a "{"
#                     and a "}" in column 0);
#   layout-modules    chapters/README.md's module table lists every public
#                     header of src/, in its folder, and nothing else.
# POSIX sh and awk; runs in about a second.

B=${B:-build}
LAYOUT_TMP="$B/cases-layout"
rm -rf "$LAYOUT_TMP"
mkdir -p "$LAYOUT_TMP"
LAYERS="base linalg fem contact solve io render run cli"

lay_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
lay_fail () { fail=$((fail+1)); echo "FAIL case $1"; printf '%s\n' "$2" | head -60 | sed 's/^/     /'; }

# rank of each folder, as "folder rank" lines
i=0; for l in $LAYERS; do echo "$l $i"; i=$((i+1)); done > "$LAYOUT_TMP/ranks"

# ---- layout-readme -------------------------------------------------------
msg=""
for l in $LAYERS; do
  [ -f "src/$l/README.md" ] || msg="$msg src/$l/README.md is missing;"
done
for f in src/*.c src/*.h; do
  [ "$f" = src/lac.h ] && continue
  [ -e "$f" ] && msg="$msg $f is outside the layer folders;"
done
for d in src/*/; do
  d=${d%/}; d=${d#src/}
  grep -q "^$d " "$LAYOUT_TMP/ranks" || msg="$msg src/$d is not a layer of tests/cases-layout.sh;"
done
if [ -z "$msg" ]; then lay_ok layout-readme; else lay_fail layout-readme "$msg"; fi

# ---- layout-includes -----------------------------------------------------
# "file include" lines for every quoted include of src/
for f in src/*/*.c src/*/*.h; do
  sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f" | sed "s#^#$f #"
done > "$LAYOUT_TMP/includes"
msg=$(awk 'NR == FNR { rank[$1] = $2; next }
  {
    split ($1, a, "/"); from = a[2]
    n = split ($2, b, "/")
    if (n != 2) { print $1 ": #include \"" $2 "\" does not name its folder"; next }
    if (!(b[1] in rank)) { print $1 ": #include \"" $2 "\": no such layer"; next }
    if (rank[b[1]] > rank[from])
      print $1 ": #include \"" $2 "\" goes up (" from " is below " b[1] ")"
  }' "$LAYOUT_TMP/ranks" "$LAYOUT_TMP/includes")
for h in $(awk '{ print $2 }' "$LAYOUT_TMP/includes" | sort -u); do
  [ -f "src/$h" ] || msg="$msg
#include \"$h\": no such file in src/"
done
if [ -z "$msg" ]; then lay_ok layout-includes; else lay_fail layout-includes "$msg"; fi

# ---- layout-calls and layout-circles -------------------------------------
# "object kind symbol" for every object of the library and the command line
objs=$(ls "$B"/src/*/*.o 2>/dev/null)
if [ -z "$objs" ]; then
  lay_fail layout-calls "no objects under $B/src (build first)"
else
  for o in $objs; do
    s=${o#"$B"/}; [ -f "${s%.o}.c" ] || continue   # an object left by a moved source
    nm "$o" | awk -v o="$o" 'NF == 3 && $2 ~ /^[TDBRC]$/ { print o, "D", $3 }
                             NF == 2 && $1 == "U" { print o, "U", $2 }'
  done > "$LAYOUT_TMP/symbols"
  # file -> file edges by calls (objects named as their sources)
  awk -v B="$B/" '
    { f = $1; sub ("^" B, "", f); sub (/\.o$/, "", f) }
    $2 == "D" { def[$3] = f; next }
    { need[f, ++nn[f]] = $3; files[f] = 1 }
    END { for (f in files) for (k = 1; k <= nn[f]; k++)
            if ((need[f, k]) in def && def[need[f, k]] != f)
              print f, def[need[f, k]], need[f, k] }' "$LAYOUT_TMP/symbols" \
    | sort -u > "$LAYOUT_TMP/calls"
  msg=$(awk 'NR == FNR { rank[$1] = $2; next }
    { split ($1, a, "/"); split ($2, b, "/")
      if (rank[b[2]] > rank[a[2]])
        print $1 ".c calls " $3 " of " $2 ".c (" a[2] " is below " b[2] ")" }' \
    "$LAYOUT_TMP/ranks" "$LAYOUT_TMP/calls")
  if [ -z "$msg" ]; then lay_ok layout-calls; else lay_fail layout-calls "$msg"; fi

  # units: src/x/lac_y.c and its header src/x/lac_y.h are one node
  # "src/x/lac_y"; edges leave the .c files only (a header is the face of
  # its .c: what a header includes for its types is not a dependency of
  # code)
  { awk '{ print $1, $2, "calls", $3 }' "$LAYOUT_TMP/calls"
    awk '$1 ~ /\.c$/ { a = $1; sub (/\.c$/, "", a); b = "src/" $2; sub (/\.h$/, "", b)
           if (a != b) print a, b, "includes", $2 }' "$LAYOUT_TMP/includes"
  } | sort -u -k1,2 > "$LAYOUT_TMP/edges"
  # transitive closure (Floyd-Warshall on a hundred units), then each
  # circle: the units that reach each other, and the edges between them
  msg=$(awk '
    { id[$1]; id[$2]; e[$1, $2] = 1; why[$1, $2] = $3 " " $4 }
    END {
      n = 0; for (v in id) name[++n] = v
      for (i = 1; i <= n; i++) for (j = 1; j <= n; j++) r[i, j] = e[name[i], name[j]]
      for (k = 1; k <= n; k++) for (i = 1; i <= n; i++)
        if (r[i, k]) for (j = 1; j <= n; j++)
          if (r[k, j]) r[i, j] = 1
      for (i = 1; i <= n; i++) if (r[i, i] && !done[i]) {
        line = "circle:"; m = 0
        for (j = 1; j <= n; j++)
          if (r[i, j] && r[j, i]) { line = line " " name[j]; done[j] = 1; memb[++m] = j }
        print line
        for (a = 1; a <= m; a++) for (b = 1; b <= m; b++)
          if (e[name[memb[a]], name[memb[b]]])
            print "  " name[memb[a]] " -> " name[memb[b]] ": " why[name[memb[a]], name[memb[b]]] } }' "$LAYOUT_TMP/edges")
  if [ -z "$msg" ]; then lay_ok layout-circles; else lay_fail layout-circles "$msg"; fi
fi

# ---- layout-functions ----------------------------------------------------
med=$(awk '
  /^\{/ { start = FNR; next }
  /^\}/ && start { len[++n] = FNR - start - 1; start = 0 }
  END {
    for (i = 2; i <= n; i++) { v = len[i]; j = i - 1
      while (j > 0 && len[j] > v) { len[j + 1] = len[j]; j-- }
      len[j + 1] = v }
    print n ? len[int ((n + 1) / 2)] : 0 }' src/*/*.c)
if [ "$med" -le 20 ]; then lay_ok layout-functions
else lay_fail layout-functions "median function length $med lines > 20"; fi

# ---- layout-modules ------------------------------------------------------
# The table rows look like "| `folder/` | `lac_a`, `lac_b` | ... |"
awk -F'|' '$2 ~ /`[a-z]+\/`/ {
    d = $2; gsub (/[ `\/]/, "", d)
    m = $3; while (match (m, /`lac_[a-z0-9_]+`/)) {
      print d "/" substr (m, RSTART + 1, RLENGTH - 2); m = substr (m, RSTART + RLENGTH) } }' \
  chapters/README.md | sort -u > "$LAYOUT_TMP/table"
for h in src/*/lac_*.h; do
  case "$h" in *_internal.h) continue ;; esac
  h=${h#src/}; echo "${h%.h}"
done | sort -u > "$LAYOUT_TMP/headers"
msg=$(comm -3 "$LAYOUT_TMP/table" "$LAYOUT_TMP/headers" | awk -F'\t' '
  $1 != "" { print "chapters/README.md lists " $1 ", which has no header in src/" }
  $1 == "" { print "src/" $2 ".h is not in the module table of chapters/README.md" }')
if [ -z "$msg" ]; then lay_ok layout-modules; else lay_fail layout-modules "$msg"; fi
