#!/bin/sh
# make-html.sh OUT -- the book as HTML (make doc): every Markdown page of
# the repository (the README, the chapters, the folders' READMEs) through
# pandoc with maths as MathML, the figures copied beside them, a page per
# source file that a page links to (lines anchored #L<n>), and
# equations.html, from the paper's equations to the code, made from the
# [LAC ...] tags of src/.  Run from the top of the repository.  Any pandoc
# warning stops it (--fail-if-warnings).
set -eu
OUT=${1:?usage: make-html.sh OUT}
H=chapters/html
TAB=$(printf '\t')
mkdir -p "$OUT"
tmp="$OUT/.work"
rm -rf "$tmp"; mkdir -p "$tmp"
: > "$OUT/pages.txt"                  # the pages made from Markdown

# the repository's files (not the build folders)
find . \( -name .git -o -name build -o -path "./$OUT" \) -prune -o -type f -print |
  sed 's|^\./||' | sort > "$tmp/files"
: > "$tmp/need"

# the pages: the book in reading order, then the other Markdown files
{
  echo README.md
  echo chapters/README.md
  for d in chapters/[0-9][0-9]-*/; do
    [ -f "${d}README.md" ] || continue      # a folder of the reader's: not the book
    echo "${d}README.md"
    ls "$d"*.md | grep -v '/README\.md$' || true
  done
} > "$tmp/book"
grep '\.md$' "$tmp/files" | grep -vxF -f "$tmp/book" > "$tmp/other" || true

title() { sed -n 's/^# *//p' "$1" | head -n 1; }
# the functions of src/, for links from their names to their definitions
awk -f "$H/funcdefs.awk" $(find src -name '*.c' | sort) > "$tmp/funcs-def"
# from a folder of the repository (or a file's) to its top: "", "../", ...
rootdir() { [ "$1" = . ] && return 0; echo "$1" | sed 's|[^/][^/]*|..|g; s|$|/|'; }
root() { rootdir "$(dirname "$1")"; }

# page SRC OUT_HTML DOCDIR PREV NEXT (PREV, NEXT: sources or empty)
page() {
  src=$1; dst=$2; dir=$3; pv=$4; nx=$5; r=$(rootdir "$dir")
  set -- -f markdown -t html5 --mathml --fail-if-warnings \
    --template="$H/template.html" --lua-filter="$H/links.lua" \
    -M docdir="$dir" -M filelist="$tmp/files" -M needlist="$tmp/need" \
    -M funclist="$tmp/funcs-def" \
    -M pagetitle="$(title "$src")" -V root="$r"
  [ -n "$pv" ] && set -- "$@" -V prev="$r${pv%.md}.html" -V prevtitle="$(title "$pv")"
  [ -n "$nx" ] && set -- "$@" -V next="$r${nx%.md}.html" -V nexttitle="$(title "$nx")"
  mkdir -p "$(dirname "$dst")"
  echo "${dst#"$OUT/"}" >> "$OUT/pages.txt"
  # <!-- include: FILE FUNCTION --> markers: the code, read from the source
  in=$src
  if grep -q '^<!-- include: ' "$src"; then
    in="$tmp/include.md"
    awk -v root="$r" -f "$H/include.awk" "$src" > "$in" ||
      { echo "make-html: $src: an include marker names nothing" >&2; echo "$src" >> "$tmp/failed"; }
  fi
  pandoc "$@" -o "$dst" "$in" || { echo "make-html: $src: see above" >&2
                                   echo "$src" >> "$tmp/failed"; }
}

prev=""
set -- $(cat "$tmp/book")
while [ $# -gt 0 ]; do
  page "$1" "$OUT/${1%.md}.html" "$(dirname "$1")" "$prev" "${2:-}"
  prev=$1; shift
done
for f in $(cat "$tmp/other"); do
  page "$f" "$OUT/${f%.md}.html" "$(dirname "$f")" "" ""
done

# each chapter's example.c as a commented program (literate.awk): the
# comments as text with their maths, the code as blocks; the plain listing
# with line numbers beside it (example.c.src.html)
for ex in chapters/[0-9][0-9]-*/example.c; do
  [ -f "$(dirname "$ex")/README.md" ] || continue
  d=$(dirname "$ex")
  awk -v name="$ex" -v plain="example.c.src.html" \
      -v title="$(title "$d/README.md" | sed 's/^\([0-9][0-9]\) .*/\1/') The commented program" \
      -f "$H/literate.awk" "$ex" > "$tmp/literate.md"
  page "$tmp/literate.md" "$OUT/$ex.html" "$d" "$d/README.md" ""
  echo "=src:$ex" >> "$tmp/need"
done

# equations.md: the tags, sorted, one section per equation / section / item
grep -rn --include='*.[ch]' '\[LAC [^]]*\]' src | awk -f "$H/eqindex.awk" |
  sort -t "$TAB" -k1,1n -k2,2 -k4,4 -k5,5n -u > "$tmp/tags"
{
  echo "# From the paper to the code"
  echo
  echo "Every place in \`src/\` whose comment cites the paper as \`[LAC ...]\`,"
  echo "by equation, section and numbered item (made by \`make doc\` from the"
  echo "tags themselves).  Each line: the file and line, the function that"
  echo "holds the tag or that its comment introduces, the line itself."
  awk -f "$H/funcs.awk" $(find src -name '*.[ch]' | sort) > "$tmp/funcs"
  awk -F "$TAB" '
    FNR == NR { fn[$1 ":" $2] = $3; next }
    BEGIN { g[1] = "Equations"; g[2] = "Sections"; g[3] = "Algorithm";
            g[4] = "Definitions, hypotheses, remarks, figures" }
    $1 != group { group = $1; printf "\n## %s\n", g[group] }
    $3 != name  { name = $3; id = name; gsub(/[^A-Za-z0-9]+/, "-", id)
                  sub(/^-/, "", id); sub(/-$/, "", id)
                  printf "\n### %s {#%s-%s}\n\n", name, (group == 2 ? "sec" : "item"), id }
    { t = $6; gsub(/`/, "", t); sub(/^[ \/*]+/, "", t); sub(/[ \/*]+$/, "", t)
      f = fn[$4 ":" $5]
      printf "- [`%s:%s`](%s#L%s)%s%s\n", $4, $5, $4, $5,
             (f == "" ? "" : " (<code>" f "</code>)"), (t == "" ? "" : ": `" t "`") }
  ' "$tmp/funcs" "$tmp/tags"
} > "$tmp/equations.md"
page "$tmp/equations.md" "$OUT/equations.html" . "" ""

# figures and the source pages the pages link to
sort -u "$tmp/need" | while IFS= read -r f; do
  case $f in
    =src:*) f=${f#=src:}; mkdir -p "$OUT/$(dirname "$f")"
            awk -v name="$f" -v root="$(root "$f")" -f "$H/source.awk" "$f" > "$OUT/$f.src.html" ;;
    chapters/[0-9][0-9]-*/example.c) ;;       # the commented program, above
    =*) f=${f#=}; mkdir -p "$OUT/$(dirname "$f")"; cp "$f" "$OUT/$f" ;;
    *)  mkdir -p "$OUT/$(dirname "$f")"
        awk -v name="$f" -v root="$(root "$f")" -f "$H/source.awk" "$f" > "$OUT/$f.html" ;;
  esac
done
if [ -s "$tmp/failed" ]; then
  echo "make-html: pandoc warned on $(wc -l < "$tmp/failed") page(s)" >&2; exit 1
fi
rm -rf "$tmp"
echo "make-html: $(find "$OUT" -name '*.html' | wc -l) pages in $OUT"
