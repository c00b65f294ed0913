#!/bin/sh
# doc-browser.sh DOC [PNGCHECK] -- the pages of make doc in headless Chromium (make
# doc-test): every page of the book (the README, chapters/, the equation
# index; DOC/*.html and below, not the source pages) loads, its maths renders
# as MathML (no "$" or TeX command left in the text), every image loads,
# every link and anchor resolves; a screenshot of chapter 06 goes to
# DOC/screenshot.png, not blank (PNGCHECK, figures/pngcheck.c: at least 5 %
# of its pixels inked, 50 colours).  Prints one line per problem; exit
# status 1 if any.
set -eu
DOC=${1:?usage: doc-browser.sh DOC}
DOCABS=$(cd "$DOC" && pwd)
check="$DOC/check.html"
[ -s "$DOC/pages.txt" ] || { echo "doc-browser: no $DOC/pages.txt: run make doc"; exit 1; }
pages=$(cat "$DOC/pages.txt")
{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"><title>check</title></head><body>'
  echo '<pre id="result">NOT RUN</pre>'
  for p in $pages; do echo "<iframe src=\"$p\" width=\"1000\" height=\"600\"></iframe>"; done
  echo '<script>'; cat tests/doc-check.js; echo '</script></body></html>'
} > "$check"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
chrome() {
  timeout 300 chromium --headless --no-sandbox --disable-gpu --no-first-run \
    --user-data-dir="$profile" --allow-file-access-from-files "$@" 2>"$profile/log"
}
chrome --virtual-time-budget=30000 --dump-dom "file://$DOCABS/check.html" > "$DOC/check.out" ||
  { echo "doc-browser: chromium failed:"; tail -5 "$profile/log"; exit 1; }
sed -n '/<pre id="result">/,/<\/pre>/{p;/<\/pre>/q;}' "$DOC/check.out" |
  sed 's/<pre id="result">//; s|</pre>.*||; s/&lt;/</g; s/&gt;/>/g; s/&amp;/\&/g' > "$DOC/check.txt"
cat "$DOC/check.txt" | grep -v '^DONE$' | grep -v '^$' || true
grep -qx DONE "$DOC/check.txt" || { echo "doc-browser: the checks did not finish"; exit 1; }
chrome --screenshot="$DOCABS/screenshot.png" --window-size=1000,1400 --hide-scrollbars \
  "file://$DOCABS/chapters/06-assembly/README.html" >/dev/null ||
  { echo "doc-browser: no screenshot:"; tail -5 "$profile/log"; exit 1; }
[ -s "$DOC/screenshot.png" ] || { echo "doc-browser: empty screenshot"; exit 1; }
if [ -n "${2:-}" ]; then
  set -- $("$2" "$DOC/screenshot.png")          # file width height ink colours
  awk -v i="$4" -v c="$5" 'BEGIN { exit !(i >= 0.05 && c >= 50) }' ||
    { echo "doc-browser: blank screenshot: ink $4, $5 colours"; exit 1; }
fi
echo "doc-browser: screenshot of chapter 06 in $DOC/screenshot.png"
[ "$(grep -vc -e '^DONE$' -e '^checked ' -e '^$' "$DOC/check.txt")" -eq 0 ]
