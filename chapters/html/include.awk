# include.awk -- a page's include markers as code (make-html.sh):
#   <!-- include: FILE FUNCTION -->
# becomes the definition of FUNCTION in FILE (GNU style: its name at column
# 0 followed by " (", its body up to the "}" at column 0), with the comment
# block and the return type above it, as a highlighted C block, and under
# it a link to the lines in the source page.  The code is read from the
# source when the page is made, so it cannot drift from it.  A marker
# whose function is not found stops make doc (exit status 1).
function extract(file, fn,   n, i, l, start, stop, k) {
  n = 0
  while ((getline l < file) > 0) src[++n] = l
  close(file)
  start = 0
  for (i = 1; i <= n; i++)
    if (index(src[i], fn " (") == 1 || src[i] == fn " (void)") { start = i; break }
  if (!start) return 0
  # the return type (lines above, up to a blank line or a comment's end)
  k = start
  while (k > 1 && src[k - 1] !~ /^[ \t]*$/ && src[k - 1] !~ /\*\/[ \t]*$/ && src[k - 1] !~ /^}/) k--
  # the comment block right above
  if (k > 1 && src[k - 1] ~ /\*\/[ \t]*$/) {
    k--; while (k > 1 && src[k] !~ /^\/\*/) k--
  }
  stop = start; while (stop <= n && src[stop] !~ /^}/) stop++
  print "```c"
  for (i = k; i <= stop; i++) print src[i]
  print "```"
  printf "\n::: {.source}\n`%s` in [%s, lines %d–%d](%s%s#L%d)\n:::\n", fn, file, start, stop, root, file, start
  return 1
}
/^<!-- include: [^ ]+ [A-Za-z_0-9]+ -->$/ {
  f = $3; fn = $4
  if (!extract(f, fn)) { printf "include.awk: %s: %s not found in %s\n", FILENAME, fn, f > "/dev/stderr"; bad = 1 }
  next
}
{ print }
END { exit bad }
