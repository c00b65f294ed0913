# man.awk -- the manual page lac.1 from the text of `lac --help`
#
#   lac --help | awk -v version=0.1.0 -f tools/man.awk > lac.1
#
# The page says what --help says, in the same order, so that the two
# cannot drift apart (tests/cases-install.sh checks that every word of the
# help text is in the rendered page, in order).  The help text is made of
# blocks separated by blank lines, read as:
#
#   usage: lac CMD ...   DESCRIPTION    the first block: SYNOPSIS, and the
#          lac CMD ...   DESCRIPTION    commands at the head of DESCRIPTION;
#                                       a later one: the section of lac CMD
#   example: COMMAND                    an example (indented lines go on
#              ...                      with the command)
#   title (note):                       a heading, when the block ends with
#     TERM    DESCRIPTION               a list: terms, and their descriptions
#             DESCRIPTION               in one column
#   text ...                            a paragraph; an indented line in it
#     formula                           is shown on a line of its own
#
# Headings are sections (.SH) in the part of lac run, subsections (.SS) in
# the part of a later command.  No hyphenation and a ragged right margin:
# the words (file names, keys, option values) stay whole.  POSIX awk.

BEGIN {
  part = 0                      # 0 before the first usage block, then 1, 2 ...
  n = 0                         # lines of the current block: blk[1..n]
  print ".TH LAC 1 \"\" \"lac " version "\" \"User Commands\""
  print ".nh"
  print ".ad l"
  print ".SH NAME"
  print "lac \\- the Local Average Contact method: frictionless contact " \
        "between elastic bodies with non-matching meshes"
}

$0 == "" { flush(); next }
{ blk[++n] = $0 }

END {
  flush()
  print ".SH SEE ALSO"
  print "The chapters' example programs, installed with lac in " \
        "share/doc/lac/examples (pkg\\-config lac builds them); " \
        "the book, README.md and chapters/ of lac's sources, where the " \
        "files named above lie."
}

function indent(s) { match(s, /^ */); return RLENGTH }
function trim(s) { sub(/^ +/, "", s); sub(/ +$/, "", s); return s }

# Text for roff: backslashes printed as such, a minus sign where a dash
# starts a word (--set, -ksp_monitor, A^-1, 1e-8), no control line.
function esc(s,   out, i, c, p, q) {
  out = ""; p = " "; q = " "
  for (i = 1; i <= length(s); i++) {
    c = substr(s, i, 1)
    if (c == "\\") c = "\\e"
    else if (c == "-" && (p !~ /[A-Za-z0-9]/ || substr(s, i + 1, 1) == "-" ||
                          (p == "e" && q ~ /[0-9]/)))
      c = "\\-"
    out = out c; q = p; p = substr(s, i, 1)
  }
  if (out ~ /^[.']/) out = "\\&" out
  return out
}

# A command line of a usage block: literal words bold, SCENE and the like
# in italics.
function synopsis(s,   w, k, i, out, x) {
  k = split(s, w, " "); out = ""
  for (i = 1; i <= k; i++) {
    if (w[i] ~ /^[A-Z_]+$/) x = "\\fI" w[i] "\\fR"
    else if (w[i] ~ /^\[.*\]$/) x = "[\\fI" substr(w[i], 2, length(w[i]) - 2) "\\fR]"
    else x = "\\fB" esc(w[i]) "\\fR"
    out = out (i > 1 ? " " : "") x
  }
  return out
}

# The command and its description on a line of a usage block.
function split_usage(s) {
  sub(/^usage: /, "", s); s = trim(s)
  if (match(s, /  +/)) {
    ucmd = substr(s, 1, RSTART - 1); udesc = substr(s, RSTART + RLENGTH)
  } else { ucmd = s; udesc = "" }
}

function flush(   k) {
  if (n == 0) return
  if (blk[1] ~ /^usage: /) usage_block()
  else if (blk[1] ~ /^example: /) example_block()
  else {
    # k: the first line of the indented lines that end the block
    k = n + 1
    while (k > 1 && indent(blk[k - 1]) > 0) k--
    if (k > 1 && k <= n && blk[k - 1] ~ /:$/) { heading(1, k - 1); entries(k, n) }
    else if (k == 1) entries(1, n)
    else paragraph(1, n)
  }
  n = 0
}

function usage_block(   i, w) {
  if (part == 0) {
    print ".SH SYNOPSIS"
    for (i = 1; i <= n; i++) {
      split_usage(blk[i]); print synopsis(ucmd); print ".br"
    }
    print ".SH DESCRIPTION"
    for (i = 1; i <= n; i++) {
      split_usage(blk[i])
      print ".TP"; print synopsis(ucmd); print esc(udesc)
    }
  } else {
    split_usage(blk[1])
    split(ucmd, w, " ")
    print ".SH \"" toupper(w[1] " " w[2]) "\""
    print synopsis(ucmd); print ".br"; print esc(udesc)
    for (i = 2; i <= n; i++) print esc(trim(blk[i]))
  }
  part++
}

function example_block(   i, first) {
  first = blk[1]; sub(/^example: /, "", first)
  print ".PP"; print "Example:"
  print ".RS"; print ".nf"
  print esc(first)
  for (i = 2; i <= n; i++)
    print esc(substr(blk[i], indent(blk[i]) < 9 ? indent(blk[i]) + 1 : 10))
  print ".fi"; print ".RE"
}

# Lines a..b, a title ending with ':': the words before a parenthesis are
# the heading, the parenthesis a paragraph under it.
function heading(a, b,   s, i, t, note) {
  s = blk[a]
  for (i = a + 1; i <= b; i++) s = s " " blk[i]
  t = s; note = ""
  if (match(s, / \(/)) { t = substr(s, 1, RSTART - 1); note = substr(s, RSTART + 1) }
  else sub(/:$/, "", t)
  if (part <= 1) print ".SH \"" toupper(t) "\""
  else print ".SS \"" toupper(substr(t, 1, 1)) substr(t, 2) "\""
  if (note != "") { print ".PP"; print esc(note) }
}

# Lines a..b: TERM at column 3, its description from the column c where
# the lines that go on start (else after the first run of two spaces).
function entries(a, b,   i, c, cnt, best, s, t, d) {
  split("", cnt); best = 0; c = 0
  for (i = a; i <= b; i++)
    if (indent(blk[i]) > 2 && ++cnt[indent(blk[i])] > best) {
      best = cnt[indent(blk[i])]; c = indent(blk[i])
    }
  for (i = a; i <= b; i++) {
    s = blk[i]
    if (indent(s) > 2) { print esc(trim(s)); continue }
    if (c > 0 && length(s) > c && substr(s, c, 1) == " " && substr(s, c + 1, 1) != " ") {
      t = substr(s, 1, c); d = substr(s, c + 1)
    } else if (match(substr(s, 3), /  +/)) {
      t = substr(s, 1, RSTART + 1); d = substr(s, RSTART + 2 + RLENGTH)
    } else { t = s; d = "" }
    print ".TP"; print "\\fB" esc(trim(t)) "\\fR"
    if (trim(d) != "") print esc(trim(d))
  }
}

# Lines a..b, a paragraph: a first word such as "stderr:" in bold, an
# indented line on a line of its own.
function paragraph(a, b,   i, s) {
  print ".PP"
  for (i = a; i <= b; i++) {
    s = blk[i]
    if (indent(s) > 0) {
      print ".RS"; print ".nf"; print esc(trim(s)); print ".fi"; print ".RE"
    } else if (i == a && match(s, /^[A-Za-z]+: /)) {
      print "\\fB" esc(substr(s, 1, RLENGTH - 1)) "\\fR " esc(substr(s, RLENGTH + 1))
    } else print esc(s)
  }
}
