# eqindex.awk -- the [LAC ...] tags of src/ (lines of grep -n) as records
#   group <TAB> sort key <TAB> name <TAB> file <TAB> line <TAB> text
# for make-html.sh, which sorts them and writes equations.md.
# Equations "(17)", ranges "(16)-(18)", sections "§4.4", "§2-§5", "§5.1-5.2",
# and Alg., Def., Remark, Hyp., Fig., Thm., App., ref.
function emit(group, key, name) {
  printf "%s\t%s\t%s\t%s\t%s\t%s\n", group, key, name, file, lnum, text
}
function digits(s, a,   n) {          # the numbers of s into a[1..n]
  gsub(/[^0-9.]+/, " ", s)
  n = split(s, a, " ")
  return n
}
function section(s,   a, n, k, top) {
  n = digits(s, a)
  if (n == 2 && index(a[1], ".") == 0 && index(a[2], ".") == 0) {
    for (k = a[1] + 0; k <= a[2] + 0; k++) emit(2, sprintf("%06.2f", k), "§" k)
    return
  }
  if (n == 2 && index(a[2], ".") > 0) {           # §5.1-5.2
    split(a[1], top, ".")
    for (k = top[2] + 0; k <= substr(a[2], index(a[2], ".") + 1) + 0; k++)
      emit(2, sprintf("%06.2f", top[1] "." k), "§" top[1] "." k)
    return
  }
  emit(2, sprintf("%06.2f", a[1]), "§" a[1])
}
function named(piece, re, label, group,   m) {
  if (match(piece, re)) {
    m = substr(piece, RSTART, RLENGTH)
    sub(/^[^ ]* */, "", m)
    emit(group, sprintf("%-12s%06s", label, m), label " " m)
  }
}
{
  # file:line:text (grep -n); the text may hold colons
  file = $0; sub(/:.*/, "", file)
  rest = substr($0, length(file) + 2)
  lnum = rest; sub(/:.*/, "", lnum)
  text = substr(rest, length(lnum) + 2)
  gsub(/\t/, " ", text)
  gsub(/–/, "-", text)
  line = text
  while (match(line, /\[LAC [^]]*\]/)) {
    tag = substr(line, RSTART + 5, RLENGTH - 6)
    line = substr(line, RSTART + RLENGTH)
    np = split(tag, piece, /[,;]/)
    for (i = 1; i <= np; i++) {
      p = piece[i]
      if (match(p, /\([0-9]+\) *- *\([0-9]+\)/)) {
        digits(substr(p, RSTART, RLENGTH), a)
        for (k = a[1] + 0; k <= a[2] + 0; k++) emit(1, sprintf("%04d", k), "(" k ")")
      } else if (match(p, /\([0-9]+\)/)) {
        k = substr(p, RSTART + 1, RLENGTH - 2) + 0
        emit(1, sprintf("%04d", k), "(" k ")")
      }
      if (match(p, /§[0-9.]+( *- *(§)?[0-9.]+)?/))
        section(substr(p, RSTART, RLENGTH))
      named(p, "Alg\\. *[0-9]+", "Algorithm", 3)
      named(p, "Def(\\.|inition) *[0-9]+", "Definition", 4)
      named(p, "Hyp\\. *[0-9]+", "Hypothesis", 4)
      named(p, "Rem(\\.|ark) *[0-9]+", "Remark", 4)
      named(p, "Thm\\. *[0-9]+", "Theorem", 4)
      named(p, "Fig\\. *[0-9]+", "Figure", 4)
      named(p, "App\\. *[A-Z]", "Appendix", 4)
      named(p, "ref\\. *[0-9]+", "Reference", 4)
    }
  }
}
