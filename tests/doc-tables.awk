# doc-tables.awk -- the tables of numbers of the book (tests/cases-doc.sh,
# case doc-tables).  A table of numbers is a Markdown pipe table, or a
# fenced block without a language (what a program prints), with at least 3
# rows that each hold at least 2 numbers (1, -2.5, 3.1e-14, 4.8 %, 1,024,
# 5·10⁻³ ...).  Each must follow (on the line before it, or the one
# before that if blank) one of the markers
#   <!-- output: COMMAND -->          checked: COMMAND prints it (numcmp)
#   <!-- output[TOL]: COMMAND -->     the same with the tolerances TOL
#   <!-- snapshot[ATTRS]: COMMAND @ COMMIT, MACHINE; sha SHA -->
#                                     a run too long for an output block:
#                                     make doc-snapshots reruns COMMAND
#                                     (tests/doc-snapshots.sh, which says
#                                     what ATTRS may be); SHA is the first
#                                     12 hex digits of the sha256 of the
#                                     block's lines (so an edit by hand
#                                     shows in make test)
#   <!-- quoted: SOURCE -->           numbers that are not lac's results
#                                     (the paper's tables, input data)
# Prints "FILE:LINE<TAB>KIND<TAB>MARKER" for each table (KIND none when no
# marker), then its lines each prefixed by "\t", then "@@end".
function isnum(t) {
  gsub(/^[ \t$*`(]+|[ \t$*`)%]+$/, "", t)
  gsub(/\\,|,|−/, "", t); sub(/^[-+−~≈]/, "", t)
  return t ~ /^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/ || t ~ /^[0-9.]+(·|\\cdot ?|×|x)10(\^\{?-?[0-9]+\}?|⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)$/
}
function rownums(l,   n, k, c, parts) {
  n = 0
  if (l ~ /^\|/) { k = split(l, parts, "|"); for (c = 2; c < k; c++) if (isnum(parts[c])) n++ }
  else { k = split(l, parts, /[ \t]+/); for (c = 1; c <= k; c++) if (isnum(parts[c])) n++ }
  return n
}
function flush(   i, kind) {
  if (nl > 0 && rows >= 3) {
    kind = "none"
    if (mark ~ /^<!-- output(\[[^]]*\])?: /) kind = "output"
    else if (mark ~ /^<!-- snapshot(\[[^]]*\])?: /) kind = "snapshot"
    else if (mark ~ /^<!-- quoted: /) kind = "quoted"
    printf "%s:%d\t%s\t%s\n", FILENAME, at, kind, mark
    for (i = 1; i <= nl; i++) printf "\t%s\n", tl[i]
    print "@@end"
  }
  nl = 0; rows = 0
}
FNR == 1 { infence = 0; nl = 0; prev1 = ""; prev2 = ""; intab = 0 }
/^```/ {
  if (infence) { infence = 0; if (plain) flush(); next }
  infence = 1; plain = ($0 ~ /^```[ \t]*$/)
  mark = prev1 ~ /^<!--/ ? prev1 : (prev1 == "" && prev2 ~ /^<!--/ ? prev2 : "")
  at = FNR; nl = 0; rows = 0; prev2 = prev1; prev1 = $0; next
}
infence { if (plain) { tl[++nl] = $0; if (rownums($0) >= 2) rows++ } next }
/^\|/ {
  if (!intab) { intab = 1; at = FNR; nl = 0; rows = 0
                mark = prev1 ~ /^<!--/ ? prev1 : (prev1 == "" && prev2 ~ /^<!--/ ? prev2 : "") }
  tl[++nl] = $0; if ($0 !~ /^\|[-: |]*$/ && rownums($0) >= 2) rows++
  next
}
intab { intab = 0; flush() }
{ prev2 = prev1; prev1 = $0 }
END { if (intab) flush() }
