# literate.awk -- a chapter's example.c as a commented program, in Markdown
# (make-html.sh; -v name=PATH -v title=TITLE).  The comments that stand on
# lines of their own become the prose (with their $maths$), the code
# between them highlighted blocks, "// @sect Title" a heading; comments at
# the end of a code line stay in the code.  The file's head comment (up to
# its first #include) is shown as it is, in a block of its own.  Names
# lac_xxx in the prose become code spans (make-html links them to their
# definition).
function flushcode(   i, n) {
  # trim blank lines at both ends
  while (nc > 0 && code[nc] ~ /^[ \t]*$/) nc--
  i = 1; while (i <= nc && code[i] ~ /^[ \t]*$/) i++
  if (i <= nc) {
    printf "\n```c\n"
    for (n = i; n <= nc; n++) print code[n]
    printf "```\n"
  }
  nc = 0
}
function prose(s) {
  # names of the library as code spans, outside $...$ and `...`
  out = ""; inm = 0; inc = 0
  while (s != "") {
    c = substr(s, 1, 1)
    if (c == "$" && !inc) { inm = !inm; out = out c; s = substr(s, 2); continue }
    if (c == "`" && !inm) { inc = !inc; out = out c; s = substr(s, 2); continue }
    if (!inm && !inc && match(s, /^lac_[A-Za-z0-9_]+( \(\))?/) &&
        (out == "" || substr(out, length(out), 1) !~ /[A-Za-z0-9_]/)) {
      out = out "`" substr(s, 1, RLENGTH) "`"; s = substr(s, RLENGTH + 1); continue
    }
    out = out c; s = substr(s, 2)
  }
  return out
}
function flushtext() {
  if (nt > 0) {
    printf "\n"
    for (i = 1; i <= nt; i++) print prose(text[i])
  }
  nt = 0
}
BEGIN { nc = 0; nt = 0; head = 1; incomment = 0
        printf "# %s\n\n", title
        printf "The commented program of this chapter, `%s`: its comments are the text, its code the blocks between them. The plain listing with line numbers: <a href=\"%s\">%s</a>.\n", name, plain, name }
head {
  if ($0 ~ /^#include/) { head = 0; if (nh > 0) { printf "\n```\n"; for (i = 1; i <= nh; i++) print hl[i]; printf "```\n" } }
  else { hl[++nh] = $0; next }
}
# inside a comment block of its own
incomment {
  line = $0
  if (line ~ /\*\//) { incomment = 0; sub(/[ \t]*\*\/.*$/, "", line) }
  sub(/^[ \t]*\* ?/, "", line); sub(/^[ \t]+/, "", line)
  if (line == "" ) { text[++nt] = "" } else text[++nt] = line
  next
}
/^[ \t]*\/\/ @sect / {
  flushcode(); flushtext()
  t = $0; sub(/^[ \t]*\/\/ @sect /, "", t)
  printf "\n## %s\n", t
  next
}
/^[ \t]*\/\*/ && !/\*\/.*[^ \t]/ {
  # a comment that opens a line (and no code after its end)
  flushcode()
  line = $0; sub(/^[ \t]*\/\*+ ?/, "", line)
  if (line ~ /\*\//) { sub(/[ \t]*\*\/.*$/, "", line) } else incomment = 1
  if (nt > 0) text[++nt] = ""
  if (line != "") text[++nt] = line
  if (!incomment) { }
  next
}
/^[ \t]*\/\// {
  flushcode()
  line = $0; sub(/^[ \t]*\/\/ ?/, "", line)
  text[++nt] = line
  next
}
{ if (nt > 0) flushtext(); code[++nc] = $0 }
END { flushcode(); flushtext() }
