# tests/cases-html.sh -- the equation index of make doc (sourced by
# tests/run.sh; make doc-test checks the pages themselves in a browser).
#   doc-eqindex-parse  chapters/html/eqindex.awk reads equations, ranges
#                      (16)-(18), sections §4.4, §2-§5, §5.1-5.2 and the
#                      numbered items of sample tags as it should;
#   doc-eqindex-tags   every [LAC ...] tag of src/*.[ch] gives at least one
#                      entry of the index (a tag it cannot read fails);
#   doc-funcs          chapters/html/funcs.awk names the function of a tag:
#                      none in the file's head, the next one for a comment
#                      above it, the one whose body holds it.
# POSIX sh and awk; well under a second.

html_ok () { pass=$((pass+1)); [ -n "$LAC_TEST_VERBOSE" ] && echo "ok   case $1"; return 0; }
html_fail () { fail=$((fail+1)); echo "FAIL case $1"; printf '%s\n' "$2" | head -30 | sed 's/^/     /'; }

html_got=$(printf '%s\n' \
  'a.c:3: x [LAC (16)-(18); §5.1-5.2] y' \
  'b.h:7: [LAC §2-§5] and [LAC Alg. 1, lines 2-8]' \
  'c.c:9: [LAC Def. 1, (16)–(18)] [LAC §4.4 item 1, Fig. 2] [LAC (10), App. A]' |
  awk -f chapters/html/eqindex.awk | cut -f3-5 | tr '\t' ' ' | tr '\n' '|')
html_want='(16) a.c 3|(17) a.c 3|(18) a.c 3|§5.1 a.c 3|§5.2 a.c 3|§2 b.h 7|§3 b.h 7|§4 b.h 7|§5 b.h 7|Algorithm 1 b.h 7|Definition 1 c.c 9|(16) c.c 9|(17) c.c 9|(18) c.c 9|§4.4 c.c 9|Figure 2 c.c 9|(10) c.c 9|Appendix A c.c 9|'
if [ "$html_got" = "$html_want" ]; then html_ok doc-eqindex-parse
else html_fail doc-eqindex-parse "got  $html_got
want $html_want"; fi

html_miss=$(grep -rn --include='*.[ch]' -o '\[LAC [^]]*\]' src | while IFS= read -r l; do
  printf '%s\n' "$l" | awk -f chapters/html/eqindex.awk | grep -q . || printf '%s\n' "$l"
done)
if [ -z "$html_miss" ] && [ -n "$(grep -rln --include='*.[ch]' '\[LAC ' src)" ]; then
  html_ok doc-eqindex-tags
else html_fail doc-eqindex-tags "tags the index cannot read:
$html_miss"; fi

B=${B:-build}
mkdir -p "$B/cases-html"
printf '%s\n' '/* x.c -- [LAC (1)] */' '#include <x.h>' '/* f does (2) [LAC (2)] */' \
  'static int' 'f (int a)' '{' '  return a; /* [LAC (3)] */' '}' '' 'int' 'g (void)' '{' \
  '  return 0;' '}' '/* [LAC (4)] */' > "$B/cases-html/x.c"
html_got=$(awk -f chapters/html/funcs.awk "$B/cases-html/x.c" | cut -f2- | tr '\t\n' ':|')
if [ "$html_got" = "1:|3:f|7:f|15:|" ]; then html_ok doc-funcs
else html_fail doc-funcs "got $html_got, want 1:|3:f|7:f|15:|"; fi
